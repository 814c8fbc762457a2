#pragma once
/// @file version.hpp
/// The project's version, recorded in every output file.

namespace sgmp {

/// Version string of the testbed (from the top-level CMake project).
const char* version();

}  // namespace sgmp
