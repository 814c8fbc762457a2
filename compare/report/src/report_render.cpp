#include "sgmp/report/report_render.hpp"
#include "sgmp/report/sequential_rows.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "html_text.hpp"
#include "sgmp/metrics/csv_text.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::report {

using metrics::kSchemaVersion;
using metrics::write_csv_preamble;

using detail::html_escape;

namespace {

using Json = nlohmann::ordered_json;

/// Four significant digits for people; scripts read the exact values from JSON/CSV.
std::string fixed(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

std::string mean_sd(const MetricRow& row, double mean, double sd) {
    if (row.kind != MetricKind::Scalar) {
        return "—";
    }
    return fixed(mean) + " ± " + fixed(sd);
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
    std::string line = "- **" + title(c) + "** (" + std::to_string(c.candidate_packs) + " vs " +
                       std::to_string(c.reference_packs) + " packs): ";
    const Verdict order[] = {Verdict::Agree, Verdict::Differ, Verdict::Inconclusive};
    bool first = true;
    for (const Verdict v : order) {
        std::string names;
        for (const auto& row : c.rows) {
            if (row.verdict == v) {
                names += (names.empty() ? "" : ", ") + row.label;
            }
        }
        if (!names.empty()) {
            line += (first ? "" : "; ") + std::string(to_string(v)) + " on " + names;
            first = false;
        }
    }
    return line + ".";
}

std::string finite_text(double v) {
    return std::isfinite(v) ? fixed(v) : "∞";
}

std::string interval_text(const MetricRow& row) {
    if (row.verdict == Verdict::Info && row.tolerance_rule != "margin") {
        return "—";
    }
    return "[" + finite_text(row.ci_low) + ", " + finite_text(row.ci_high) + "]";
}

std::string verdict_text(const MetricRow& row) {
    std::string text(to_string(row.verdict));
    if (row.verdict == Verdict::Info && row.tolerance_rule == "below overlap depth") {
        text += " (below overlap depth)";
    } else if (row.verdict == Verdict::Inconclusive && row.look > 0) {
        text += " (" + sequential_note(row) + ")";
    } else if (row.verdict == Verdict::Inconclusive) {
        text += row.seeds_to_decide ? " (" + std::to_string(*row.seeds_to_decide) + " seeds a side)"
                                    : " (no seed count up to 1000 decides)";
    }
    return text;
}

void comparison_markdown(std::ostringstream& md, const Comparison& c) {
    md << "\n### " << title(c) << "\n\n";
    md << "Reference: " << c.reference << ", " << c.reference_packs
       << " packs; candidate: " << c.candidate << ", " << c.candidate_packs << " packs.\n\n";
    md << "| metric | candidate mean ± sd | reference mean ± sd | difference | 90 % interval | "
          "margin | mdd | verdict |\n";
    md << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
    for (const auto& row : c.rows) {
        md << "| " << row.label
           << (row.unit == "ratio" || row.unit == "dimensionless" ? "" : " (" + row.unit + ")")
           << " | " << mean_sd(row, row.candidate_mean, row.candidate_sd) << " | "
           << mean_sd(row, row.reference_mean, row.reference_sd) << " | " << fixed(row.difference)
           << " | " << interval_text(row) << " | " << fixed(row.margin) << " | "
           << finite_text(row.mdd) << " | " << verdict_text(row) << " |\n";
    }
    if (!c.candidate_curves.phi_y_note.empty() || !c.reference_curves.phi_y_note.empty()) {
        md << "\nφ(y): " << c.candidate_curves.phi_y_note << " " << c.reference_curves.phi_y_note
           << "\n";
    }
}

void inputs_markdown(std::ostringstream& md, const Report& report) {
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
               << fixed(p.diameter) << " |";
            for (const auto& key : provenance_columns()) {
                md << " " << provenance_value(p, key) << " |";
            }
            md << "\n";
        }
    }
}

}  // namespace

nlohmann::ordered_json finite_or_null(double value) {
    return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
}

