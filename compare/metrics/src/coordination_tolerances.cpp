#include "sgmp/metrics/coordination_tolerances.hpp"

namespace sgmp::metrics {

const std::vector<double>& coordination_tolerances() {
    static const std::vector<double> values{0.0, 1e-6, 1e-3, 1e-2, 2e-2, 5e-2};
    return values;
}

const std::vector<std::string>& coordination_tolerance_names() {
    static const std::vector<std::string> names{"0", "1e-6", "1e-3", "1e-2", "2e-2", "5e-2"};
    return names;
}

const std::vector<std::string>& coordination_tolerance_labels() {
    static const std::vector<std::string> labels{"0", "10⁻⁶", "10⁻³", "10⁻²", "2·10⁻²", "5·10⁻²"};
    return labels;
}

}  // namespace sgmp::metrics
