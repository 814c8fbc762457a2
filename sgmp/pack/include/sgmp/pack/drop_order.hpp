#pragma once
/// @file drop_order.hpp
/// The order in which a blend's particles are dropped (`--drop-order`). With species
/// counts nᵢ summing to N:
///  - stratified (the default): drop k = 1, …, N is the species with the largest deficit
///    k·nᵢ/N − pᵢ (pᵢ: its drops so far; ties to the earlier species), so every run of
///    drops from the first holds each species within one particle of its share. A
///    deposit grows bottom-up in drop order, so each height of the bed gets the blend's
///    composition, not a random sample of it.
///  - shuffled: a uniform random permutation (Fisher–Yates), whose composition over any
///    k drops scatters binomially (sd √(k·fᵢ·(1 − fᵢ)) particles).
/// One size has one order.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "sgmp/pack/name_table.hpp"

namespace sgmp {

enum class DropOrder { Stratified, Shuffled };

/// stratified, shuffled.
const NameTable<DropOrder, 2>& drop_orders();
std::string_view to_string(DropOrder order);
std::optional<DropOrder> parse_drop_order(std::string_view text);

/// The stratified sequence of species indices 0, 1, … for the counts (their sum long).
std::vector<std::size_t> stratified_sequence(const std::vector<std::size_t>& counts);

}  // namespace sgmp