std::vector<std::string> rule_statements() {
    std::vector<std::string> rules{
        "Verdicts: an equivalence test of each metric on its declared margin m (margins and "
        "their reasons: compare/README.md, Margins). agree: the 90 % confidence interval of "
        "the difference lies inside [-m, m] (two one-sided tests at 5 %); differ: it lies "
        "wholly outside; inconclusive: it straddles a margin (seeds_to_decide: the smallest n "
        "seeds a side, never fewer than either group has, at which the same estimate and sds "
        "would decide it); info: shown without a verdict. Nothing "
        "changes a verdict afterwards; no model spread widens a margin.",
        "Scalar metric: difference = mean(candidate) - mean(reference); pooled Student "
        "standard error s_p sqrt(1/n_a + 1/n_b), s_p^2 = ((n_a - 1) s_a^2 + (n_b - 1) s_b^2) "
        "/ (n_a + n_b - 2), with n_a + n_b - 2 degrees of freedom (Schuirmann's TOST); a "
        "candidate of one pack takes the reference's sd. ratio = "
        "|difference| / m. mdd: the true difference called differ with probability 80 %, "
        "m + (t_0.95 + t_0.80) SE.",
        "Curves: g(r) by the L2 distance sqrt(sum (g_a - g_b)^2 dr) of the mean curves over bin "
        "centres in [1.1 d, 5 d] (the contact peak is judged by Z and P(Z)); for blends "
        "also outside each pair type's contact peak, the bins meeting [0.98, 1.1] x "
        "(D_I + D_J)/2 (each species' Z judges contact there); P(Z) by the "
        "total-variation distance (1/2) sum |p_a - p_b|. `difference` is that distance of the "
        "mean curves, which the noise biases upwards. g(r)'s bounds on the true distance "
        "come from U = D^2 - dr sum v_k (v_k the per-bin variance of the mean difference), "
        "unbiased for its square (Dette et al. 2018): one-sided 95 % bounds from U's "
        "Cornish-Fisher quantiles, with a variance bound for every direction of the "
        "difference and the bins' design effect 1.4, so D may lie above ci_high. P(Z): "
        "distance -/+ q, q the 95 % quantile of the noise's TV norm (normal). "
        "ratio = distance / m.",
        "Contact metrics (Z and P(Z) at gap tolerance delta) are info where the two groups' "
        "overlap depths (mean pair overlap over d, averaged over packs) differ by more than "
        "delta/2: a soft pack's gaps are shifted by its overlaps, so the two count different "
        "things there; info too where a group's depth is not known (batch rows without "
        "overlap_mean).",
        "Relaxed packs (header relax = frictionless or frictional) claim a mechanical "
        "equilibrium and are judged only with certified = true (the engine's equilibrium "
        "certificate); otherwise their comparisons are not judged (info, 'not certified').",
        "Stands in: no test differs under Holm's procedure on the tests' p-values of "
        "|difference| <= m over every judged metric and count (family-wise error <= 5 %), and "
        "at every count a majority of the metrics judged there agree (every judged metric "
        "counts, decided or not). Differs: Holm keeps a "
        "difference. Otherwise undecided. Pairs of reference classes are judged the same way; "
        "classes that stand in for each other are one family.",
        "Candidate rows (crossval): group-sequential. Look k judges the first n_k candidate "
        "packs (manifest order; n_1, n_1 + b, ..., --max-seeds) against the fixed reference at "
        "the level its boundary gives (look, looks, alpha_spent, nominal_alpha): Lan-DeMets "
        "O'Brien-Fleming-type spending of 5 % per one-sided test over the information "
        "fractions t_k = (1/N + 1/n_b)/(1/n_k + 1/n_b); a row keeps the verdict of the first "
        "look that decides, and is inconclusive for good only at the last. An undecided row "
        "names the side that limits it (limited_by: candidate, reference, or both when neither "
        "alone would) and the candidate seeds (seeds_to_decide) or reference pours "
        "(pours_to_decide) that would decide it at the same estimate and scatter. Without "
        "--max-seeds: one look, the fixed-sample test.",
        "Lengths are in units of the mean diameter d. Z at tolerance X counts neighbours with "
        "gap |ci - cj| - ri - rj <= X d, over centres in the region; g(r) bins are centred on "
        "multiples of the bin width (contact at d is a bin centre) and its density is the one "
        "the origins see, so g -> 1 far from contact.",
    };
    std::string margins = "Declared margins:";
    for (const auto& rule : metric_rules()) {
        if (rule.judged) {
            margins += " " + rule.name + " " + format_number(rule.margin) + ";";
        }
    }
    rules.push_back(margins);
    return rules;
}

