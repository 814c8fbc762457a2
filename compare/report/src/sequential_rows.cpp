#include "sgmp/report/sequential_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "equivalence_detail.hpp"
#include "sgmp/report/species_rows.hpp"

namespace sgmp::report {
namespace {

using Packs = std::vector<const PackSummary*>;

/// The one-sided level of `rule`'s test at a look: scalars the Student boundary's, curves
/// the normal one's (group_sequential.hpp).
double level_of(const MetricRule& rule, const Look& look) {
    return rule.kind == MetricKind::Scalar ? look.student_alpha : look.nominal_alpha;
}

bool decided(Verdict v) {
    return v == Verdict::Agree || v == Verdict::Differ;
}

/// The rules of every row the comparison can hold, by name.
std::map<std::string, MetricRule> rules_by_name(const Packs& a, const Packs& b) {
    std::map<std::string, MetricRule> rules;
    for (const auto& r : metric_rules()) {
        rules.emplace(r.name, r);
    }
    for (const auto& r : species_rules(a, b)) {
        rules.emplace(r.name, r);
    }
    return rules;
}

/// The smallest n in (from, kMostProjected] with decides(n); none when kMostProjected
/// does not decide.
template <class F>
std::optional<std::size_t> smallest_deciding(std::size_t from, const F& decides) {
    return detail::smallest_deciding(from + 1, kMostProjected, decides);
}

/// Names the side that limits an undecided row (sequential_rows.hpp) at look `taken`.
void name_limit(MetricRow& row, const MetricRule& rule, const Packs& a, const Packs& b,
                const std::vector<Look>& looks, std::size_t taken) {
    row.seeds_to_decide.reset();
    row.pours_to_decide.reset();
    for (std::size_t k = taken + 1; k < looks.size(); ++k) {
        if (decides_with(rule, a, b, level_of(rule, looks[k]), looks[k].candidate_n, b.size())) {
            row.limited_by = "candidate";
            row.seeds_to_decide = looks[k].candidate_n;
            return;
        }
    }
    const Look& last = looks.back();
    const auto pours = smallest_deciding(b.size(), [&](std::size_t n) {
        return decides_with(rule, a, b, level_of(rule, last), last.candidate_n, n);
    });
    if (pours) {
        row.limited_by = "reference";
        row.pours_to_decide = pours;
        return;
    }
    const auto seeds = smallest_deciding(last.candidate_n, [&](std::size_t n) {
        return decides_with(rule, a, b, level_of(rule, last), n, b.size());
    });
    if (seeds) {
        row.limited_by = "candidate";
        row.seeds_to_decide = seeds;
        return;
    }
    // Neither side alone: both grown in the proportion they have now.
    const double ratio = double(b.size()) / double(last.candidate_n);
    const auto pours_for = [&](std::size_t n) {
        return std::max(b.size(), static_cast<std::size_t>(std::ceil(ratio * double(n))));
    };
    const auto both = smallest_deciding(last.candidate_n, [&](std::size_t n) {
        return decides_with(rule, a, b, level_of(rule, last), n, pours_for(n));
    });
    if (both) {
        row.limited_by = "both";
        row.seeds_to_decide = both;
        row.pours_to_decide = pours_for(*both);
    }
}

/// One row judged look by look; `rule` its rule.
MetricRow judge_looks(const MetricRule& rule, const Packs& a, const Packs& b,
                      const std::vector<Look>& looks) {
    MetricRow row;
    std::size_t taken = 0;
    for (std::size_t k = 0; k < looks.size() && looks[k].candidate_n <= a.size(); ++k) {
        const Packs prefix(a.begin(),
                           a.begin() + static_cast<std::ptrdiff_t>(looks[k].candidate_n));
        MetricRow at = judge(rule, prefix, b, level_of(rule, looks[k]));
        if (at.verdict == Verdict::Info) {  // not judged at this look's packs
            at.verdict = Verdict::Inconclusive;
        }
        row = std::move(at);
        taken = k;
        if (decided(row.verdict)) {
            break;
        }
    }
    row.look = taken + 1;
    row.looks = looks.size();
    row.candidate_n = looks[taken].candidate_n;
    row.alpha_spent = looks[taken].alpha_spent;
    row.nominal_alpha = level_of(rule, looks[taken]);
    if (!decided(row.verdict)) {
        name_limit(row, rule, a, b, looks, taken);
    }
    return row;
}

}  // namespace

void judge_sequentially(Comparison& comparison, const Packs& candidate, const Packs& reference,
                        const SequentialDesign& design, BoundaryCache& cache) {
    if (!comparison.invalid.empty() || candidate.empty() || reference.empty()) {
        return;
    }
    const auto schedule = look_schedule(design, candidate.size());
    const auto looks = cache.get(schedule, reference.size(), design.alpha);
    const auto rules = rules_by_name(candidate, reference);
    for (auto& row : comparison.rows) {
        const auto rule = rules.find(row.name);
        if (row.verdict == Verdict::Info || row.tolerance_rule != "margin" || rule == rules.end()) {
            continue;
        }
        row = judge_looks(rule->second, candidate, reference, looks);
    }
}

std::vector<SeedsNeeded> seeds_needed(const Report& report, const SequentialDesign& design) {
    std::vector<SeedsNeeded> needed;
    for (const auto& c : report.comparisons) {
        std::size_t rows = 0;
        for (const auto& row : c.rows) {
            // Every undecided row before the last look: its estimate moves as seeds come,
            // so even a row the projection calls reference-limited may still decide.
            const bool open =
                row.look > 0 && row.verdict == Verdict::Inconclusive && row.look < row.looks;
            rows += open ? 1 : 0;
        }
        if (rows == 0) {
            continue;
        }
        const auto schedule = look_schedule(design, c.candidate_packs);
        const auto next = std::upper_bound(schedule.begin(), schedule.end(), c.candidate_packs);
        if (next == schedule.end()) {
            continue;
        }
        const auto same = std::find_if(needed.begin(), needed.end(), [&](const SeedsNeeded& s) {
            return s.group == c.candidate && s.count == c.count;
        });
        if (same != needed.end()) {
            same->rows += rows;
        } else {
            needed.push_back({c.candidate, c.count, c.candidate_packs, *next, rows});
        }
    }
    return needed;
}

std::string render_seeds_needed_csv(const std::vector<SeedsNeeded>& needed) {
    const auto field = [](const std::string& text) {
        if (text.find_first_of(",\"") == std::string::npos) {
            return text;
        }
        std::string quoted = "\"";
        for (const char ch : text) {
            quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        }
        return quoted + "\"";
    };
    std::ostringstream csv;
    csv << "mode,count,seeds_now,seeds_next,rows\n";
    for (const auto& s : needed) {
        csv << field(s.group) << ',' << s.count << ',' << s.seeds_now << ',' << s.seeds_next << ','
            << s.rows << '\n';
    }
    return csv.str();
}

std::string sequential_note(const MetricRow& row) {
    std::string text = "look " + std::to_string(row.look) + " of " + std::to_string(row.looks) +
                       " at " + std::to_string(row.candidate_n) + " seeds; ";
    if (row.limited_by == "candidate" && row.seeds_to_decide) {
        return text + "limited by the candidate: " + std::to_string(*row.seeds_to_decide) +
               " seeds decide";
    }
    if (row.limited_by == "reference" && row.pours_to_decide) {
        return text + "limited by the reference: " + std::to_string(*row.pours_to_decide) +
               " pours decide";
    }
    if (row.limited_by == "both" && row.seeds_to_decide && row.pours_to_decide) {
        return text + "limited by both sides: " + std::to_string(*row.seeds_to_decide) +
               " seeds and " + std::to_string(*row.pours_to_decide) + " pours decide";
    }
    return text + "no depth up to " + std::to_string(kMostProjected) +
           " seeds decides (the estimate on the margin)";
}

std::string sequential_csv_fields(const MetricRow& row) {
    if (row.look == 0) {
        return ",,,,,";
    }
    std::ostringstream out;
    out.precision(6);
    out << row.look << ',' << row.looks << ',' << row.alpha_spent << ',' << row.nominal_alpha << ','
        << row.limited_by << ','
        << (row.pours_to_decide ? std::to_string(*row.pours_to_decide) : "");
    return out.str();
}

}  // namespace sgmp::report
