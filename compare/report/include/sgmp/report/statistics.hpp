#pragma once
/// @file statistics.hpp
/// Seed-to-seed statistics: mean, sample standard deviation (n − 1), and the L2 distance
/// between curves sampled on the same bins.

#include <vector>

namespace sgmp::report {

double mean(const std::vector<double>& values);
/// Sample standard deviation √(Σ(x − x̄)² / (n − 1)); 0 for fewer than two values.
double sample_sd(const std::vector<double>& values);

/// Element-wise mean of curves of equal length.
std::vector<double> mean_curve(const std::vector<std::vector<double>>& curves);

/// √(Σ_k (a_k − b_k)² · width) over the bins k whose centres x_k lie in [lo, hi].
double l2_distance(const std::vector<double>& x, const std::vector<double>& a,
                   const std::vector<double>& b, double width, double lo, double hi);

}  // namespace sgmp::report
