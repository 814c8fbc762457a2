#include "sgmp/compare/crossval.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace sgmp::compare {
namespace {

std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string signed_fixed(double value, int decimals) {
    return (value >= 0.0 ? "+" : "") + fixed(value, decimals);
}

const MetricRow& row_named(const Comparison& c, const std::string& name) {
    for (const auto& row : c.rows) {
        if (row.name == name) {
            return row;
        }
    }
    throw std::logic_error("comparison lacks metric " + name);
}

std::string verdict(bool agree) {
    return agree ? "agree" : "DIFFER";
}

/// Mean wall seconds of the manifest's packs of `group` at `count`.
std::optional<double> mean_seconds(const std::vector<ManifestEntry>& manifest,
                                   const std::string& group, std::size_t count) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& entry : manifest) {
        if (entry.role == Role::Candidate && entry.group == group && entry.count == count) {
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

std::string count_list(const std::vector<std::size_t>& counts) {
    std::string text;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        text += (i == 0 ? "" : ", ") + std::to_string(counts[i]);
    }
    return text;
}

/// One sentence on one metric of one candidate/reference pair over all counts.
struct MetricSpread {
    std::vector<std::size_t> agree;
    std::vector<std::size_t> differ;
    double low = 0.0;  // smallest and largest candidate − reference among the differing
    double high = 0.0;

    void add(std::size_t count, bool agrees, double difference) {
        if (agrees) {
            agree.push_back(count);
            return;
        }
        low = differ.empty() ? difference : std::min(low, difference);
        high = differ.empty() ? difference : std::max(high, difference);
        differ.push_back(count);
    }
};

std::string describe(const std::string& metric, const MetricSpread& s, const std::string& unit,
                     int decimals) {
    const std::size_t total = s.agree.size() + s.differ.size();
    std::string text = metric + " agrees at " + std::to_string(s.agree.size()) + " of " +
                       std::to_string(total) + " counts";
    if (!s.differ.empty()) {
        text += "; differs at N = " + count_list(s.differ) + " (SGMP − DEM " +
                (s.low == s.high ? signed_fixed(s.low, decimals)
                                 : "from " + signed_fixed(s.low, decimals) + " to " +
                                       signed_fixed(s.high, decimals)) +
                " " + unit + ")";
    }
    return text;
}

std::string describe_gr(const std::vector<const HeadlineRow*>& rows, std::size_t reference) {
    std::vector<std::size_t> close;
    std::vector<std::size_t> far;
    std::vector<std::size_t> undefined;
    double worst = 0.0;
    for (const auto* row : rows) {
        const auto& v = row->against[reference];
        if (!v.gr_ratio) {
            undefined.push_back(row->count);
        } else if (v.gr_agree) {
            close.push_back(row->count);
        } else {
            far.push_back(row->count);
            worst = std::max(worst, *v.gr_ratio);
        }
    }
    std::string text = "g(r) is as close to DEM as DEM replicates are to each other at " +
                       std::to_string(close.size()) + " of " + std::to_string(rows.size()) +
                       " counts";
    if (!far.empty()) {
        text += "; farther at N = " + count_list(far) + " (distance ratio up to " +
                fixed(worst, 2) + ")";
    }
    if (!undefined.empty()) {
        text += "; undefined at N = " + count_list(undefined) + " (fewer than two DEM seeds)";
    }
    std::vector<double> beyond;
    for (const auto* row : rows) {
        if (const auto& ratio = row->against[reference].gr_beyond_contact_ratio) {
            beyond.push_back(*ratio);
        }
    }
    if (!beyond.empty()) {
        const auto [low, high] = std::minmax_element(beyond.begin(), beyond.end());
        text += "; leaving out the contact peak (r ≥ 1.1·d) the ratio is " +
                (*low == *high ? fixed(*low, 2) : fixed(*low, 2) + "–" + fixed(*high, 2));
    }
    return text;
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

std::string optional_fixed(const std::optional<double>& value, int decimals) {
    return value ? fixed(*value, decimals) : "n/a";
}

}  // namespace

GroupPlan plan_groups(const std::vector<ManifestEntry>& manifest) {
    GroupPlan plan;
    std::map<std::string, std::size_t> index;
    std::map<std::string, Role> role_of;
    std::vector<std::size_t> candidates;
    std::vector<std::size_t> references;
    for (const auto& entry : manifest) {
        const auto [it, fresh] = index.emplace(entry.group, plan.labels.size());
        if (fresh) {
            plan.labels.push_back(entry.group);
            plan.paths.emplace_back();
            role_of[entry.group] = entry.role;
            (entry.role == Role::Candidate ? candidates : references).push_back(it->second);
        } else if (role_of[entry.group] != entry.role) {
            throw std::invalid_argument("group '" + entry.group +
                                        "' is listed both as candidate and as reference");
        }
        plan.paths[it->second].push_back(entry.path);
    }
    if (candidates.empty() || references.empty()) {
        throw std::invalid_argument(
            "the manifest needs at least one candidate and one reference group");
    }
    for (const auto c : candidates) {
        for (const auto r : references) {
            plan.comparisons.emplace_back(c, r);
        }
    }
    return plan;
}

CrossValidation cross_validate(const Report& report, const std::vector<ManifestEntry>& manifest,
                               const ThesisTables& thesis) {
    CrossValidation cv;
    std::set<std::string> seen;
    for (const auto& entry : manifest) {
        if (seen.insert(entry.group).second) {
            (entry.role == Role::Candidate ? cv.candidates : cv.references).push_back(entry.group);
        }
    }
    // (candidate, count) → row, filled from every comparison of that candidate.
    std::map<std::pair<std::string, std::size_t>, HeadlineRow> rows;
    for (const auto& c : report.comparisons) {
        auto& row = rows[{c.candidate, c.count}];
        const auto& phi = row_named(c, kHeadlinePhi);
        const auto& z = row_named(c, kHeadlineZ);
        row.group = c.candidate;
        row.count = c.count;
        row.packs = c.candidate_packs;
        row.phi = phi.candidate_mean;
        row.z = z.candidate_mean;
        row.against.resize(cv.references.size());
        const auto slot = std::find(cv.references.begin(), cv.references.end(), c.reference);
        if (slot == cv.references.end()) {
            throw std::invalid_argument("comparison against '" + c.reference +
                                        "', which is not a reference group of the manifest");
        }
        auto& v = row.against[static_cast<std::size_t>(slot - cv.references.begin())];
        v.reference = c.reference;
        v.phi_reference = phi.reference_mean;
        v.phi_tolerance = phi.tolerance;
        v.phi_agree = phi.agree;
        v.z_reference = z.reference_mean;
        v.z_tolerance = z.tolerance;
        v.z_agree = z.agree;
        if (c.gr_ratio_defined) {
            v.gr_ratio = c.gr_ratio;
        }
        v.gr_agree = c.gr_agree;
        v.gr_beyond_contact_ratio = c.gr_beyond_contact_ratio;
    }
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
            row.seconds = mean_seconds(manifest, label, row.count);
            row.thesis = find_thesis_result(thesis.results, label, row.count);
            row.thesis_start = find_thesis_start(thesis.starts, label, row.count);
            if (row.thesis && row.seconds && *row.seconds > 0.0) {
                row.speedup = row.thesis->runtime_seconds / *row.seconds;
            }
            cv.rows.push_back(row);
        }
    }
    return cv;
}

