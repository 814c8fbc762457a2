#include "sgmp/report/manifest.hpp"

#include <set>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/line_reader.hpp"

namespace sgmp::report {
namespace {

constexpr const char* kHeader = "role,group,count,seed,seconds,path";

}  // namespace

const char* to_string(Role role) {
    switch (role) {
        case Role::Candidate:
            return "candidate";
        case Role::Reference:
            return "reference";
        case Role::Variant:
            return "variant";
        case Role::Stiff:
            return "stiff";
    }
    return "candidate";
}

std::vector<ManifestEntry> read_manifest(std::istream& in, const std::string& source) {
    LineReader reader(in, source);
    std::string line;
    if (!reader.next(line)) {
        throw InputError(source, 0,
                         "empty manifest: expected the header '" + std::string(kHeader) + "'");
    }
    if (line != kHeader) {
        throw InputError(
            source, 1, "expected the header '" + std::string(kHeader) + "', found '" + line + "'");
    }
    std::vector<ManifestEntry> entries;
    std::set<std::string> paths;
    while (reader.next(line)) {
        const std::size_t number = reader.line_number();
        if (line.find_first_not_of(" \t") == std::string::npos) {
            continue;
        }
        const auto quoted = split_quoted_csv_line(line);
        if (!quoted) {
            throw InputError(source, number,
                             "a quoted field lacks its closing quote or has text after it");
        }
        const auto& fields = *quoted;
        if (fields.size() != 6) {
            throw InputError(
                source, number,
                "expected 6 comma-separated fields, found " + std::to_string(fields.size()));
        }
        ManifestEntry entry;
        if (fields[0] == "candidate") {
            entry.role = Role::Candidate;
        } else if (fields[0] == "reference") {
            entry.role = Role::Reference;
        } else if (fields[0] == "variant") {
            entry.role = Role::Variant;
        } else if (fields[0] == "stiff") {
            entry.role = Role::Stiff;
        } else {
            throw InputError(
                source, number,
                "role '" + fields[0] + "' must be 'candidate', 'reference', 'variant' or 'stiff'");
        }
        entry.group = fields[1];
        if (entry.group.empty()) {
            throw InputError(source, number, "the group is empty");
        }
        const auto count = parse_csv_number<std::size_t>(fields[2]);
        if (!count || *count == 0) {
            throw InputError(source, number,
                             "count '" + fields[2] + "' must be a positive integer");
        }
        entry.count = *count;
        const auto seed = parse_csv_number<std::uint64_t>(fields[3]);
        if (!seed) {
            throw InputError(source, number,
                             "seed '" + fields[3] + "' must be a non-negative integer");
        }
        entry.seed = *seed;
        if (!fields[4].empty()) {
            const auto seconds = parse_csv_number<double>(fields[4]);
            if (!seconds || *seconds < 0.0) {
                throw InputError(source, number,
                                 "seconds '" + fields[4] + "' must be a number >= 0 or empty");
            }
            entry.seconds = *seconds;
        }
        entry.path = fields[5];
        if (entry.path.empty()) {
            throw InputError(source, number, "the path is empty");
        }
        if (!paths.insert(entry.path).second) {
            throw InputError(source, number, "path '" + entry.path + "' is listed twice");
        }
        entries.push_back(std::move(entry));
    }
    if (entries.empty()) {
        throw InputError(source, reader.line_number(), "the manifest lists no packs");
    }
    return entries;
}

}  // namespace sgmp::report
