#pragma once
// A physically possible value of each scalar metric (check_physical accepts it), for tests
// that build pack summaries by hand around it.
#include <string>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report::test {

inline double centre_of(const MetricRule& rule) {
    if (rule.name == "phi" || rule.name == "voronoi_phi_mean") {
        return 0.60;
    }
    if (rule.name.rfind("z_mean", 0) == 0) {
        return 6.0;
    }
    if (rule.name == "split_ratio" || rule.name == "q6_local_mean") {
        return 0.5;
    }
    if (rule.name == "voronoi_phi_sd") {
        return 0.1;
    }
    if (rule.name == "q6_global") {
        return 0.3;
    }
    return 0.0;  // the overlap metrics (info): none
}

}  // namespace sgmp::report::test
