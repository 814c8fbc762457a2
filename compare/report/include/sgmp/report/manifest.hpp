#pragma once
/// @file manifest.hpp
/// The list of packs a cross-validation reads: a CSV file with the header
/// `role,group,count,seed,seconds,path`, one pack per line. `role` is `candidate` (packs
/// under test, e.g. one SGMP arrangement per group) or `reference` (the classes they are
/// judged against, e.g. one DEM friction class per group) or `variant` / `stiff` (another
/// protocol or stiffness of the reference group named by `group`: a reference class of its
/// own, "<group> (variant)", crossval.hpp);
/// `seconds` is the wall time that made the pack (empty when unknown). An optional seventh
/// column `container` (header `role,group,count,seed,seconds,path,container`) states the
/// pack's walls, "x_min x_max z_min z_max floor" as the header key (empty: not stated;
/// sgmp/pack/stated_container.hpp).

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp::report {

enum class Role { Candidate, Reference, Variant, Stiff };
/// "candidate", "reference", "variant", "stiff": the manifest's words.
const char* to_string(Role role);

struct ManifestEntry {
    Role role = Role::Candidate;
    std::string group;
    std::size_t count = 0;
    std::uint64_t seed = 0;
    std::optional<double> seconds;
    std::string path;
    /// The walls the row states (the `container` column), parsed by Container::parse.
    std::optional<Container> container{};
    /// The row's line in the manifest (from 1), for messages.
    std::size_t line = 0;
};

/// The rule a group name (a manifest's `group`, `report --label-a/--label-b`) keeps, or
/// nullopt when it keeps it. Group names reach report.md (Markdown tables), index.html,
/// report.csv and headline.csv, and crossval.json as they are, so they are refused, not
/// escaped, when they could act there: well-formed UTF-8 (JSON), no control character,
/// none of `< > | [ ]` (HTML tags, table cells, links in Markdown), and no first character
/// a spreadsheet takes for a formula (`= + - @`, a blank).
std::optional<std::string> group_name_rule_broken(std::string_view name);

/// Reads a manifest strictly; throws sgmp::InputError ("source:line: reason") on a wrong
/// header, a wrong number of fields, an unknown role, a non-numeric count, seed or seconds,
/// an empty group or path, a group name that breaks group_name_rule_broken, a field that is
/// not UTF-8, a path listed twice, or a container that is not five finite
/// numbers with x_min < x_max and z_min < z_max. Fields holding a comma or a quote are
/// double-quoted, with quotes doubled (RFC 4180).
std::vector<ManifestEntry> read_manifest(std::istream& in, const std::string& source);

}  // namespace sgmp::report
