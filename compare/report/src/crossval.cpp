#include "sgmp/report/crossval.hpp"

#include "sgmp/metrics/metric_descriptors.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace sgmp::report {
namespace {

/// Mean wall seconds of the manifest's packs of `group` at `count` (any role) over the rows
/// that give seconds, and how many do: a row without seconds is a pack this run did not time.
struct TimedMean {
    std::optional<double> mean;
    std::size_t timed = 0;
};
TimedMean mean_seconds(const std::vector<ManifestEntry>& manifest, const std::string& group,
                       Role role, std::size_t count) {
    double sum = 0.0;
    TimedMean result;
    for (const auto& entry : manifest) {
        if (entry.role == role && entry.group == group && entry.count == count && entry.seconds) {
            sum += *entry.seconds;
            ++result.timed;
        }
    }
    if (result.timed > 0) {
        result.mean = sum / static_cast<double>(result.timed);
    }
    return result;
}

/// The diameter and the mean starting height (the engine's `start_height` key) of the
/// group's packs at the row's count.
void fill_from_packs(HeadlineRow& row, const Group& group) {
    double height_sum = 0.0;
    std::size_t heights = 0;
    std::size_t packs = 0;
    std::size_t certified = 0;
    for (const auto& pack : group.packs) {
        if (pack.count != row.count) {
            continue;
        }
        ++packs;
        row.diameter = pack.diameter;
        for (const auto& [key, value] : pack.provenance) {
            if (key == "start_height") {
                height_sum += std::stod(value);
                ++heights;
            }
            certified += key == "certified" && value == "true" ? 1 : 0;
            row.with_certificate += key == "certified" ? 1 : 0;
        }
    }
    row.certified = packs > 0 && certified == packs;
    row.certified_packs = certified;
    if (heights > 0) {
        row.start_height = height_sum / static_cast<double>(heights);
    }
}

std::vector<std::string> labels_of(const std::vector<ManifestEntry>& manifest, Role role) {
    std::vector<std::string> labels;
    std::set<std::string> seen;
    for (const auto& entry : manifest) {
        if (entry.role == role && seen.insert(entry.group).second) {
            labels.push_back(entry.group);
        }
    }
    return labels;
}

bool judged(const MetricRow& row) {
    return row.verdict != Verdict::Info;
}

StandIn stand_in_of(const CrossValidation& cv, const std::string& candidate, std::size_t r) {
    std::vector<std::pair<std::size_t, std::vector<MetricRow>>> rows;
    std::optional<double> speedup;
    std::size_t speedup_count = 0;
    std::string invalid;
    for (const auto& row : cv.rows) {
        if (row.group != candidate || row.against[r].rows.empty()) {
            continue;
        }
        if (invalid.empty() && !row.against[r].invalid.empty()) {
            invalid = "N = " + std::to_string(row.count) + ": " + row.against[r].invalid;
        }
        rows.emplace_back(row.count, row.against[r].rows);
        if (row.against[r].speedup && row.count >= speedup_count) {
            speedup = row.against[r].speedup;
            speedup_count = row.count;
        }
    }
    StandIn s = stand_in_from(rows);
    s.candidate = candidate;
    s.reference = cv.references[r];
    s.speedup = speedup;
    s.speedup_count = speedup_count;
    if (!invalid.empty()) {
        s.decision = StandInDecision::Invalid;
        s.invalid = invalid;
    }
    return s;
}

/// Per reference, every candidate's stand-in record, best first (fewest differing verdicts,
/// then most agreeing).
std::vector<StandIn> stand_ins(const CrossValidation& cv) {
    std::vector<StandIn> all;
    for (std::size_t r = 0; r < cv.references.size(); ++r) {
        std::vector<StandIn> per;
        for (const auto& candidate : cv.candidates) {
            per.push_back(stand_in_of(cv, candidate, r));
        }
        std::stable_sort(per.begin(), per.end(), [](const StandIn& a, const StandIn& b) {
            const auto rank = [](const StandIn& x) { return static_cast<int>(x.decision); };
            if (rank(a) != rank(b)) {  // stands in, differs, undecided
                return rank(a) < rank(b);
            }
            return a.differ_familywise != b.differ_familywise
                       ? a.differ_familywise < b.differ_familywise
                       : a.agree > b.agree;
        });
        all.insert(all.end(), per.begin(), per.end());
    }
    return all;
}

std::vector<ClassPair> class_pairs(const Report& report) {
    std::map<std::pair<std::string, std::string>,
             std::vector<std::pair<std::size_t, std::vector<MetricRow>>>>
        by_pair;
    std::vector<std::pair<std::string, std::string>> order;
    for (const auto& c : report.class_comparisons) {
        const auto key = std::pair{c.candidate, c.reference};
        if (by_pair.count(key) == 0) {
            order.push_back(key);
        }
        by_pair[key].emplace_back(c.count, c.rows);
    }
    std::vector<ClassPair> pairs;
    for (const auto& key : order) {
        ClassPair pair{key.first, key.second, stand_in_from(by_pair[key])};
        pair.record.candidate = key.first;
        pair.record.reference = key.second;
        pairs.push_back(pair);
    }
    return pairs;
}

}  // namespace

