#include "sgmp/batch/shard.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"

namespace sgmp::batch {
namespace {

/// A whole number written in decimal digits, nothing else (the pack library's strict parse).
std::optional<std::size_t> whole(std::string_view text) {
    return parse_csv_number<std::size_t>(std::string(text));
}

}  // namespace

Shard parse_shard(std::string_view text) {
    const std::size_t slash = text.find('/');
    const auto index = whole(text.substr(0, slash));
    const auto count =
        slash == std::string_view::npos ? std::nullopt : whole(text.substr(slash + 1));
    if (!index || !count || *count == 0) {
        throw ParameterError("shard", printable(text),
                             "must be I/N with whole numbers N >= 1 and 1 <= I <= N, e.g. 3/40");
    }
    if (*index < 1 || *index > *count) {
        throw ParameterError("shard", printable(text),
                             "I must lie in 1.." + std::to_string(*count));
    }
    return {*index, *count};
}

std::vector<std::size_t> assigned_jobs(std::size_t job_count, Shard shard, std::size_t rank,
                                       std::size_t ranks) {
    std::vector<std::size_t> jobs;
    std::size_t position = 0;  // within the shard
    for (std::size_t j = shard.index - 1; j < job_count; j += shard.count, ++position) {
        if (position % ranks == rank) {
            jobs.push_back(j);
        }
    }
    return jobs;
}

}  // namespace sgmp::batch
