// The agreement rule checks itself on the stored LIGGGHTS pours (data/reference/):
// - the variant set (the same physics set up differently: E = 5e8 Pa, a taller starting
//   cloud) agrees with the main set on every judged metric at every count it has, with at
//   most 1 false alarm in 20 verdicts; its model spread at the count judged is taken from
//   the other counts only (leave one count out), so the check is not circular;
// - DEM μ = 0.5 differs from μ = 0.01 on φ and Z(δ = 10⁻³) at every N ≥ 2001, and on g(r)
//   at N = 9000, where DEM can tell the classes apart;
// - the hard-sphere limits of μ = 0 and μ = 0.5 (from the stiff set) are what an independent
//   scipy extrapolation of the same pours gives, lie below the pours in Z, and differ from
//   each other on φ and Z(δ = 10⁻³) at every count both have.
#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sgmp/compare/agreement.hpp"
#include "sgmp/compare/hard_sphere_limit.hpp"
#include "sgmp/pack/pack_file.hpp"

using namespace sgmp;
using namespace sgmp::compare;
namespace fs = std::filesystem;

namespace {

const std::vector<std::size_t> kCounts{150, 300, 750, 1002, 2001, 3000, 6000, 9000};

std::string pour_path(const std::string& set, std::size_t count, const std::string& mu, int seed) {
    char name[128];
    std::snprintf(name, sizeof name, "%s/n%04zu-mu%s-seed%d.xyz.gz", set.c_str(), count, mu.c_str(),
                  seed);
    return std::string(SGMP_SOURCE_DIR) + "/data/reference/" + name;
}

/// Every stored pour of one set and class (seeds 1–5 where present).
Group pours(const std::string& label, const std::string& set, const std::string& mu) {
    Group g;
    g.label = label;
    for (const std::size_t n : kCounts) {
        for (int seed = 1; seed <= 5; ++seed) {
            const std::string path = pour_path(set, n, mu, seed);
            if (!fs::exists(path)) {
                continue;
            }
            const Pack pack = read_pack_file(path);
            g.packs.push_back(summarise(path, pack, measure(pack, MeasureOptions{})));
        }
    }
    return g;
}

Group only_counts(const Group& g, std::size_t count, bool keep) {
    Group out;
    out.label = g.label;
    for (const auto& p : g.packs) {
        if ((p.count == count) == keep) {
            out.packs.push_back(p);
        }
    }
    return out;
}

struct Sets {
    Group main_frictional = pours("DEM mu=0.5", ".", "0.5");
    Group main_smooth = pours("DEM mu=0.01", ".", "0.01");
    Group variant_frictional = pours("variant mu=0.5", "variant", "0.5");
    Group variant_smooth = pours("variant mu=0.01", "variant", "0.01");
};

const Sets& sets() {
    static const Sets s;
    return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(dem_classes)

BOOST_AUTO_TEST_CASE(the_variant_set_agrees_with_the_main_set) {
    std::size_t judged = 0;
    std::size_t false_alarms = 0;
    const std::pair<const Group*, const Group*> classes[] = {
        {&sets().main_frictional, &sets().variant_frictional},
        {&sets().main_smooth, &sets().variant_smooth}};
    for (const auto& [main, variant] : classes) {
        BOOST_TEST_REQUIRE(!variant->packs.empty(), "no variant pours for " << main->label);
        for (const std::size_t n : kCounts) {
            const Group here = only_counts(*variant, n, true);
            if (here.packs.empty()) {
                continue;
            }
            // Candidate: the variant at n; reference: the main set; model spread from the
            // variant's other counts.
            ReportPlan plan;
            plan.comparisons = {{0, 1}};
            plan.variants[1] = 2;
            const Report r = build_report({here, *main, only_counts(*variant, n, false)}, plan);
            BOOST_TEST_REQUIRE(r.comparisons.size() == 1u);
            for (const auto& row : r.comparisons[0].rows) {
                if (row.verdict == Verdict::Info) {
                    continue;
                }
                ++judged;
                if (row.verdict != Verdict::Agree) {
                    ++false_alarms;
                    BOOST_TEST_MESSAGE(main->label << " N = " << n << ": " << row.name << " "
                                                   << row.verdict << ", ratio "
                                                   << (row.ratio ? *row.ratio : -1.0));
                }
            }
        }
    }
    BOOST_TEST_MESSAGE("variant against main: " << false_alarms << " of " << judged
                                                << " verdicts not agree");
    BOOST_TEST(judged >= 4u * 2u * 10u);  // at least 4 counts × 2 classes × 10 metrics
    BOOST_TEST(20 * false_alarms <= judged, false_alarms << " false alarms in " << judged);
}

BOOST_AUTO_TEST_CASE(the_friction_classes_differ_where_dem_tells_them_apart) {
    ReportPlan plan;
    plan.comparisons = {{0, 1}};
    plan.variants[1] = 2;
    const Report r =
        build_report({sets().main_frictional, sets().main_smooth, sets().variant_smooth}, plan);
    for (const auto& c : r.comparisons) {
        BOOST_TEST_MESSAGE(
            "N = " << c.count << ": phi " << c.row("phi").verdict << " (" << *c.row("phi").ratio
                   << "), Z(1e-3) " << c.row("z_mean_tol_1e-3").verdict << " ("
                   << *c.row("z_mean_tol_1e-3").ratio << "), g(r) " << c.row("g_r").verdict << " ("
                   << *c.row("g_r").ratio << "), split " << c.row("split_ratio").verdict << " ("
                   << *c.row("split_ratio").ratio << ")");
        if (c.count >= 2001) {
            BOOST_TEST(c.row("phi").verdict == Verdict::Differ, "N = " << c.count);
            BOOST_TEST(c.row("z_mean_tol_1e-3").verdict == Verdict::Differ, "N = " << c.count);
        }
        if (c.count == 9000) {
            BOOST_TEST(c.row("g_r").verdict == Verdict::Differ);
        }
    }
    BOOST_TEST(r.comparisons.size() == kCounts.size());
}

BOOST_AUTO_TEST_CASE(the_hard_sphere_limits_of_the_classes) {
    std::vector<std::string> unpaired;
    const Group smooth = hard_sphere_limit(pours("DEM mu=0", ".", "0"),
                                           pours("DEM mu=0 (stiff)", "stiff", "0"), "0", unpaired);
    const Group frictional = hard_sphere_limit(
        sets().main_frictional, pours("DEM mu=0.5 (stiff)", "stiff", "0.5"), "0.5", unpaired);
    BOOST_TEST(unpaired.empty());
    BOOST_TEST_REQUIRE(smooth.packs.size() >= 12u);  // 1002, 2001, 3000, 9000 × 3 seeds
    const auto mean_at = [](const Group& g, std::size_t n, const std::string& metric) {
        const auto& rules = metric_rules();
        std::size_t k = 0;
        for (const auto& rule : rules) {
            if (rule.name == metric) {
                break;
            }
            k += rule.kind == MetricKind::Scalar ? 1 : 0;
        }
        double sum = 0.0;
        int packs = 0;
        for (const auto& p : g.packs) {
            if (p.count == n) {
                sum += p.scalars[k];
                ++packs;
            }
        }
        return sum / packs;
    };
    // scripts/hard-sphere-limit and a scipy kd-tree count of the same six pours: 5.970 and
    // 6.044 (3 decimals; tolerance 0.005, the rounding plus the two codes' control volumes).
    BOOST_TEST(std::abs(mean_at(smooth, 3000, "z_mean_tol_1e-3") - 5.970) < 0.005);
    BOOST_TEST(std::abs(mean_at(smooth, 9000, "z_mean_tol_1e-3") - 6.044) < 0.005);
    BOOST_TEST(std::abs(mean_at(smooth, 9000, "phi") - 0.6324) < 0.0005);

    Group smooth_pours = pours("DEM mu=0", ".", "0");
    ReportPlan plan;
    plan.comparisons = {{0, 1}};
    const Report r = build_report({smooth, frictional}, plan);
    std::size_t compared = 0;
    for (const auto& c : r.comparisons) {
        ++compared;
        BOOST_TEST(c.row("phi").verdict == Verdict::Differ, "N = " << c.count);
        BOOST_TEST(c.row("z_mean_tol_1e-3").verdict == Verdict::Differ, "N = " << c.count);
        BOOST_TEST(mean_at(smooth, c.count, "z_mean_tol_1e-3") <
                       mean_at(smooth_pours, c.count, "z_mean_tol_1e-3"),
                   "N = " << c.count);
    }
    BOOST_TEST(compared >= 4u);  // 1002, 2001, 3000, 9000 at least
}

BOOST_AUTO_TEST_SUITE_END()
