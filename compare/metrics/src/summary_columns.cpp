#include "sgmp/metrics/summary_columns.hpp"

#include <cmath>
#include <string>

#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp::metrics {

const std::vector<SummaryColumn>& summary_columns() {
    static const std::vector<SummaryColumn> columns = [] {
        std::vector<SummaryColumn> c;
        for (const MetricDescriptor* d : ranked_metrics(&MetricDescriptor::summary_rank)) {
            c.push_back({d->summary_column, d->name, d->integer, d->summary_optional, d->value,
                         d->tolerance});
        }
        return c;
    }();
    return columns;
}

std::vector<std::string> summary_column_names() {
    std::vector<std::string> names;
    for (const SummaryColumn& c : summary_columns()) {
        names.push_back(c.column);
    }
    return names;
}

const SummaryColumn* summary_column_of(const std::string& metric) {
    for (const SummaryColumn& c : summary_columns()) {
        if (c.metric == metric) {
            return &c;
        }
    }
    return nullptr;
}

}  // namespace sgmp::metrics
