#pragma once
/// @file size_distribution_file.hpp
/// `--size-distribution FILE` of the front ends that take one (`sgmp pack`, `sgmp-reference
/// pour`): the file read and parsed (parse_size_distribution_csv), a bad file a usage error
/// naming file:line, and the one-line warning when its fractions do not sum to 1 (they are
/// normalised). A lognormal:… text is no file: the callers give it to their parameter row.
#include <string>
#include <vector>

#include "sgmp/pack/size_modes.hpp"

namespace sgmp::cli {

/// The modes of the CSV file at `path`. Throws UsageError ("--size-distribution PATH: …",
/// exit 2) for a path that names no readable file, std::runtime_error
/// ("--size-distribution PATH:LINE: …", exit 1: a bad input file) for one that does not
/// parse.
/// `largest_diameter` (when given) receives the largest diameter with the unit the file's
/// diameter column names ("200 um"), and is left alone when it names none.
std::vector<SizeMode> read_size_distribution_file(const std::string& path,
                                                  std::string* largest_diameter = nullptr);

/// Prints "PROGRAM: warning: OPTION: fractions sum to S; normalised to 1" to stderr when
/// the fractions of `modes` do not sum to 1 (unnormalised_total, size_modes.hpp); OPTION
/// is the option as typed, e.g. "--size-distribution blend.csv".
void warn_unnormalised(const std::string& program, const std::string& option,
                       const std::vector<SizeMode>& modes);

}  // namespace sgmp::cli
