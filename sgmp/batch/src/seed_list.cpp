#include "sgmp/batch/seed_list.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"

namespace sgmp::batch {
namespace {

/// A whole number written in decimal digits, nothing else (the pack library's strict parse).
std::optional<std::uint64_t> whole(std::string_view text) {
    return parse_csv_number<std::uint64_t>(std::string(text));
}

}  // namespace

std::vector<std::uint64_t> parse_seed_list(std::string_view text) {
    const auto refuse = [&](const std::string& rule) {
        throw ParameterError("seeds", printable(text), rule);
    };
    const std::string form =
        "must be seeds S or ranges A-B (A <= B) of whole numbers from 0 to "
        "18446744073709551615, separated by commas, e.g. 1-100000 or 1,5,9-12";
    std::vector<std::uint64_t> seeds;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::string_view item = text.substr(start, comma - start);
        const std::size_t dash = item.find('-');
        const auto lo = whole(item.substr(0, dash));
        const auto hi = dash == std::string_view::npos ? lo : whole(item.substr(dash + 1));
        if (!lo || !hi) {
            refuse(form);
        }
        if (*lo > *hi) {
            refuse("range " + std::string(item) + " runs backwards (A must not exceed B)");
        }
        if (*hi - *lo >= kMaxSeeds - seeds.size()) {
            refuse("holds more than " + std::to_string(kMaxSeeds) + " seeds");
        }
        for (std::uint64_t s = *lo;; ++s) {
            seeds.push_back(s);
            if (s == *hi) {
                break;
            }
        }
        start = comma + 1;
    }
    std::vector<std::uint64_t> sorted = seeds;
    std::sort(sorted.begin(), sorted.end());
    const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeated != sorted.end()) {
        refuse("seed " + std::to_string(*repeated) + " appears twice");
    }
    return seeds;
}

}  // namespace sgmp::batch
