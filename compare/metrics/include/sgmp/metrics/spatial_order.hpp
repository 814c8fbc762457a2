#pragma once
/// @file spatial_order.hpp
/// Points sorted along a Morton (Z-order) curve of cubic cells, so that points near in
/// space are near in the order (and in memory, once copied in it). The order depends only
/// on the input.

#include <vector>

#include "sgmp/metrics/neighbour_index.hpp"

namespace sgmp::metrics {

/// `subset` (indices into `points`) sorted by the Morton code of their cell of side `cell`.
std::vector<Index> spatial_order(const std::vector<Particle>& points, std::vector<Index> subset,
                                 double cell, unsigned threads = 0);

}  // namespace sgmp::metrics
