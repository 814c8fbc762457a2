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

}  // namespace sgmp::metrics
