// The memory a run may use: the big structures' sizes are estimated against it before they are
// made and refused with the field that makes them big named; the command line also sets it as the process'
// data limit, so an allocation past it fails as std::bad_alloc, reported in a sentence.
#pragma once

#include <stdexcept>
#include <string>

namespace fabguide {

/// A structure refused for the memory it would need.
struct MemoryError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Bytes a run may use: the memory free when it began unless set (`--memory`).
double memoryLimit();

/// Sets memoryLimit(); the command line's `--memory`.
void setMemoryLimit(double bytes);

/// Throws MemoryError "`what` need(s) ~X GB, more than the Y GB of memory the run may use (…)`remedy`"
/// when `bytes` is over memoryLimit().
void needMemory(double bytes, const std::string& what, const std::string& remedy = "");

/// A size in words: "820 MB", "1.9 GB", "48 GB".
std::string inBytes(double bytes);

}  // namespace fabguide
