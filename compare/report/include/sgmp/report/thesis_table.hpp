#pragma once
/// @file thesis_table.hpp
/// The thesis' published results (data/thesis/results.csv: Tables 5.1, 6.1, 7.1, 8.1):
/// runtime and control-volume packing fraction per starting arrangement and count.

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace sgmp::report {

struct ThesisResult {
    std::string arrangement;
    std::size_t count = 0;
    double runtime_seconds = 0.0;
    double packing_fraction = 0.0;
    std::string table;  // e.g. "5.1"
};

/// Reads `arrangement,count,runtime_s,packing_fraction,table`; throws sgmp::InputError
/// with source:line on malformed lines.
std::vector<ThesisResult> read_thesis_results(std::istream& in, const std::string& source);

/// The thesis' starting packs (data/thesis/starting_packs.csv: Tables 6.2, 7.2, 8.2).
struct ThesisStart {
    std::string arrangement;
    std::size_t count = 0;
    std::string grid;  // e.g. "8x8"; empty for loose random
    double starting_height = 0.0;
    std::string table;
};

/// Reads `arrangement,count,grid,starting_height,table`; throws sgmp::InputError with
/// source:line on malformed lines.
std::vector<ThesisStart> read_thesis_starts(std::istream& in, const std::string& source);

/// The row for (arrangement, count), if the thesis has one.
std::optional<ThesisResult> find_thesis_result(const std::vector<ThesisResult>& results,
                                               const std::string& arrangement, std::size_t count);
std::optional<ThesisStart> find_thesis_start(const std::vector<ThesisStart>& starts,
                                             const std::string& arrangement, std::size_t count);

}  // namespace sgmp::report
