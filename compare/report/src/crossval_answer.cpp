#include "crossval_answer.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

#include "sgmp/metrics/metric_descriptors.hpp"

namespace sgmp::report {

namespace {

std::string decimals(double value, int places) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(places) << value;
    return out.str();
}

/// "150, 300 and 1002".
std::string count_list(const std::vector<std::size_t>& counts) {
    std::string text;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == counts.size() ? " and " : ", ") + std::to_string(counts[i]);
    }
    return text;
}

/// "a–b" or "a" of two whole numbers.
std::string span(std::size_t low, std::size_t high) {
    return low == high ? std::to_string(low) : std::to_string(low) + "–" + std::to_string(high);
}

std::vector<const HeadlineRow*> rows_of(const CrossValidation& cv, const std::string& mode) {
    std::vector<const HeadlineRow*> rows;
    for (const auto& row : cv.rows) {
        if (row.group == mode) {
            rows.push_back(&row);
        }
    }
    return rows;
}

/// "stands in for X at N = … (agrees on a–b of j judged metrics there, with s seeds)".
std::string relation(const StandIn& s, const std::vector<const HeadlineRow*>& rows) {
    std::ostringstream out;
    if (s.tallies.empty()) {
        return "not compared with **" + s.reference + "**";
    }
    if (s.decision == StandInDecision::Invalid) {
        return "not judged against **" + s.reference + "** (" + s.invalid + ")";
    }
    std::vector<std::size_t> standing;
    std::size_t agree_lo = std::numeric_limits<std::size_t>::max();
    std::size_t agree_hi = 0;
    std::size_t judged_hi = 0;
    for (const CountTally& t : s.tallies) {
        if (t.standing) {
            standing.push_back(t.count);
            agree_lo = std::min(agree_lo, t.agree);
            agree_hi = std::max(agree_hi, t.agree);
            judged_hi = std::max(judged_hi, t.judged);
        }
    }
    std::size_t seeds_lo = std::numeric_limits<std::size_t>::max();
    std::size_t seeds_hi = 0;
    for (const HeadlineRow* row : rows) {
        if (std::find(standing.begin(), standing.end(), row->count) != standing.end()) {
            seeds_lo = std::min(seeds_lo, row->packs);
            seeds_hi = std::max(seeds_hi, row->packs);
        }
    }
    if (s.decision == StandInDecision::Differs) {
        const KeptDifference d = leading_difference(s);
        out << "differs from **" << s.reference << "** (" << d.label << " at N = " << d.count
            << ", " << decimals(d.ratio, 1) << "× its margin";
        if (s.kept.size() > 1) {
            out << "; " << s.kept.size() - 1 << " more difference"
                << (s.kept.size() > 2 ? "s" : "");
        }
        out << ")";
    } else if (standing.empty()) {
        out << "undecided against **" << s.reference << "** (no count where a majority of the "
            << "judged metrics agrees; " << s.agree << " of " << s.agree + s.differ + s.inconclusive
            << " tests agree)";
    } else {
        out << (s.decision == StandInDecision::StandsIn ? "stands in for **"
                                                        : "stands in only partly for **")
            << s.reference << "** at N = " << count_list(standing) << " (agrees on "
            << span(agree_lo, agree_hi) << " of " << judged_hi << " judged metrics there, "
            << span(seeds_lo, seeds_hi) << " seeds)";
        if (s.decision != StandInDecision::StandsIn) {
            out << ", not at the other " << s.counts - standing.size() << " of " << s.counts
                << " counts";
        }
    }
    return out.str();
}

