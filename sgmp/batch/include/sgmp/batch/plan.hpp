#pragma once
/// @file plan.hpp
/// A sweep's job list: the Cartesian product of the value lists of every parameter
/// (parameters.hpp) with the seed list. Jobs are numbered 0 … M−1 in a fixed order — the
/// parameter combinations in lexicographic order of parameters() (the first parameter
/// outermost, each list in the order given), and for each combination every seed in the
/// order given — so job j has combination j / S and seed seeds[j mod S] (S seeds). The
/// order depends on the inputs only, never on timing, threads, ranks or shards.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sgmp/batch/parameters.hpp"

namespace sgmp::batch {

/// Most jobs one plan may hold (a plan stores its value lists and seeds, not its jobs).
inline constexpr std::uint64_t kMaxJobs = 100'000'000;
/// Most jobs one batch process runs (its shard): each keeps its summary row, about 0.9 kB,
/// until the table is written, so memory stays near 1 GB.
inline constexpr std::uint64_t kMaxJobsPerBatch = 1'000'000;

/// Value lists as given; an empty list means the parameter's default (count and
/// arrangement have none and must be given).
struct Grid {
    std::vector<std::vector<std::string>> values =
        std::vector<std::vector<std::string>>(parameters().size());
    std::vector<std::uint64_t> seeds;
    /// The size-distribution files the values name, read by the front end.
    DistributionFiles distribution_files;
};

struct Plan {
    std::vector<ParameterValues> combinations;
    std::vector<std::uint64_t> seeds;
    std::vector<bool> varies;              // per parameter: more than one value in the grid
    DistributionFiles distribution_files;  // the grid's

    [[nodiscard]] std::size_t job_count() const { return combinations.size() * seeds.size(); }
    [[nodiscard]] const ParameterValues& values(std::size_t job) const {
        return combinations[job / seeds.size()];
    }
    [[nodiscard]] std::uint64_t seed(std::size_t job) const { return seeds[job % seeds.size()]; }
};

/// The plan of `grid`. Every combination is checked as `sgmp pack` checks it, so a bad
/// value fails here, before any pack is made. Throws std::invalid_argument (one line,
/// naming the option, the value and the rule) for an empty list of counts, arrangements
/// or seeds, a value repeated within one list, an invalid combination or more than
/// kMaxJobs jobs.
Plan make_plan(const Grid& grid);

}  // namespace sgmp::batch
