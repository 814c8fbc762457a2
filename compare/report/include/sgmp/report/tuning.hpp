#pragma once
/// @file tuning.hpp
/// Parameters of a candidate mode tuned against reference packs, disclosed on every page
/// and kept out of the verdicts they would bias.
///
/// A tuning file is a CSV with the header `group,parameter,value,reference,count,seeds,note`,
/// one tuned parameter per line: candidate group `group` had `parameter` set to `value` by
/// comparing it with reference group `reference` at `count` particles, on the reference's
/// seeds `seeds` (space-separated integers, or ranges "a-b"). A comparison of that group
/// with that reference at that count whose reference packs include any of those seeds is
/// not judged: its rows become `info` ("tuned on these seeds"), so no verdict rests on the
/// data that chose the parameter. Its other counts, judged against seeds the tuning did
/// not see, are the check.

#include <cstdint>
#include <istream>
#include <set>
#include <string>
#include <vector>

#include "sgmp/report/agreement.hpp"
#include "sgmp/report/manifest.hpp"

namespace sgmp::report {

struct TunedParameter {
    std::string group;
    std::string parameter;
    std::string value;
    std::string reference;
    std::size_t count = 0;
    std::set<std::uint64_t> seeds;
    std::string note;
};

/// Reads a tuning file strictly; throws sgmp::InputError ("source:line: reason") on a wrong
/// header, a wrong number of fields, an empty group, parameter or reference, a count that
/// is not a positive integer, or seeds that are not integers or ranges a-b with a ≤ b.
std::vector<TunedParameter> read_tuning(std::istream& in, const std::string& source);

/// Makes every judged row of the comparisons the tuning used `info` (the header); returns
/// how many comparisons it withheld.
std::size_t withhold_tuned(Report& report, const std::vector<TunedParameter>& tuning,
                           const std::vector<ManifestEntry>& manifest);

}  // namespace sgmp::report