namespace {

/// The Markdown page; the HTML page draws its own plots section instead of the file list.
std::string markdown_page(const Report& report, const ReportContext& context, bool plot_list) {
    std::ostringstream md;
    md << "# " << context.title << "\n\n";
    md << "Made by sgmp-compare " << sgmp::version() << ": `" << context.command << "`\n\n";
    md << context.lead_markdown;
    md << "\n## Rules\n\n";
    for (const auto& rule : rule_statements()) {
        md << "- " << rule << "\n";
    }
    if (plot_list) {
        md << "\n## Plots\n\n";
    }
    if (!plot_list) {
    } else if (context.plots_made) {
        md << "Open index.html (self-contained), or the SVG files:\n\n";
        for (const auto& file : context.plot_files) {
            md << "- [" << file << "](" << file << ")\n";
        }
    } else {
        md << "Plots were skipped: " << context.plots_note << "\n";
    }
    md << "\n## Every comparison\n\n";
    if (report.comparisons.empty()) {
        md << "- No particle count is present on both sides; nothing was compared.\n";
    }
    for (const auto& c : report.comparisons) {
        md << summary_line(c) << "\n";
    }
    for (const auto& note : report.notes) {
        md << "- " << note << "\n";
    }
    for (const auto& c : report.comparisons) {
        comparison_markdown(md, c);
    }
    inputs_markdown(md, report);
    md << "\nAll provenance keys of every input are in report.json. Parameters: `"
       << context.parameters.dump() << "`\n";
    return md.str();
}

}  // namespace

std::string render_markdown(const Report& report, const ReportContext& context) {
    return markdown_page(report, context, true);
}

