#pragma once
/// @file option_rules.hpp
/// Checks of numeric command-line values shared by the three tools, applied to the text
/// as typed (before any conversion can wrap or round it). Each returns an empty string
/// when the value is acceptable, else the rule it breaks.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace sgmp {

/// A seed: a whole number in [0, 2^64 - 1] written in decimal digits ("-1" and
/// "18446744073709551616" are refused rather than wrapped or clamped).
inline std::string seed_rule(std::string_view text) {
    std::uint64_t value = 0;
    const auto* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end) {
        return "must be a whole number from 0 to 18446744073709551615";
    }
    return {};
}

/// A particle count: a whole number in [1, max] written in decimal digits ("-5" is
/// refused rather than wrapped).
inline std::string count_rule(std::string_view text, std::uint64_t max) {
    std::uint64_t value = 0;
    const auto* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end || value < 1 || value > max) {
        return "must be a whole number from 1 to " + std::to_string(max);
    }
    return {};
}

/// A finite number in [lo, hi].
inline std::string finite_range_rule(std::string_view text, double lo, double hi,
                                     const std::string& range) {
    double value = 0.0;
    const auto* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end || !std::isfinite(value) ||
        value < lo || value > hi) {
        return "must be a number in " + range;
    }
    return {};
}

}  // namespace sgmp
