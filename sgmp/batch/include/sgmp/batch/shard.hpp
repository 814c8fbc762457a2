#pragma once
/// @file shard.hpp
/// Splitting a plan's jobs between independent processes: `--shard I/N` (1 ≤ I ≤ N) takes
/// the jobs j with j mod N = I − 1 (round-robin over the job order, so shards of a sweep
/// mixing small and large packs get the same mix), and the R ranks of an MPI run split a
/// shard's jobs the same way again. The union of all shards (and ranks) is every job, each
/// exactly once.

#include <cstddef>
#include <string_view>
#include <vector>

namespace sgmp::batch {

struct Shard {
    std::size_t index = 1;  // I, 1-based
    std::size_t count = 1;  // N
};

/// Parses "I/N". Throws std::invalid_argument "--shard TEXT: rule" when I or N is not a
/// whole number or I lies outside 1..N.
Shard parse_shard(std::string_view text);

/// The jobs of `shard` taken by rank `rank` of `ranks`, in job order.
std::vector<std::size_t> assigned_jobs(std::size_t job_count, Shard shard, std::size_t rank = 0,
                                       std::size_t ranks = 1);

}  // namespace sgmp::batch
