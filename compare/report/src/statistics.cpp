#include "sgmp/report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sgmp::report {

double mean(const std::vector<double>& values) {
    if (values.empty()) {
        return 0.0;
    }
    double sum = 0.0;
    for (const double v : values) {
        sum += v;
    }
    return sum / static_cast<double>(values.size());
}

double sample_sd(const std::vector<double>& values) {
    if (values.size() < 2 ||
        std::all_of(values.begin(), values.end(), [&](double v) { return v == values[0]; })) {
        return 0.0;  // exactly, not the rounding residue of the mean
    }
    const double m = mean(values);
    double sum = 0.0;
    for (const double v : values) {
        sum += (v - m) * (v - m);
    }
    return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

std::vector<double> mean_curve(const std::vector<std::vector<double>>& curves) {
    if (curves.empty()) {
        return {};
    }
    std::vector<double> result(curves.front().size(), 0.0);
    for (const auto& curve : curves) {
        if (curve.size() != result.size()) {
            throw std::invalid_argument("curves to average have different lengths");
        }
        for (std::size_t k = 0; k < curve.size(); ++k) {
            result[k] += curve[k];
        }
    }
    for (double& v : result) {
        v /= static_cast<double>(curves.size());
    }
    return result;
}

double l2_distance(const std::vector<double>& x, const std::vector<double>& a,
                   const std::vector<double>& b, double width, double lo, double hi) {
    if (a.size() != x.size() || b.size() != x.size()) {
        throw std::invalid_argument("curves to compare have different lengths");
    }
    double sum = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        if (x[k] >= lo && x[k] <= hi) {
            sum += (a[k] - b[k]) * (a[k] - b[k]) * width;
        }
    }
    return std::sqrt(sum);
}

}  // namespace sgmp::report
