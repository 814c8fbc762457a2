#pragma once
/// @file random.hpp
/// Reproducible random numbers: the same seed gives the same sequence on every platform
/// and standard library (std:: distributions are implementation-defined, so they are
/// not used for anything that reaches an output file).

#include <cstdint>
#include <random>

namespace sgmp {

class Random {
  public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}

    /// Uniform in [0, 1), from the top 53 bits of one draw.
    double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
    /// Uniform integer in [0, n), n > 0, by rejection (no modulo bias).
    std::uint64_t below(std::uint64_t n);
    std::uint64_t raw() { return engine_(); }

  private:
    std::mt19937_64 engine_;
};

}  // namespace sgmp
