#pragma once
/// @file pack_content_error.hpp
/// A pack whose contents break a metric's rule (a sphere swallowed by a larger one, no
/// particles, a diameter that is not finite): bad input, which the tools report with
/// status 1, as opposed to an option out of its range (ParameterError, status 2).
#include <stdexcept>

namespace sgmp::metrics {

class PackContentError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace sgmp::metrics
