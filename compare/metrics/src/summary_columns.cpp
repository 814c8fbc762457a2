#include "sgmp/metrics/summary_columns.hpp"

#include <cmath>
#include <string>

#include "sgmp/pack/metadata.hpp"

namespace sgmp::metrics {

const std::vector<SummaryColumn>& summary_columns() {
    static const std::vector<SummaryColumn> columns = [] {
        std::vector<SummaryColumn> c;
        c.push_back(
            {"phi", "phi", false, false,
             [](const Measurement& m, std::size_t) -> std::optional<double> { return m.phi; }});
        const auto& names = coordination_tolerance_names();
        for (std::size_t t = 0; t < names.size(); ++t) {
            c.push_back({"z_" + names[t], "z_mean_tol_" + names[t], false, false,
                         [](const Measurement& m, std::size_t k) -> std::optional<double> {
                             return m.local.coordination.z_mean.at(k);
                         },
                         t});
        }
        c.push_back({"overlaps", "overlaps", true, false,
                     [](const Measurement& m, std::size_t) -> std::optional<double> {
                         return static_cast<double>(m.overlaps.pairs.count);
                     }});
        c.push_back({"overlap_max", "overlap_max_over_d", false, false,
                     [](const Measurement& m, std::size_t) -> std::optional<double> {
                         return m.overlaps.pairs.max_over_d;
                     }});
        // The overlap depth that decides which contact metrics are judged (a summary
        // written before it was a column reads as not measured).
        c.push_back({"overlap_mean", "overlap_mean_over_d", false, true,
                     [](const Measurement& m, std::size_t) -> std::optional<double> {
                         return m.overlaps.pairs.mean_over_d;
                     }});
        c.push_back({"wall_overlaps", "wall_overlaps", true, false,
                     [](const Measurement& m, std::size_t) -> std::optional<double> {
                         return static_cast<double>(m.overlaps.walls.count);
                     }});
        c.push_back({"split_ratio", "split_ratio", false, false,
                     [](const Measurement& m, std::size_t) -> std::optional<double> {
                         return m.local.rdf.split_ratio;
                     }});
        c.push_back({"voronoi_phi_mean", "voronoi_phi_mean", false, true,
                     [](const Measurement& m, std::size_t) -> std::optional<double> {
                         if (!m.voronoi) {
                             return std::nullopt;
                         }
                         return m.voronoi->mean;
                     }});
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