std::string render_headline_text(const CrossValidation& cv) {
    std::ostringstream out;
    out << "N      arrangement    seconds  phi     Z(1e-2)";
    for (const auto& ref : cv.references) {
        out << " | " << ref << ": phi / Z / g(r) ratio";
    }
    out << "\n";
    for (const auto& row : cv.rows) {
        char head[128];
        std::snprintf(head, sizeof head, "%-6zu %-14s %7s  %.4f  %5.2f  ", row.count,
                      row.group.c_str(), optional_fixed(row.seconds, 3).c_str(), row.phi, row.z);
        out << head;
        for (const auto& v : row.against) {
            char cell[160];
            std::snprintf(cell, sizeof cell, " | %.4f %-6s / %5.2f %-6s / %5s %-6s",
                          v.phi_reference, verdict(v.phi_agree).c_str(), v.z_reference,
                          verdict(v.z_agree).c_str(), optional_fixed(v.gr_ratio, 2).c_str(),
                          verdict(v.gr_agree).c_str());
            out << cell;
        }
        out << "\n";
    }
    return out.str();
}

std::string render_crossval_markdown(const CrossValidation& cv) {
    std::ostringstream md;
    md << "## Where SGMP agrees with DEM\n\n";
    md << "Each line compares one SGMP starting arrangement with one DEM friction class over "
          "all particle counts, on the control volume's packing fraction φ (a ratio), the mean "
          "coordination Z at gap tolerance δ = 10⁻²·d (contacts per particle) and g(r).\n\n";
    for (const auto& candidate : cv.candidates) {
        std::vector<const HeadlineRow*> rows;
        for (const auto& row : cv.rows) {
            if (row.group == candidate) {
                rows.push_back(&row);
            }
        }
        for (std::size_t r = 0; r < cv.references.size(); ++r) {
            MetricSpread phi;
            MetricSpread z;
            for (const auto* row : rows) {
                phi.add(row->count, row->against[r].phi_agree,
                        row->phi - row->against[r].phi_reference);
                z.add(row->count, row->against[r].z_agree, row->z - row->against[r].z_reference);
            }
            md << "- **" << candidate << " vs " << cv.references[r]
               << "**: " << describe("φ", phi, "(ratio)", 4) << ". "
               << describe("Z(δ=10⁻²)", z, "contacts/particle", 2) << ". " << describe_gr(rows, r)
               << ".\n";
        }
    }
    md << "\n## Headline\n\n";
    md << "φ: packing fraction of the control volume (ratio); Z: mean contacts per particle "
          "at δ = 10⁻²; g(r) ratio: L2 distance of the SGMP mean g(r) from the DEM mean on "
          "[0.8·d, 5·d] over the mean distance between DEM replicates (ratio; ≤ 1 agrees). "
          "The ratio on r ≥ 1.1·d leaves out the contact peak, where soft DEM contacts "
          "(overlapping by up to about 1 % of d) and hard SGMP contacts (exactly d apart) fall "
          "into different bins; it is informative and carries no verdict. Seconds: mean wall "
          "time per SGMP pack.\n\n";
    md << "| N | arrangement | SGMP s | SGMP φ | SGMP Z |";
    for (const auto& ref : cv.references) {
        md << " " << ref << " φ | φ verdict | " << ref
           << " Z | Z verdict | g(r) ratio | g(r) verdict | g(r) ratio r ≥ 1.1·d |";
    }
    md << "\n| ---: | --- | ---: | ---: | ---: |";
    for (std::size_t r = 0; r < cv.references.size(); ++r) {
        md << " ---: | --- | ---: | --- | ---: | --- | ---: |";
    }
    md << "\n";
    for (const auto& row : cv.rows) {
        md << "| " << row.count << " | " << row.group << " | " << optional_fixed(row.seconds, 3)
           << " | " << fixed(row.phi, 4) << " | " << fixed(row.z, 2) << " |";
        for (const auto& v : row.against) {
            md << " " << fixed(v.phi_reference, 4) << " | " << verdict(v.phi_agree) << " | "
               << fixed(v.z_reference, 2) << " | " << verdict(v.z_agree) << " | "
               << optional_fixed(v.gr_ratio, 2) << " | " << verdict(v.gr_agree) << " | "
               << optional_fixed(v.gr_beyond_contact_ratio, 2) << " |";
        }
        md << "\n";
    }
    md << "\n## Beside the thesis\n\n";
    md << "The thesis' runtime (s, one core of a 2.0 GHz Core Duo) and control-volume φ "
          "(Tables 5.1, 6.1, 7.1, 8.1) next to ours; speed-up = thesis runtime / our mean "
          "runtime (ratio). d: sphere diameter (length units). Start height: top of the "
          "starting arrangement above the floor (length units; thesis Tables 6.2, 7.2, 8.2, "
          "which give none for the single column). — marks what the thesis does not give.\n\n";
    md << "| N | arrangement | d | thesis s | our s | speed-up | thesis φ | our φ | φ − thesis φ | "
          "thesis start height | our start height |\n"
          "| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    const std::string none = "—";
    for (const auto& row : cv.rows) {
        const auto& t = row.thesis;
        md << "| " << row.count << " | " << row.group << " | " << fixed(row.diameter, 4) << " | "
           << (t ? fixed(t->runtime_seconds, 0) + " (" + t->table + ")" : none) << " | "
           << optional_fixed(row.seconds, 3) << " | "
           << (row.speedup ? fixed(*row.speedup, 0) + "×" : none) << " | "
           << (t ? fixed(t->packing_fraction, 4) : none) << " | " << fixed(row.phi, 4) << " | "
           << (t ? signed_fixed(row.phi - t->packing_fraction, 4) : none) << " | "
           << (row.thesis_start ? fixed(row.thesis_start->starting_height, 2) + " (" +
                                      row.thesis_start->table + ")"
                                : none)
           << " | " << (row.start_height ? fixed(*row.start_height, 2) : none) << " |\n";
    }
    return md.str();
}