/// Where the mode's packs cannot be mechanically stable, or that they are certified (all, or
/// how many where some are not: a certificate, not Z, decides for a relaxed mode).
std::string stability(const std::vector<const HeadlineRow*>& rows) {
    std::vector<std::size_t> unstable;
    std::string partly;
    double z_lo = std::numeric_limits<double>::infinity();
    double z_hi = 0.0;
    bool certified = !rows.empty();
    for (const HeadlineRow* row : rows) {
        certified = certified && row->certified;
        if (row->with_certificate > 0) {
            if (!row->certified) {
                partly += (partly.empty() ? "" : "; ") + std::string("at N = ") +
                          std::to_string(row->count) + ", " + std::to_string(row->certified_packs) +
                          " of " + std::to_string(row->with_certificate) + " packs";
            }
            continue;
        }
        const bool measured = std::any_of(row->against.begin(), row->against.end(),
                                          [](const HeadlineVerdict& v) { return !v.rows.empty(); });
        const double z = measured
                             ? row->value(metrics::metric_with(metrics::MetricRole::Stability).name)
                             : std::nan("");
        if (!row->certified && std::isfinite(z) && z < kLeastStableFrictionalZ) {
            unstable.push_back(row->count);
            z_lo = std::min(z_lo, z);
            z_hi = std::max(z_hi, z);
        }
    }
    if (certified) {
        return "Its packs are certified equilibria (contact forces balance every sphere).";
    }
    if (!partly.empty()) {
        return "Certified equilibria (contact forces balance every sphere): " + partly +
               "; a count with an uncertified pack is not judged.";
    }
    if (unstable.empty()) {
        return "";
    }
    return "Its packs cannot be mechanically stable at N = " + count_list(unstable) +
           ": Z(10⁻³) = " + decimals(z_lo, 2) +
           (z_hi > z_lo + 0.005 ? "–" + decimals(z_hi, 2) : "") +
           " contacts per sphere, below the 4 a rigid frictional packing needs.";
}

/// The mode's time against the pours', saying what is compared: SGMP packs timed by the run
/// that wrote the manifest (reused packs carry no time), DEM pours by their recorded times.
std::string pace(const std::vector<const HeadlineRow*>& rows) {
    for (auto it = rows.rbegin(); it != rows.rend(); ++it) {
        const HeadlineRow& row = **it;
        for (const auto& v : row.against) {
            if (row.seconds && v.reference_seconds && v.speedup) {
                return "Time at N = " + std::to_string(row.count) + ": " +
                       decimals(*row.seconds, *row.seconds < 1.0 ? 2 : 1) + " s a pack (" +
                       std::to_string(row.timed_packs) + " of " + std::to_string(row.packs) +
                       " packs timed in this run), " + decimals(*v.reference_seconds, 0) +
                       " s a pour of " + v.reference +
                       " (the pours' recorded times, from another run and load: a ratio of "
                       "recorded times, not one measurement).";
            }
        }
    }
    const bool untimed = std::any_of(rows.begin(), rows.end(), [](const HeadlineRow* row) {
        return row->packs > 0 && row->timed_packs == 0;
    });
    return untimed ? "Not timed in this run: its packs were made by an earlier run and reused."
                   : "";
}

}  // namespace

void answer_markdown(std::ostringstream& md, const CrossValidation& cv) {
    md << "## The answer\n\n";
    md << "One sentence per SGMP mode: which DEM class it stands in for, at which counts, on "
          "how many of the metrics judged there and with how many seeds; where its packs "
          "cannot be mechanically stable; its time against the pours'.\n\n";
    for (const std::string& mode : cv.candidates) {
        const auto rows = rows_of(cv, mode);
        std::vector<std::string> parts;
        for (const auto& s : cv.stand_ins) {
            if (s.candidate == mode) {
                parts.push_back(relation(s, rows));
            }
        }
        md << "- **" << mode << "**" << (cv.tuned(mode) ? " (tuned)" : "") << ": ";
        for (std::size_t i = 0; i < parts.size(); ++i) {
            md << (i == 0 ? "" : "; ") << parts[i];
        }
        md << (parts.empty() ? "not compared with any class." : ".");
        for (const std::string& more : {stability(rows), pace(rows)}) {
            md << (more.empty() ? "" : " " + more);
        }
        md << "\n";
    }
    md << "\n";
}

}  // namespace sgmp::report
