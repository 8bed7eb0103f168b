// Each domain's bindings add themselves to the fabguide_core module.
#pragma once

#include <pybind11/pybind11.h>

namespace fabguide::bindings {

void bindMaterial(pybind11::module_& m);
void bindFunction(pybind11::module_& m);
void bindPrintable(pybind11::module_& m);
void bindExplore(pybind11::module_& m);

}  // namespace fabguide::bindings
