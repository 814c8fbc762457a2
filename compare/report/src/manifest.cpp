#include "sgmp/report/manifest.hpp"

#include <set>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/line_reader.hpp"
#include "sgmp/pack/parameter_error.hpp"

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

std::optional<std::string> group_name_rule_broken(std::string_view name) {
    const std::string rule =
        "a group name must be UTF-8 text without control characters or '<', '>', '|', '[', "
        "']', and may not start with '=', '+', '-', '@' or a blank (it reaches Markdown, "
        "HTML and CSV cells as it is)";
    if (!is_utf8(name)) {
        return rule;
    }
    if (!name.empty() && std::string_view("=+-@ ").find(name.front()) != std::string_view::npos) {
        return rule;
    }
    for (const char c : name) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f ||
            std::string_view("<>|[]").find(c) != std::string_view::npos) {
            return rule;
        }
    }
    return std::nullopt;
}

namespace {

Role parse_role(const std::string& field, const std::string& source, std::size_t number) {
    if (field == "candidate") {
        return Role::Candidate;
    }
    if (field == "reference") {
        return Role::Reference;
    }
    if (field == "variant") {
        return Role::Variant;
    }
    if (field == "stiff") {
        return Role::Stiff;
    }
    throw InputError(source, number,
                     "role '" + field + "' must be 'candidate', 'reference', 'variant' or 'stiff'");
}

/// One row's fields (6, or 7 with the container column) as an entry.
ManifestEntry parse_entry(const std::vector<std::string>& fields, const std::string& source,
                          std::size_t number) {
    ManifestEntry entry;
    entry.role = parse_role(fields[0], source, number);
    entry.group = fields[1];
    if (entry.group.empty()) {
        throw InputError(source, number, "the group is empty");
    }
    if (const auto rule = group_name_rule_broken(entry.group)) {
        throw InputError(source, number, "group '" + entry.group + "': " + *rule);
    }
    const auto count = parse_csv_number<std::size_t>(fields[2]);
    if (!count || *count == 0) {
        throw InputError(source, number, "count '" + fields[2] + "' must be a positive integer");
    }
    entry.count = *count;
    const auto seed = parse_csv_number<std::uint64_t>(fields[3]);
    if (!seed) {
        throw InputError(source, number, "seed '" + fields[3] + "' must be a non-negative integer");
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
    if (fields.size() > 6 && !fields[6].empty()) {
        try {
            entry.container = Container::parse(fields[6]);  // the header key's parser
        } catch (const ParameterError& error) {
            throw InputError(source, number, "container " + error.value() + ": " + error.rule());
        }
    }
    return entry;
}

}  // namespace

std::vector<ManifestEntry> read_manifest(std::istream& in, const std::string& source) {
    LineReader reader(in, source);
    std::string line;
    if (!reader.next(line)) {
        throw InputError(source, 0,
                         "empty manifest: expected the header '" + std::string(kHeader) + "'");
    }
    const std::string with_container = std::string(kHeader) + ",container";
    if (line != kHeader && line != with_container) {
        throw InputError(source, 1,
                         "expected the header '" + std::string(kHeader) + "' (or '" +
                             with_container + "'), found '" + line + "'");
    }
    const std::size_t width = line == kHeader ? 6 : 7;
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
        if (quoted->size() != width) {
            throw InputError(source, number,
                             "expected " + std::to_string(width) +
                                 " comma-separated fields, found " +
                                 std::to_string(quoted->size()));
        }
        for (const auto& field : *quoted) {  // every field reaches crossval.json
            if (!is_utf8(field)) {
                throw InputError(source, number,
                                 "field '" + field +
                                     "' is not UTF-8 (a Latin-1 byte?): a "
                                     "manifest must be UTF-8 text");
            }
        }
        ManifestEntry entry = parse_entry(*quoted, source, number);
        entry.line = number;
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
