// Each domain's bindings add themselves to the fabguide_core module.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>

namespace fabguide::bindings {

/// Lets another thread stop a running pack() or optimise() (bound by bindMaterial as CancelToken).
struct CancelToken {
    std::atomic<bool> flag{false};
};

void bindMaterial(pybind11::module_& m);
void bindFunction(pybind11::module_& m);
void bindPrintable(pybind11::module_& m);
void bindExplore(pybind11::module_& m);

}  // namespace fabguide::bindings
