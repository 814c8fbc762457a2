#pragma once
/// @file seed_list.hpp
/// Seed lists as typed after `--seeds`: comma-separated items, each a seed `S` or an
/// inclusive range `A-B` with A ≤ B (`1-100000`, `1,5,9-12`). Seeds are whole numbers in
/// [0, 2^64 − 1]; a seed may appear only once.

#include <cstdint>
#include <string_view>
#include <vector>

namespace sgmp::batch {

/// Most seeds one list may hold (ten million packs per batch).
inline constexpr std::uint64_t kMaxSeeds = 10'000'000;

/// The seeds of `text` in the order written. Throws std::invalid_argument
/// "--seeds TEXT: rule" for an empty or malformed item, a range with A > B, a repeated
/// seed or more than kMaxSeeds seeds.
std::vector<std::uint64_t> parse_seed_list(std::string_view text);

}  // namespace sgmp::batch