std::string_view to_string(StandInDecision decision) {
    switch (decision) {
        case StandInDecision::StandsIn:
            return "stands in";
        case StandInDecision::Differs:
            return "differs";
        case StandInDecision::Undecided:
            return "undecided";
        case StandInDecision::Invalid:
            return "invalid";
    }
    return "undecided";
}

std::vector<std::size_t> holm_rejected(const std::vector<double>& p, double alpha) {
    std::vector<std::size_t> order(p.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
    std::vector<std::size_t> rejected;
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (!(p[order[i]] <= alpha / static_cast<double>(order.size() - i))) {
            break;
        }
        rejected.push_back(order[i]);
    }
    return rejected;
}

StandIn stand_in_from(
    const std::vector<std::pair<std::size_t, std::vector<MetricRow>>>& rows_by_count) {
    StandIn s;
    std::vector<double> p;
    std::vector<std::pair<std::size_t, const MetricRow*>> rows;  // (count, row)
    bool every_count_agrees = true;
    for (const auto& [count, metric_rows] : rows_by_count) {
        ++s.counts;
        std::vector<double> p_here;
        std::size_t judged_here = 0;
        std::size_t agree_here = 0;
        for (const auto& m : metric_rows) {
            if (!judged(m)) {
                continue;
            }
            // Every judged metric counts, decided or not: "stands in" needs a majority of
            // what was judged to agree, not of what happened to decide.
            ++judged_here;
            agree_here += m.verdict == Verdict::Agree ? 1 : 0;
            s.agree += m.verdict == Verdict::Agree ? 1 : 0;
            s.differ += m.verdict == Verdict::Differ ? 1 : 0;
            s.inconclusive += m.verdict == Verdict::Inconclusive ? 1 : 0;
            p.push_back(m.p_differ);
            p_here.push_back(m.p_differ);
            rows.emplace_back(count, &m);
        }
        const bool enough =
            judged_here > 0 &&
            static_cast<double>(agree_here) > kStandInAgreeShare * static_cast<double>(judged_here);
        every_count_agrees = every_count_agrees && enough;
        const bool standing = enough && holm_rejected(p_here, kFamilyAlpha).empty();
        s.counts_standing += standing ? 1 : 0;
        s.tallies.push_back({count, agree_here, judged_here, standing});
    }
    const auto rejected = holm_rejected(p, kFamilyAlpha);
    s.differ_familywise = rejected.size();
    const auto consider = [&](std::size_t k) {
        const auto& [count, m] = rows[k];
        if (m->ratio && *m->ratio > s.worst_ratio) {
            s.worst_ratio = *m->ratio;
            s.worst_metric = m->label;
            s.worst_count = count;
        }
    };
    if (!rejected.empty()) {
        for (const std::size_t k : rejected) {
            consider(k);
            const auto& [count, m] = rows[k];
            s.kept.push_back({m->name, m->label, count, m->ratio.value_or(0.0)});
        }
        s.decision = StandInDecision::Differs;
    } else {
        for (std::size_t k = 0; k < rows.size(); ++k) {
            if (rows[k].second->verdict == Verdict::Differ) {
                consider(k);
            }
        }
        s.decision = every_count_agrees && s.counts > 0 ? StandInDecision::StandsIn
                                                        : StandInDecision::Undecided;
    }
    return s;
}

bool CrossValidation::tuned(const std::string& group) const {
    return std::any_of(tuning.begin(), tuning.end(),
                       [&](const TunedParameter& t) { return t.group == group; });
}

const std::vector<std::string>& headline_metrics() {
    static const std::vector<std::string> names =
        metrics::ranked_metric_names(&metrics::MetricDescriptor::headline_rank);
    return names;
}

const MetricRow& HeadlineVerdict::row(const std::string& name) const {
    for (const auto& r : rows) {
        if (r.name == name) {
            return r;
        }
    }
    throw std::logic_error("headline lacks metric " + name);
}

double HeadlineRow::value(const std::string& name) const {
    for (const auto& v : against) {
        if (!v.rows.empty()) {
            return v.row(name).candidate_mean;
        }
    }
    return 0.0;
}

