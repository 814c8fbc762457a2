#include "sgmp/compare/crossval.hpp"

#include "sgmp/compare/hard_sphere_limit.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace sgmp::compare {
namespace {

/// Mean wall seconds of the manifest's packs of `group` at `count` (any role).
std::optional<double> mean_seconds(const std::vector<ManifestEntry>& manifest,
                                   const std::string& group, Role role, std::size_t count) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& entry : manifest) {
        if (entry.role == role && entry.group == group && entry.count == count) {
            if (!entry.seconds) {
                return std::nullopt;
            }
            sum += *entry.seconds;
            ++n;
        }
    }
    if (n == 0) {
        return std::nullopt;
    }
    return sum / static_cast<double>(n);
}

/// The diameter and the mean starting height (the engine's `start_height` key) of the
/// group's packs at the row's count.
void fill_from_packs(HeadlineRow& row, const Group& group) {
    double height_sum = 0.0;
    std::size_t heights = 0;
    for (const auto& pack : group.packs) {
        if (pack.count != row.count) {
            continue;
        }
        row.diameter = pack.diameter;
        for (const auto& [key, value] : pack.provenance) {
            if (key == "start_height") {
                height_sum += std::stod(value);
                ++heights;
            }
        }
    }
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

StandIn stand_in_of(const CrossValidation& cv, const std::string& candidate, std::size_t r) {
    StandIn s;
    s.candidate = candidate;
    s.reference = cv.references[r];
    for (const auto& row : cv.rows) {
        if (row.group != candidate || row.against[r].rows.empty()) {
            continue;
        }
        const auto& v = row.against[r];
        for (const auto& m : v.rows) {
            if (m.verdict == Verdict::Agree) {
                ++s.agree;
            } else if (m.verdict == Verdict::Differ) {
                ++s.differ;
                if (m.ratio && *m.ratio > s.worst_ratio) {
                    s.worst_ratio = *m.ratio;
                    s.worst_metric = m.label;
                    s.worst_count = row.count;
                }
            } else if (m.verdict == Verdict::Inconclusive) {
                ++s.inconclusive;
            }
        }
        if (v.speedup && row.count >= s.speedup_count) {
            s.speedup = v.speedup;
            s.speedup_count = row.count;
        }
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
            return a.differ != b.differ ? a.differ < b.differ : a.agree > b.agree;
        });
        all.insert(all.end(), per.begin(), per.end());
    }
    return all;
}

}  // namespace

const std::vector<std::string>& headline_metrics() {
    static const std::vector<std::string> names{"phi",         "z_mean_tol_1e-3", "z_mean_tol_1e-2",
                                                "split_ratio", "p_z_tol_1e-3",    "g_r"};
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
    std::map<std::string, std::size_t> variant_of;
    std::vector<std::pair<std::string, std::size_t>> stiff_of;  // in manifest order
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
            if (entry.role == Role::Variant) {
                variant_of[entry.group] = it->second;
            } else if (entry.role == Role::Stiff) {
                stiff_of.emplace_back(entry.group, it->second);
            } else {
                (entry.role == Role::Candidate ? candidates : references).push_back(it->second);
            }
        }
        result.paths[it->second].push_back(entry.path);
    }
    if (candidates.empty() || references.empty()) {
        throw std::invalid_argument(
            "the manifest needs at least one candidate and one reference group");
    }
    const auto reference_named = [&](const std::string& group, Role role) {
        const auto ref = role_of.find(group);
        if (ref == role_of.end() || ref->second != Role::Reference) {
            throw std::invalid_argument(std::string(to_string(role)) + " group '" + group +
                                        "' names no reference group of the manifest");
        }
        return index.at({group, Role::Reference});
    };
    for (const auto& [group, v] : variant_of) {
        result.plan.variants[reference_named(group, Role::Variant)] = v;
    }
    for (const auto& [group, s] : stiff_of) {
        const std::size_t r = reference_named(group, Role::Stiff);
        result.plan.variants.emplace(r, s);  // a variant set, where there is one, comes first
        result.stiff.emplace_back(r, s);
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

std::vector<std::string> add_hard_sphere_limits(std::vector<Group>& groups, GroupPlan& plan) {
    std::vector<std::string> notes;
    std::vector<std::size_t> limits;
    for (const auto& [r, s] : plan.stiff) {
        const std::string label = hard_sphere_limit_label(groups.at(r).label);
        Group limit = hard_sphere_limit(groups.at(r), groups.at(s), label, notes);
        if (limit.packs.empty()) {
            continue;
        }
        const std::size_t l = groups.size();
        groups.push_back(std::move(limit));
        plan.labels.push_back(label);
        plan.paths.emplace_back();
        plan.plan.variants[l] = s;
        plan.plan.derived_from[l] = r;
        for (const auto c : plan.candidates) {
            plan.plan.comparisons.emplace_back(c, l);
        }
        limits.push_back(l);
    }
    if (!limits.empty()) {
        plan.plan.class_sets.push_back(limits);
    }
    return notes;
}

CrossValidation cross_validate(const Report& report, const std::vector<ManifestEntry>& manifest,
                               const ThesisTables& thesis) {
    CrossValidation cv;
    cv.candidates = labels_of(manifest, Role::Candidate);
    cv.references = labels_of(manifest, Role::Reference);
    std::map<std::string, std::string> runtime_label;  // a derived reference → its pours' group
    for (const auto& [ci, ri] : report.plan.comparisons) {
        const std::string& label = report.groups.at(ri).label;
        if (std::find(cv.references.begin(), cv.references.end(), label) == cv.references.end()) {
            cv.references.push_back(label);
        }
        const auto source = report.plan.derived_from.find(ri);
        runtime_label[label] = source == report.plan.derived_from.end()
                                   ? label
                                   : report.groups.at(source->second).label;
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
        const auto source = runtime_label.find(c.reference);
        v.reference_seconds =
            mean_seconds(manifest, source == runtime_label.end() ? c.reference : source->second,
                         Role::Reference, c.count);
    }
    cv.counts.assign(counts.begin(), counts.end());
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
            row.seconds = mean_seconds(manifest, label, Role::Candidate, row.count);
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
    return cv;
}

}  // namespace sgmp::compare
