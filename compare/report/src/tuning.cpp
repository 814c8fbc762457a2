#include "sgmp/report/tuning.hpp"

#include <sstream>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/line_reader.hpp"

namespace sgmp::report {
namespace {

constexpr const char* kHeader = "group,parameter,value,reference,count,seeds,note";
constexpr std::uint64_t kMostSeeds = 100000;  // a range wider than this is a mistake

/// Seeds "1 2 5-7"; nullopt on anything else.
std::optional<std::set<std::uint64_t>> parse_seeds(const std::string& text) {
    std::set<std::uint64_t> seeds;
    std::istringstream words(text);
    std::string word;
    while (words >> word) {
        const auto dash = word.find('-');
        const auto first = parse_csv_number<std::uint64_t>(word.substr(0, dash));
        const auto last = dash == std::string::npos
                              ? first
                              : parse_csv_number<std::uint64_t>(word.substr(dash + 1));
        if (!first || !last || *last < *first || *last - *first > kMostSeeds) {
            return std::nullopt;
        }
        for (std::uint64_t s = *first; s <= *last; ++s) {
            seeds.insert(s);
        }
    }
    if (seeds.empty()) {
        return std::nullopt;
    }
    return seeds;
}

}  // namespace

std::vector<TunedParameter> read_tuning(std::istream& in, const std::string& source) {
    LineReader reader(in, source);
    std::string line;
    if (!reader.next(line) || line != kHeader) {
        throw InputError(source, 1, "expected the header '" + std::string(kHeader) + "'");
    }
    std::vector<TunedParameter> result;
    while (reader.next(line)) {
        const std::size_t number = reader.line_number();
        if (line.find_first_not_of(" \t") == std::string::npos) {
            continue;
        }
        const auto fields = split_quoted_csv_line(line);
        if (!fields || fields->size() != 7) {
            throw InputError(source, number, "expected 7 comma-separated fields");
        }
        const auto& f = *fields;
        TunedParameter t{f[0], f[1], f[2], f[3], 0, {}, f[6]};
        if (t.group.empty() || t.parameter.empty() || t.reference.empty()) {
            throw InputError(source, number, "group, parameter and reference must not be empty");
        }
        const auto count = parse_csv_number<std::size_t>(f[4]);
        if (!count || *count == 0) {
            throw InputError(source, number, "count '" + f[4] + "' must be a positive integer");
        }
        t.count = *count;
        const auto seeds = parse_seeds(f[5]);
        if (!seeds) {
            throw InputError(source, number,
                             "seeds '" + f[5] + "' must be integers or ranges a-b (a <= b)");
        }
        t.seeds = *seeds;
        result.push_back(std::move(t));
    }
    return result;
}

std::size_t withhold_tuned(Report& report, const std::vector<TunedParameter>& tuning,
                           const std::vector<ManifestEntry>& manifest) {
    std::size_t withheld = 0;
    for (auto& c : report.comparisons) {
        for (const auto& t : tuning) {
            if (c.candidate != t.group || c.reference != t.reference || c.count != t.count) {
                continue;
            }
            bool used = false;
            for (const auto& e : manifest) {
                used = used || (e.role == Role::Reference && e.group == t.reference &&
                                e.count == t.count && t.seeds.count(e.seed) != 0);
            }
            if (!used) {
                continue;
            }
            ++withheld;
            for (auto& row : c.rows) {
                if (row.verdict != Verdict::Info) {  // the verdict it would have stays in view
                    row.tolerance_rule = "tuned on these seeds (would be " +
                                         std::string(to_string(row.verdict)) + ")";
                    row.verdict = Verdict::Info;
                }
            }
        }
    }
    return withheld;
}

}  // namespace sgmp::report
