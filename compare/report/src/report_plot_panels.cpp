// Which plots a report gets (report_plots.hpp): one panel per comparison or per count,
// split into panels of at most kMaxSeries curves, and the metrics' trends over the counts.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/report/report_plots.hpp"

namespace sgmp::report {
namespace {

/// A mean curve's legend entry: the group and the packs it averages.
std::string mean_label(const std::string& label, std::size_t packs) {
    return label + " (mean of " + std::to_string(packs) + ")";
}

}  // namespace

std::vector<Trend> trends_of(const Report& report, const std::vector<std::string>& metrics) {
    std::vector<Trend> trends;
    const auto series = [&](const std::string& metric, const std::string& label,
                            bool reference) -> Trend& {
        for (auto& t : trends) {
            if (t.metric == metric && t.label == label && t.reference == reference) {
                return t;
            }
        }
        trends.push_back(Trend{metric, metric_rule(metric).label, label, reference, {}, {}, {}});
        return trends.back();
    };
    for (const auto& metric : metrics) {
        for (const auto& c : report.comparisons) {
            const MetricRow& row = c.row(metric);
            const auto n = static_cast<double>(c.count);
            Trend& a = series(metric, c.candidate, false);
            if (a.count.empty() || a.count.back() != n) {
                a.count.push_back(n);
                a.mean.push_back(row.candidate_mean);
                a.sd.push_back(row.candidate_sd);
            }
            Trend& b = series(metric, c.reference, true);
            if (std::find(b.count.begin(), b.count.end(), n) == b.count.end()) {
                b.count.push_back(n);
                b.mean.push_back(row.reference_mean);
                b.sd.push_back(row.reference_sd);
            }
        }
    }
    for (auto& t : trends) {  // references in count order (comparisons come per candidate)
        std::vector<std::size_t> order(t.count.size());
        for (std::size_t i = 0; i < order.size(); ++i) {
            order[i] = i;
        }
        std::sort(order.begin(), order.end(),
                  [&](std::size_t x, std::size_t y) { return t.count[x] < t.count[y]; });
        Trend sorted = t;
        for (std::size_t i = 0; i < order.size(); ++i) {
            sorted.count[i] = t.count[order[i]];
            sorted.mean[i] = t.mean[order[i]];
            sorted.sd[i] = t.sd[order[i]];
        }
        t = sorted;
    }
    return trends;
}

/// $SGMP_GNUPLOT when set (a path, or empty to disable plots), else gnuplot on $PATH.
std::vector<PlotPanel> panels_per_comparison(const Report& report) {
    std::vector<PlotPanel> panels;
    for (std::size_t i = 0; i < report.comparisons.size(); ++i) {
        const Comparison& c = report.comparisons[i];
        panels.push_back(
            PlotPanel{"c" + std::to_string(i) + "_N" + std::to_string(c.count),
                      c.candidate + " vs " + c.reference + ", N = " + std::to_string(c.count),
                      {PlotCurve{mean_label(c.candidate, c.candidate_packs), &c.candidate_curves,
                                 false, c.candidate},
                       PlotCurve{mean_label(c.reference, c.reference_packs), &c.reference_curves,
                                 true, c.reference}}});
    }
    return panels;
}

std::vector<std::vector<std::size_t>> split_series(const std::vector<bool>& reference) {
    std::vector<std::size_t> refs, cands;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        (reference[i] ? refs : cands).push_back(i);
    }
    const auto chunks = [](const std::vector<std::size_t>& items, std::size_t size) {
        std::vector<std::vector<std::size_t>> out;
        for (std::size_t i = 0; i < items.size(); i += size) {
            out.emplace_back(
                items.begin() + static_cast<std::ptrdiff_t>(i),
                items.begin() + static_cast<std::ptrdiff_t>(std::min(items.size(), i + size)));
        }
        return out;
    };
    if (refs.empty() || cands.empty()) {
        std::vector<std::size_t> all(reference.size());
        for (std::size_t i = 0; i < all.size(); ++i) {
            all[i] = i;
        }
        return chunks(all, kMaxSeries);
    }
    const std::size_t per_ref = std::min<std::size_t>(refs.size(), 3);
    std::vector<std::vector<std::size_t>> out;
    for (const auto& r : chunks(refs, per_ref)) {
        for (const auto& c : chunks(cands, kMaxSeries - per_ref)) {
            out.push_back(c);
            out.back().insert(out.back().end(), r.begin(), r.end());
        }
    }
    return out;
}

namespace {

/// `panel` cut into panels of at most kMaxSeries curves (split_series).
std::vector<PlotPanel> split_panel(const PlotPanel& panel) {
    std::vector<bool> reference;
    std::vector<std::pair<std::string, bool>> series;
    for (const auto& curve : panel.curves) {
        reference.push_back(curve.reference);
        series.emplace_back(curve.group.empty() ? curve.label : curve.group, curve.reference);
    }
    const auto parts = split_series(reference);
    std::vector<PlotPanel> out;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        PlotPanel part{panel.stem + (p == 0 ? "" : "_" + std::to_string(p + 1)),
                       panel.what + (parts.size() > 1 ? " (" + std::to_string(p + 1) + " of " +
                                                            std::to_string(parts.size()) + ")"
                                                      : ""),
                       {}};
        for (const std::size_t k : parts[p]) {
            part.curves.push_back(panel.curves[k]);
            part.curves.back().slot = k;
        }
        if (parts.size() > 1) {
            part.series = series;  // one colour per group across the parts
        }
        out.push_back(std::move(part));
    }
    return out;
}

}  // namespace

std::vector<PlotPanel> panels_per_count(const Report& report) {
    std::vector<PlotPanel> panels;
    std::vector<std::set<std::string>> drawn;
    for (const Comparison& c : report.comparisons) {
        std::size_t k = 0;
        while (k < panels.size() && panels[k].stem != "N" + std::to_string(c.count)) {
            ++k;
        }
        if (k == panels.size()) {
            panels.push_back(
                PlotPanel{"N" + std::to_string(c.count), "N = " + std::to_string(c.count), {}});
            drawn.emplace_back();
        }
        if (drawn[k].insert(c.candidate).second) {
            panels[k].curves.push_back(PlotCurve{mean_label(c.candidate, c.candidate_packs),
                                                 &c.candidate_curves, false, c.candidate});
        }
        if (drawn[k].insert(c.reference).second) {
            panels[k].curves.push_back(PlotCurve{mean_label(c.reference, c.reference_packs),
                                                 &c.reference_curves, true, c.reference});
        }
    }
    std::vector<PlotPanel> split;
    for (const PlotPanel& panel : panels) {
        for (PlotPanel& part : split_panel(panel)) {
            split.push_back(std::move(part));
        }
    }
    return split;
}

}  // namespace sgmp::report