GroupPlan plan_groups(const std::vector<ManifestEntry>& manifest) {
    GroupPlan result;
    std::map<std::pair<std::string, Role>, std::size_t> index;
    std::map<std::string, Role> role_of;
    std::vector<std::size_t> candidates;
    std::vector<std::size_t> references;
    std::vector<std::pair<std::string, Role>> sets_of_references;  // to check their names
    const auto is_set_of_a_reference = [](Role role) {
        return role == Role::Variant || role == Role::Stiff;
    };
    for (const auto& entry : manifest) {
        if (!is_set_of_a_reference(entry.role)) {
            const auto [known, fresh] = role_of.emplace(entry.group, entry.role);
            if (!fresh && known->second != entry.role) {
                throw std::invalid_argument("group '" + entry.group +
                                            "' is listed both as candidate and as reference");
            }
        }
        const auto [it, fresh] =
            index.emplace(std::pair{entry.group, entry.role}, result.labels.size());
        if (fresh) {
            result.labels.push_back(is_set_of_a_reference(entry.role)
                                        ? entry.group + " (" + to_string(entry.role) + ")"
                                        : entry.group);
            result.paths.emplace_back();
            if (is_set_of_a_reference(entry.role)) {
                sets_of_references.emplace_back(entry.group, entry.role);
            }
            (entry.role == Role::Candidate ? candidates : references).push_back(it->second);
        }
        result.paths[it->second].push_back(entry.path);
    }
    for (const auto& [group, role] : sets_of_references) {
        const auto ref = role_of.find(group);
        if (ref == role_of.end() || ref->second != Role::Reference) {
            throw std::invalid_argument(std::string(to_string(role)) + " group '" + group +
                                        "' names no reference group of the manifest");
        }
    }
    if (candidates.empty() || references.empty()) {
        throw std::invalid_argument(
            "the manifest needs at least one candidate and one reference group");
    }
    for (const auto c : candidates) {
        for (const auto r : references) {
            result.plan.comparisons.emplace_back(c, r);
        }
    }
    result.candidates = candidates;
    result.plan.class_sets = {references};
    return result;
}

CrossValidation cross_validate(const Report& report, const std::vector<ManifestEntry>& manifest,
                               const ThesisTables& thesis) {
    CrossValidation cv;
    cv.candidates = labels_of(manifest, Role::Candidate);
    cv.references = labels_of(manifest, Role::Reference);
    for (const auto& [ci, ri] : report.plan.comparisons) {
        const std::string& label = report.groups.at(ri).label;
        if (std::find(cv.references.begin(), cv.references.end(), label) == cv.references.end()) {
            cv.references.push_back(label);
        }
    }
    std::map<std::pair<std::string, std::size_t>, HeadlineRow> rows;
    std::set<std::size_t> counts;
    for (const auto& c : report.comparisons) {
        auto& row = rows[{c.candidate, c.count}];
        row.group = c.candidate;
        row.count = c.count;
        row.packs = c.candidate_packs;
        row.against.resize(cv.references.size());
        counts.insert(c.count);
        const auto slot = std::find(cv.references.begin(), cv.references.end(), c.reference);
        if (slot == cv.references.end()) {
            throw std::invalid_argument("comparison against '" + c.reference +
                                        "', which is not a reference group of the manifest");
        }
        auto& v = row.against[static_cast<std::size_t>(slot - cv.references.begin())];
        v.reference = c.reference;
        v.rows = c.rows;
        v.invalid = c.invalid;
        v.reference_seconds = mean_seconds(manifest, c.reference, Role::Reference, c.count).mean;
    }
    cv.counts.assign(counts.begin(), counts.end());
    cv.dem_parameters = dem_parameter_table(report, cv.references);
    for (const auto& group : report.groups) {
        for (auto& [key, row] : rows) {
            if (key.first == group.label) {
                fill_from_packs(row, group);
            }
        }
    }
    for (const auto& label : cv.candidates) {
        for (auto& [key, row] : rows) {
            if (key.first != label) {
                continue;
            }
            const TimedMean timed = mean_seconds(manifest, label, Role::Candidate, row.count);
            row.seconds = timed.mean;
            row.timed_packs = timed.timed;
            row.thesis = find_thesis_result(thesis.results, label, row.count);
            row.thesis_start = find_thesis_start(thesis.starts, label, row.count);
            if (row.thesis && row.seconds && *row.seconds > 0.0) {
                row.thesis_speedup = row.thesis->runtime_seconds / *row.seconds;
            }
            for (auto& v : row.against) {
                if (v.reference_seconds && row.seconds && *row.seconds > 0.0) {
                    v.speedup = *v.reference_seconds / *row.seconds;
                }
            }
            cv.rows.push_back(row);
        }
    }
    cv.stand_ins = stand_ins(cv);
    cv.class_pairs = class_pairs(report);
    return cv;
}

KeptDifference leading_difference(const StandIn& s) {
    static const std::vector<std::string> leading =
        metrics::ranked_metric_names(&metrics::MetricDescriptor::leading_rank);
    for (const std::string& metric : leading) {
        const KeptDifference* best = nullptr;
        for (const KeptDifference& d : s.kept) {
            if (d.metric == metric && (best == nullptr || d.ratio > best->ratio)) {
                best = &d;
            }
        }
        if (best != nullptr) {
            return *best;
        }
    }
    return {"", s.worst_metric, s.worst_count, s.worst_ratio};
}

}  // namespace sgmp::report