std::string render_headline_csv(const CrossValidation& cv) {
    std::ostringstream csv;
    csv << "count,arrangement,reference,sgmp_seconds,sgmp_phi,sgmp_z_1e-2,reference_phi,"
           "phi_tolerance,phi_verdict,reference_z_1e-2,z_tolerance,z_verdict,gr_ratio,gr_verdict,"
           "gr_ratio_beyond_contact,thesis_seconds,thesis_phi,speedup,diameter,start_height,"
           "thesis_start_height\n";
    for (const auto& row : cv.rows) {
        for (const auto& v : row.against) {
            csv << row.count << ',' << row.group << ',' << v.reference << ','
                << (row.seconds ? fixed(*row.seconds, 6) : "") << ',' << fixed(row.phi, 6) << ','
                << fixed(row.z, 6) << ',' << fixed(v.phi_reference, 6) << ','
                << fixed(v.phi_tolerance, 6) << ',' << (v.phi_agree ? "agree" : "differ") << ','
                << fixed(v.z_reference, 6) << ',' << fixed(v.z_tolerance, 6) << ','
                << (v.z_agree ? "agree" : "differ") << ','
                << (v.gr_ratio ? fixed(*v.gr_ratio, 6) : "") << ','
                << (v.gr_ratio ? (v.gr_agree ? "agree" : "differ") : "n/a") << ','
                << (v.gr_beyond_contact_ratio ? fixed(*v.gr_beyond_contact_ratio, 6) : "") << ','
                << (row.thesis ? fixed(row.thesis->runtime_seconds, 0) : "") << ','
                << (row.thesis ? fixed(row.thesis->packing_fraction, 4) : "") << ','
                << (row.speedup ? fixed(*row.speedup, 1) : "") << ',' << fixed(row.diameter, 6)
                << ',' << (row.start_height ? fixed(*row.start_height, 6) : "") << ','
                << (row.thesis_start ? fixed(row.thesis_start->starting_height, 2) : "") << '\n';
        }
    }
    return csv.str();
}