namespace {

/// The plots section: the trends against N inline, then the plots of each count (or
/// comparison) in a collapsible block; every SVG inline with its file name as caption.
std::string plots_html(const ReportContext& context, const std::vector<std::string>& svgs) {
    std::ostringstream html;
    html << "<h2>Plots</h2>\n";
    if (!context.plots_made) {
        html << "<p>Plots were skipped: " << html_escape(context.plots_note) << "</p>\n";
        return html.str();
    }
    const auto stem_of = [&](std::size_t i) {
        const std::string& file = context.plot_files[i];
        const std::string name = file.substr(file.find('/') + 1);
        // The count's (or comparison's) group: "N1002" of N1002_gr.svg and N1002_2_gr.svg.
        if (name.rfind("trend_", 0) == 0) {
            return std::string();
        }
        const std::string stem = name.substr(0, name.rfind('_'));
        return stem.rfind('N', 0) == 0 ? stem.substr(0, stem.find('_')) : stem;
    };
    // The last group of plots (the largest count) is shown open; the others collapsed.
    std::string last_group;
    for (std::size_t i = 0; i < svgs.size(); ++i) {
        if (!stem_of(i).empty()) {
            last_group = stem_of(i);
        }
    }
    std::string group;
    bool open = false;
    for (std::size_t i = 0; i < svgs.size(); ++i) {
        const std::string& file = context.plot_files[i];
        const std::string stem = stem_of(i);
        const bool trend = stem.empty();
        if (!trend && stem != group) {
            html << (open ? "</details>\n" : "")
                 << (stem == last_group ? "<details open><summary>" : "<details><summary>")
                 << html_escape(stem) << ": g(r), P(Z), Z(δ), φ(y)</summary>\n";
            group = stem;
            open = true;
        }
        html << "<figure>" << svgs[i] << "<figcaption>" << html_escape(file)
             << "</figcaption></figure>\n";
    }
    html << (open ? "</details>\n" : "");
    return html.str();
}

/// Ids for the page's h2 headings and a table of contents linking them.
std::string with_contents(std::string body) {
    std::ostringstream nav;
    nav << "<nav><b>Contents</b>:";
    std::size_t n = 0;
    for (std::size_t at = body.find("<h2>"); at != std::string::npos;
         at = body.find("<h2>", at + 1)) {
        const std::size_t end = body.find("</h2>", at);
        const std::string title = body.substr(at + 4, end - at - 4);
        const std::string id = "s" + std::to_string(++n);
        body.replace(at, 4, "<h2 id=\"" + id + "\">");
        nav << (n == 1 ? " " : " · ") << "<a href=\"#" << id << "\">" << title << "</a>";
    }
    nav << "</nav>\n";
    const std::size_t first = body.find("<h2");
    body.insert(first == std::string::npos ? 0 : first, nav.str());
    return body;
}

const char* kStyle =
    "<style>body{font-family:sans-serif;max-width:1360px;margin:auto;padding:0 12px;"
    "line-height:1.35}table{border-collapse:collapse;font-size:13px;margin:6px 0}"
    "td:has(> span){white-space:nowrap}td span{letter-spacing:-1.5px;font-size:12px}"
    "code{overflow-wrap:anywhere}td{overflow-wrap:break-word}"
    "td,th{border:1px solid #bbb;padding:2px 4px}th{background:#f2f2f2}"
    "td:has(> .agree:only-child){background:#e6f0fa}"
    ".agree{color:#0072B2;font-weight:bold}.differ{color:#D55E00;font-weight:bold}"
    ".inconclusive{color:#8E4585;font-weight:bold}.info{color:#555;font-style:italic}"
    "span.mark{font-family:monospace;font-size:15px}"
    "figure{display:inline-block;margin:4px}figcaption{font-size:12px;color:#555}"
    "figure svg{width:640px;height:auto}summary{cursor:pointer;margin:4px 0}"
    "td img{width:180px;height:auto;display:block}"
    "nav{background:#f7f7f7;padding:4px 10px;border:1px solid #ddd}</style>";

/// Verdict words and marks in table cells get their colour class.
std::string color_verdicts(std::string html) {
    const std::pair<std::string, std::string> marks[] = {
        {"<td>agree</td>", "<td class=\"agree\">agree</td>"},
        {"<td>differ</td>", "<td class=\"differ\">differ</td>"},
        {"<td>inconclusive</td>", "<td class=\"inconclusive\">inconclusive</td>"},
        {"<td>inconclusive (no power)</td>",
         "<td class=\"inconclusive\">inconclusive (no power)</td>"},
        {"<td>info</td>", "<td class=\"info\">info</td>"},
        {"✓", "<span class=\"agree\">✓</span>"},
        {"✗", "<span class=\"differ\">✗</span>"},
        {"◌", "<span class=\"inconclusive\">◌</span>"},
    };
    for (const auto& [from, to] : marks) {
        std::string out;
        std::size_t start = 0;
        for (std::size_t at = html.find(from); at != std::string::npos;
             at = html.find(from, start)) {
            out.append(html, start, at - start);
            out += to;
            start = at + from.size();
        }
        out.append(html, start, std::string::npos);
        html = std::move(out);
    }
    return html;
}

}  // namespace

std::string render_html(const Report& report, const ReportContext& context,
                        const std::vector<std::string>& svgs) {
    const std::string markdown = markdown_page(report, context, false);
    // The plots go after the lead sections (before "## Rules") when plotted per count.
    std::string body = color_verdicts(markdown_to_html(markdown));
    const std::string plots = plots_html(context, svgs);
    const std::string anchor = "<h2>Rules</h2>";
    const auto at = body.find(anchor);
    if (at != std::string::npos) {
        body.insert(at, plots);
    } else {
        body += plots;
    }
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>"
         << html_escape(context.title) << "</title>" << kStyle << "</head><body>\n"
         << with_contents(body) << "</body></html>\n";
    return html.str();
}

}  // namespace sgmp::report
