#include "sgmp/report/group_curves.hpp"

#include <algorithm>
#include <cmath>

#include "sgmp/report/statistics.hpp"

namespace sgmp::report {
namespace {

std::vector<double> sd_curve(const std::vector<std::vector<double>>& curves) {
    std::vector<double> sd(curves.front().size(), 0.0);
    for (std::size_t k = 0; k < sd.size(); ++k) {
        std::vector<double> column;
        for (const auto& c : curves) {
            column.push_back(c[k]);
        }
        sd[k] = sample_sd(column);
    }
    return sd;
}

/// φ(y): slabs share y0 and thickness for packs of one count (the grid starts at the
/// floor); tops differ, so each slab is averaged over the packs that reach it.
void phi_profile_of(const std::vector<const PackSummary*>& packs, GroupCurves& c) {
    bool same_grid = true;
    std::size_t longest = 0;
    for (const auto* p : packs) {
        const auto& y = p->phi_y_mid;
        const auto& y0 = packs.front()->phi_y_mid;
        same_grid = same_grid && !y.empty() && !y0.empty() && y[0] == y0[0] &&
                    (y.size() < 2 || y0.size() < 2 || y[1] == y0[1]);
        if (y.size() > longest) {
            longest = y.size();
            c.phi_y_mid = y;
        }
    }
    if (!same_grid) {
        c.phi_y_mid = packs.front()->phi_y_mid;
        c.phi_y = packs.front()->phi_y;
        c.phi_y_note = "slab grids differ between packs; the first pack's profile is shown";
        return;
    }
    c.phi_y.assign(longest, 0.0);
    std::vector<int> reached(longest, 0);
    for (const auto* p : packs) {
        for (std::size_t k = 0; k < p->phi_y.size(); ++k) {
            c.phi_y[k] += p->phi_y[k];
            ++reached[k];
        }
    }
    for (std::size_t k = 0; k < longest; ++k) {
        c.phi_y[k] /= reached[k];
    }
}

}  // namespace

GroupCurves curves_of(const std::vector<const PackSummary*>& all) {
    GroupCurves c;
    // Packs known by their scalars only (precomputed.hpp) add no curves.
    std::vector<const PackSummary*> packs;
    std::copy_if(all.begin(), all.end(), std::back_inserter(packs),
                 [](const PackSummary* p) { return p->has_curves(); });
    if (packs.empty()) {
        std::vector<std::vector<double>> z;
        for (const auto* p : all) {
            z.push_back(p->z_mean);
        }
        c.z_mean = mean_curve(z);
        c.p_z.assign(all.front()->p_z.size(), {});
        return c;
    }
    std::vector<std::vector<double>> gr;
    std::vector<std::vector<double>> z;
    for (const auto* p : packs) {
        gr.push_back(p->gr);
        z.push_back(p->z_mean);
    }
    c.gr_r = packs.front()->gr_r;
    c.gr = mean_curve(gr);
    c.gr_sd = sd_curve(gr);
    c.z_mean = mean_curve(z);
    const std::size_t tolerances = packs.front()->p_z.size();
    for (std::size_t t = 0; t < tolerances; ++t) {
        std::size_t longest = 0;
        for (const auto* p : packs) {
            longest = std::max(longest, p->p_z[t].size());
        }
        std::vector<std::vector<double>> pz;
        for (const auto* p : packs) {
            auto padded = p->p_z[t];
            padded.resize(longest, 0.0);
            pz.push_back(std::move(padded));
        }
        c.p_z.push_back(mean_curve(pz));
    }
    phi_profile_of(packs, c);
    return c;
}

}  // namespace sgmp::report
