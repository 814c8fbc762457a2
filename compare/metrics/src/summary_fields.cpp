// summary_fields (summary_columns.hpp): measuring a pack for its summary row, kept apart
// from the column table so that the summary's readers need not link the measurement.
#include <cmath>
#include <string>

#include "sgmp/metrics/summary_columns.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp::metrics {

std::vector<std::string> summary_fields(const Pack& pack, bool voronoi, unsigned threads) {
    MeasureOptions options;
    options.voronoi = voronoi;
    options.threads = threads;
    options.gr_range = kSummaryGrRange;
    const Measurement m = measure(pack, options);
    std::vector<std::string> fields;
    for (const SummaryColumn& c : summary_columns()) {
        const std::optional<double> v = c.value(m, c.tolerance);
        if (!v) {
            fields.emplace_back();
        } else if (c.integer) {
            fields.push_back(std::to_string(std::llround(*v)));
        } else {
            fields.push_back(format_number(*v));
        }
    }
    return fields;
}

}  // namespace sgmp::metrics
