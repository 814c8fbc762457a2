#pragma once
// What the readers of measured packs (precomputed.cpp: metrics.json) and of batch summaries
// (batch_summaries.cpp: summary.csv) share.
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace sgmp::report::detail {

/// A metric not measured.
inline constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

/// The lines of `text` (without their line feeds).
std::vector<std::string_view> lines_of(std::string_view text);

/// A recorded particle count: a whole number in [1, 2⁵³] (beyond, a double no longer holds
/// every whole number, and the cast to size_t would be undefined).
std::size_t count_of(double value, const std::string& source, std::size_t line);

}  // namespace sgmp::report::detail