nlohmann::ordered_json crossval_json(const CrossValidation& cv) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& row : cv.rows) {
        nlohmann::ordered_json against = nlohmann::ordered_json::array();
        for (const auto& v : row.against) {
            against.push_back(
                {{"reference", v.reference},
                 {"phi", v.phi_reference},
                 {"phi_tolerance", v.phi_tolerance},
                 {"phi_agree", v.phi_agree},
                 {"z_mean_tol_1e-2", v.z_reference},
                 {"z_tolerance", v.z_tolerance},
                 {"z_agree", v.z_agree},
                 {"gr_ratio",
                  v.gr_ratio ? nlohmann::ordered_json(*v.gr_ratio) : nlohmann::ordered_json()},
                 {"gr_agree", v.gr_agree},
                 {"gr_ratio_beyond_contact",
                  v.gr_beyond_contact_ratio ? nlohmann::ordered_json(*v.gr_beyond_contact_ratio)
                                            : nlohmann::ordered_json()}});
        }
        nlohmann::ordered_json item{{"arrangement", row.group},
                                    {"count", row.count},
                                    {"packs", row.packs},
                                    {"diameter", row.diameter},
                                    {"seconds", row.seconds ? nlohmann::ordered_json(*row.seconds)
                                                            : nlohmann::ordered_json()},
                                    {"phi", row.phi},
                                    {"z_mean_tol_1e-2", row.z},
                                    {"against", against}};
        if (row.thesis) {
            item["thesis"] = {{"table", row.thesis->table},
                              {"runtime_seconds", row.thesis->runtime_seconds},
                              {"phi", row.thesis->packing_fraction}};
            item["speedup"] =
                row.speedup ? nlohmann::ordered_json(*row.speedup) : nlohmann::ordered_json();
        }
        if (row.start_height) {
            item["start_height"] = *row.start_height;
        }
        if (row.thesis_start) {
            item["thesis_start"] = {{"table", row.thesis_start->table},
                                    {"grid", row.thesis_start->grid},
                                    {"starting_height", row.thesis_start->starting_height}};
        }
        rows.push_back(item);
    }
    return {{"candidates", cv.candidates}, {"references", cv.references}, {"headline", rows}};
}

}  // namespace sgmp::compare
