#include "sgmp/compare/report_render.hpp"

#include "html_text.hpp"

#include <cstdio>
#include <sstream>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::compare {

using detail::html_escape;
namespace {

using Json = nlohmann::ordered_json;

/// Six significant digits for people; scripts read the exact values from JSON/CSV.
std::string fixed(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

/// Units in words are appended; "ratio" and "dimensionless" are marked in parentheses.
std::string unit_suffix(const std::string& unit) {
    if (unit == "ratio" || unit == "dimensionless") {
        return " (" + unit + ")";
    }
    return " " + unit;
}

std::string with_unit(double v, const std::string& unit) {
    return fixed(v) + unit_suffix(unit);
}

std::string mean_sd(double mean, double sd, const std::string& unit) {
    return fixed(mean) + " ± " + fixed(sd) + unit_suffix(unit);
}

std::string verdict(bool agree) {
    return agree ? "agree" : "DISAGREE";
}

std::string gr_verdict(const Comparison& c) {
    if (c.reference_packs < 2) {
        return "n/a";
    }
    return verdict(c.gr_agree);
}

std::string title(const Comparison& c) {
    return c.candidate + " vs " + c.reference + ", N = " + std::to_string(c.count);
}

/// Keys of a pack's provenance worth a column in the inputs table.
const std::vector<std::string>& provenance_columns() {
    static const std::vector<std::string> keys{"generator", "version", "arrangement",
                                               "friction",  "seed",    "count"};
    return keys;
}

std::string provenance_value(const PackSummary& p, const std::string& key) {
    for (const auto& [k, v] : p.provenance) {
        if (k == key) {
            return v;
        }
    }
    return "-";
}

std::string summary_line(const Comparison& c) {
    std::vector<std::string> agree;
    std::vector<std::string> disagree;
    for (const auto& row : c.rows) {
        (row.agree ? agree : disagree).push_back(row.name);
    }
    if (c.reference_packs >= 2) {
        (c.gr_agree ? agree : disagree).push_back("g(r)");
    }
    std::string line = "- **" + title(c) + "** (" + std::to_string(c.candidate_packs) + " vs " +
                       std::to_string(c.reference_packs) + " packs): ";
    if (disagree.empty()) {
        line += c.candidate + " agrees with " + c.reference + " on every metric";
    } else {
        line += "disagrees on ";
        for (std::size_t i = 0; i < disagree.size(); ++i) {
            line += (i ? ", " : "") + disagree[i];
        }
        line += "; agrees on " + std::to_string(agree.size()) + " of " +
                std::to_string(agree.size() + disagree.size());
    }
    if (c.reference_packs >= 2) {
        line += " (g(r) distance ratio " + fixed(c.gr_ratio) + ", a ratio)";
    } else {
        line += " (one reference pack: tolerances are the floors, g(r) ratio n/a)";
    }
    return line;
}

}  // namespace

std::vector<std::string> rule_statements() {
    std::vector<std::string> rules{
        "Scalar metric: difference = mean(candidate) - mean(reference); tolerance = max(2 x "
        "sample sd of the reference packs (n - 1), floor of the metric); agree when "
        "|difference| <= tolerance. With one reference pack the tolerance is the floor.",
        "g(r): L2 distance sqrt(sum (g_a - g_b)^2 dr) between the mean curves over bin centres "
        "in [0.8 d, 5 d], divided by the mean L2 distance between pairs of reference packs; "
        "agree when the ratio <= 1 (needs two or more reference packs).",
        "Lengths are in units of the mean diameter d. Coordination Z at tolerance X counts "
        "neighbours with gap |ci - cj| - ri - rj <= X d, over centres in the region.",
    };
    std::string floors = "Tolerance floors:";
    for (const auto& rule : metric_rules()) {
        floors += " " + rule.name + " " + fixed(rule.floor) + unit_suffix(rule.unit) + ";";
    }
    rules.push_back(floors);
    return rules;
}

std::string render_markdown(const Report& report, const ReportContext& context) {
    std::ostringstream md;
    md << "# " << context.title << "\n\n";
    md << "Made by sgmp-compare " << sgmp::version() << ": `" << context.command << "`\n\n";
    md << context.lead_markdown;
    md << (context.lead_markdown.empty() ? "" : "\n") << "## Summary of every comparison\n\n";
    if (report.comparisons.empty()) {
        md << "- No particle count is present on both sides; nothing was compared.\n";
    }
    for (const auto& c : report.comparisons) {
        md << summary_line(c) << "\n";
    }
    for (const auto& note : report.notes) {
        md << "- " << note << "\n";
    }
    md << "\n## Rules\n\n";
    for (const auto& rule : rule_statements()) {
        md << "- " << rule << "\n";
    }
    for (const auto& c : report.comparisons) {
        md << "\n## " << title(c) << "\n\n";
        md << "Reference (sets the tolerance): " << c.reference << ", " << c.reference_packs
           << " packs; candidate: " << c.candidate << ", " << c.candidate_packs << " packs.\n\n";
        md << "| metric | " << c.candidate << " mean ± sd | " << c.reference
           << " mean ± sd | difference | tolerance | verdict |\n";
        md << "| --- | --- | --- | --- | --- | --- |\n";
        for (const auto& row : c.rows) {
            md << "| " << row.name << " | "
               << mean_sd(row.candidate_mean, row.candidate_sd, row.unit) << " | "
               << mean_sd(row.reference_mean, row.reference_sd, row.unit) << " | "
               << with_unit(row.difference, row.unit) << " | " << with_unit(row.tolerance, row.unit)
               << " (" << row.tolerance_rule << ") | " << verdict(row.agree) << " |\n";
        }
        md << "| g(r) distance ratio | " << fixed(c.gr_distance) << " √d (distance) | "
           << (c.reference_packs >= 2 ? fixed(c.gr_replicate_distance) + " √d (replicates)"
                                      : std::string("n/a"))
           << " | " << (c.gr_ratio_defined ? fixed(c.gr_ratio) + " (ratio)" : std::string("n/a"))
           << " | 1 (ratio) | " << gr_verdict(c) << " |\n";
        if (!c.candidate_curves.phi_y_note.empty() || !c.reference_curves.phi_y_note.empty()) {
            md << "\nphi(y): " << c.candidate_curves.phi_y_note << " "
               << c.reference_curves.phi_y_note << "\n";
        }
    }
    md << "\n## Plots\n\n";
    if (context.plots_made) {
        md << "Open index.html (self-contained), or the SVG files:\n\n";
        for (const auto& file : context.plot_files) {
            md << "- [" << file << "](" << file << ")\n";
        }
    } else {
        md << "Plots were skipped: " << context.plots_note << "\n";
    }
    md << "\n## Inputs\n\n";
    md << "| group | file | N | d |";
    for (const auto& key : provenance_columns()) {
        md << " " << key << " |";
    }
    md << "\n| --- | --- | --- | --- |";
    for (std::size_t i = 0; i < provenance_columns().size(); ++i) {
        md << " --- |";
    }
    md << "\n";
    for (const auto& g : report.groups) {
        for (const auto& p : g.packs) {
            md << "| " << g.label << " | " << p.source << " | " << p.count << " | "
               << fixed(p.diameter) << " (length unit) |";
            for (const auto& key : provenance_columns()) {
                md << " " << provenance_value(p, key) << " |";
            }
            md << "\n";
        }
    }
    md << "\nAll provenance keys of every input are in report.json. Parameters: `"
       << context.parameters.dump() << "`\n";
    return md.str();
}

std::string render_csv(const Report& report, const ReportContext& context) {
    std::ostringstream csv;
    csv << "# tool: sgmp-compare " << sgmp::version() << "\n# command: " << context.command << "\n";
    for (const auto& rule : rule_statements()) {
        csv << "# rule: " << rule << "\n";
    }
    csv << "count,candidate,reference,metric,unit,candidate_n,candidate_mean,candidate_sd,"
           "reference_n,reference_mean,reference_sd,difference,tolerance,tolerance_rule,verdict\n";
    for (const auto& c : report.comparisons) {
        const auto prefix = std::to_string(c.count) + "," + c.candidate + "," + c.reference + ",";
        for (const auto& row : c.rows) {
            csv << prefix << row.name << "," << row.unit << "," << c.candidate_packs << ","
                << format_number(row.candidate_mean) << "," << format_number(row.candidate_sd)
                << "," << c.reference_packs << "," << format_number(row.reference_mean) << ","
                << format_number(row.reference_sd) << "," << format_number(row.difference) << ","
                << format_number(row.tolerance) << "," << row.tolerance_rule << ","
                << (row.agree ? "agree" : "disagree") << "\n";
        }
        csv << prefix << "g_r_distance_ratio,ratio," << c.candidate_packs << ","
            << format_number(c.gr_distance) << ",," << c.reference_packs << ","
            << (c.reference_packs >= 2 ? format_number(c.gr_replicate_distance) : "") << ",,"
            << (c.gr_ratio_defined ? format_number(c.gr_ratio) : "") << ",1,ratio <= 1,"
            << (c.reference_packs < 2 ? "n/a" : (c.gr_agree ? "agree" : "disagree")) << "\n";
    }
    return csv.str();
}

Json render_json(const Report& report, const ReportContext& context) {
    Json j;
    j["tool"] = "sgmp-compare";
    j["version"] = sgmp::version();
    j["command"] = context.command;
    j["parameters"] = context.parameters;
    j["rules"] = rule_statements();
    Json floors;
    for (const auto& rule : metric_rules()) {
        floors[rule.name] = Json{{"unit", rule.unit}, {"floor", rule.floor}};
    }
    j["metrics"] = floors;
    j["g_r_range_over_d"] = {kGrCompareFrom, kGrCompareTo};
    Json groups = Json::array();
    for (const auto& g : report.groups) {
        Json packs = Json::array();
        for (const auto& p : g.packs) {
            Json prov = Json::object();
            for (const auto& [k, v] : p.provenance) {
                prov[k] = v;
            }
            Json scalars;
            for (std::size_t m = 0; m < metric_rules().size(); ++m) {
                scalars[metric_rules()[m].name] = p.scalars[m];
            }
            packs.push_back(Json{{"file", p.source},
                                 {"count", p.count},
                                 {"diameter", p.diameter},
                                 {"metrics", scalars},
                                 {"provenance", prov}});
        }
        groups.push_back(Json{{"label", g.label}, {"packs", packs}});
    }
    j["groups"] = groups;
    Json comparisons = Json::array();
    for (const auto& c : report.comparisons) {
        Json rows = Json::array();
        for (const auto& row : c.rows) {
            rows.push_back(Json{{"metric", row.name},
                                {"unit", row.unit},
                                {"candidate_mean", row.candidate_mean},
                                {"candidate_sd", row.candidate_sd},
                                {"reference_mean", row.reference_mean},
                                {"reference_sd", row.reference_sd},
                                {"difference", row.difference},
                                {"tolerance", row.tolerance},
                                {"tolerance_rule", row.tolerance_rule},
                                {"verdict", row.agree ? "agree" : "disagree"}});
        }
        Json gr{{"distance", c.gr_distance},
                {"replicate_distance",
                 c.reference_packs >= 2 ? Json(c.gr_replicate_distance) : Json(nullptr)},
                {"ratio", c.gr_ratio_defined ? Json(c.gr_ratio) : Json(nullptr)},
                {"verdict", c.reference_packs < 2 ? "n/a" : (c.gr_agree ? "agree" : "disagree")}};
        comparisons.push_back(Json{{"count", c.count},
                                   {"candidate", c.candidate},
                                   {"reference", c.reference},
                                   {"candidate_packs", c.candidate_packs},
                                   {"reference_packs", c.reference_packs},
                                   {"disagreements", c.disagreements()},
                                   {"metrics", rows},
                                   {"g_r", gr}});
    }
    j["comparisons"] = comparisons;
    j["notes"] = report.notes;
    j["plots"] = Json{
        {"made", context.plots_made}, {"note", context.plots_note}, {"files", context.plot_files}};
    return j;
}

namespace {

/// The plots section: every SVG inline with its file name as caption.
std::string plots_html(const ReportContext& context, const std::vector<std::string>& svgs) {
    std::ostringstream html;
    html << "<h2>Plots</h2>\n";
    if (!context.plots_made) {
        html << "<p>Plots were skipped: " << html_escape(context.plots_note) << "</p>\n";
        return html.str();
    }
    for (std::size_t i = 0; i < svgs.size(); ++i) {
        html << "<figure>" << svgs[i] << "<figcaption>" << html_escape(context.plot_files[i])
             << "</figcaption></figure>\n";
    }
    return html.str();
}

}  // namespace

std::string render_html(const Report& report, const ReportContext& context,
                        const std::vector<std::string>& svgs) {
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>"
         << html_escape(context.title)
         << "</title>"
            "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
            "table{border-collapse:collapse}td,th{border:1px solid #999;padding:2px 6px}"
            ".DISAGREE{color:#b00;font-weight:bold}</style></head><body>\n";
    html << "<h1>" << html_escape(context.title) << "</h1>\n<p>Made by sgmp-compare "
         << sgmp::version() << ": <code>" << html_escape(context.command) << "</code></p>\n"
         << markdown_to_html(context.lead_markdown)
         << (context.plots_per_count ? plots_html(context, svgs) : std::string())
         << "<h2>Summary of every comparison</h2>\n<ul>\n";
    for (const auto& c : report.comparisons) {
        html << "<li>" << html_escape(summary_line(c).substr(2)) << "</li>\n";
    }
    for (const auto& note : report.notes) {
        html << "<li>" << html_escape(note) << "</li>\n";
    }
    html << "</ul>\n<h2>Rules</h2>\n<ul>\n";
    for (const auto& rule : rule_statements()) {
        html << "<li>" << html_escape(rule) << "</li>\n";
    }
    html << "</ul>\n";
    for (const auto& c : report.comparisons) {
        html << "<h2>" << html_escape(title(c)) << "</h2>\n<table><tr><th>metric</th><th>"
             << html_escape(c.candidate) << " mean ± sd</th><th>" << html_escape(c.reference)
             << " mean ± sd</th><th>difference</th><th>tolerance</th><th>verdict</th></tr>\n";
        for (const auto& row : c.rows) {
            html << "<tr><td>" << row.name << "</td><td>"
                 << html_escape(mean_sd(row.candidate_mean, row.candidate_sd, row.unit))
                 << "</td><td>"
                 << html_escape(mean_sd(row.reference_mean, row.reference_sd, row.unit))
                 << "</td><td>" << html_escape(with_unit(row.difference, row.unit)) << "</td><td>"
                 << html_escape(with_unit(row.tolerance, row.unit)) << " (" << row.tolerance_rule
                 << ")</td><td class=\"" << verdict(row.agree) << "\">" << verdict(row.agree)
                 << "</td></tr>\n";
        }
        html << "<tr><td>g(r) distance ratio</td><td colspan=\"2\">distance "
             << fixed(c.gr_distance) << " √d; replicates "
             << (c.reference_packs >= 2 ? fixed(c.gr_replicate_distance) + " √d" : "n/a")
             << "</td><td>" << (c.gr_ratio_defined ? fixed(c.gr_ratio) + " (ratio)" : "n/a")
             << "</td><td>1 (ratio)</td><td class=\"" << gr_verdict(c) << "\">" << gr_verdict(c)
             << "</td></tr>\n</table>\n";
    }
    if (!context.plots_per_count) {
        html << plots_html(context, svgs);
    }
    html << "<h2>Inputs</h2>\n<table><tr><th>group</th><th>file</th><th>N</th>";
    for (const auto& key : provenance_columns()) {
        html << "<th>" << key << "</th>";
    }
    html << "</tr>\n";
    for (const auto& g : report.groups) {
        for (const auto& p : g.packs) {
            html << "<tr><td>" << html_escape(g.label) << "</td><td>" << html_escape(p.source)
                 << "</td><td>" << p.count << "</td>";
            for (const auto& key : provenance_columns()) {
                html << "<td>" << html_escape(provenance_value(p, key)) << "</td>";
            }
            html << "</tr>\n";
        }
    }
    html << "</table>\n<p>Parameters: <code>" << html_escape(context.parameters.dump())
         << "</code></p>\n</body></html>\n";
    return html.str();
}

}  // namespace sgmp::compare
