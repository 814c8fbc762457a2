#include "sgmp/report/crossval_render.hpp"

#include "crossval_answer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "crossval_views.hpp"
#include "matrix_table.hpp"
#include "sgmp/metrics/csv_text.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/report/report_render.hpp"
#include "sgmp/report/species_matrix.hpp"

namespace sgmp::report {

using metrics::kSchemaVersion;
using metrics::write_csv_preamble;
namespace {

using detail::headline_scalars;
using Json = nlohmann::ordered_json;

std::string fixed(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string sig(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
    return buffer;
}

std::string optional_fixed(const std::optional<double>& value, int decimals) {
    return value ? fixed(*value, decimals) : "—";
}

std::string speed(const std::optional<double>& factor) {
    if (!factor) {
        return "—";
    }
    return *factor >= 100.0 ? fixed(*factor, 0) + "×" : sig(*factor) + "×";
}

/// "k× faster than" or, below 1, "1/k× slower than": a reader compares times that way.
std::string pace_against_pour(const std::optional<double>& speedup) {
    if (speedup && *speedup > 0.0 && *speedup < 1.0) {
        return speed(1.0 / *speedup) + " slower than";
    }
    return speed(speedup) + " faster than";
}

/// One line of a stand-in record: the answer and its strength.
std::string stand_in_sentence(const StandIn& s) {
    const std::size_t judged = s.agree + s.differ + s.inconclusive;
    std::ostringstream out;
    if (s.tallies.empty()) {
        return "not compared (no count has packs of both)";
    }
    if (s.decision == StandInDecision::Invalid) {
        out << "invalid, not judged: " << s.invalid;
        return out.str();
    }
    if (s.decision == StandInDecision::Differs) {
        // φ, Z and g(r) lead; the largest difference follows when it is another.
        const KeptDifference d = leading_difference(s);
        out << "differs on " << d.label << " at N = " << d.count << " by " << sig(d.ratio)
            << "× its margin (" << s.differ_familywise << " of " << judged
            << " tests differ family-wise";
        if (d.label != s.worst_metric || d.count != s.worst_count) {
            out << "; largest " << s.worst_metric << " at N = " << s.worst_count << ", "
                << sig(s.worst_ratio) << "×";
        }
        out << ")";
    } else {
        out << to_string(s.decision) << ": agrees on " << s.agree << " of " << judged
            << " metric × count tests within the declared margins, none differs family-wise";
        if (s.differ > 0) {
            out << " (" << s.differ << " single-test difference" << (s.differ > 1 ? "s" : "")
                << ", largest " << s.worst_metric << " at N = " << s.worst_count << ", "
                << sig(s.worst_ratio) << "× its margin)";
        }
    }
    out << "; stands in at " << s.counts_standing << " of " << s.counts << " counts";
    return out.str();
}

void tuning_markdown(std::ostringstream& md, const CrossValidation& cv) {
    md << "## Tuned parameters\n\n";
    if (cv.tuning.empty()) {
        md << "No mode's parameter is declared tuned against the reference packs "
              "(crossval --tuning).\n\n";
        return;
    }
    md << "These parameters were chosen by comparing the mode with reference packs; the "
          "comparisons on those packs are shown but not judged (info), so every verdict "
          "rests on packs the tuning did not use.\n\n";
    for (const auto& t : cv.tuning) {
        md << "- **" << t.group << "** (tuned): " << t.parameter << " = " << t.value
           << ", tuned against " << t.reference << " at N = " << t.count << " (seeds";
        for (const auto s : t.seeds) {
            md << " " << s;
        }
        md << ")" << (t.note.empty() ? "" : "; " + t.note) << ".\n";
    }
    md << "\n";
}

/// The DEM parameters of the reference classes, one column per class.
void dem_parameters_markdown(std::ostringstream& md, const CrossValidation& cv) {
    const DemParameterTable& t = cv.dem_parameters;
    if (t.classes.empty()) {
        return;
    }
    md << "## DEM parameters of the reference classes\n\n";
    md << "As the LIGGGHTS pours record them in their headers (keys with their SI unit; "
          "reference/README.md explains each). A class whose pours differ lists their values."
          "\n\n| parameter |";
    for (const auto& c : t.classes) {
        md << " " << c << " |";
    }
    md << "\n| --- |";
    for (std::size_t i = 0; i < t.classes.size(); ++i) {
        md << " --- |";
    }
    md << "\n";
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        md << "| `" << t.keys[k] << "` |";
        for (const auto& v : t.values[k]) {
            std::string cell;
            for (const char ch : v) {
                cell += ch == '|' ? std::string("\\|") : std::string(1, ch);
            }
            md << " " << cell << " |";
        }
        md << "\n";
    }
    md << "\n";
}

void stand_in_markdown(std::ostringstream& md, const CrossValidation& cv) {
    md << "## Which SGMP mode stands in for which DEM class\n\n";
    md << "Every verdict is an equivalence test on a declared margin (rules at the end of the "
          "page). A mode *stands in* for a class when no test differs under Holm's procedure "
          "over every judged metric and count (family-wise error ≤ 5 %) and at every count a "
          "majority of the metrics judged there agree (decided or not); it *differs* when Holm "
          "keeps a difference; "
          "otherwise it is *undecided*. A relaxed mode whose packs are not certified "
          "mechanical equilibria is *invalid* and not judged. Speed: the DEM pour's mean wall time "
          "over the mode's at the largest count — the pours' recorded times, from another run "
          "and machine load, against the packs timed in this run: a ratio of recorded times, "
          "not one measurement.\n\n";
    for (std::size_t r = 0; r < cv.references.size(); ++r) {
        std::vector<const StandIn*> per;
        for (const auto& s : cv.stand_ins) {
            if (s.reference == cv.references[r]) {
                per.push_back(&s);
            }
        }
        if (per.empty()) {
            continue;
        }
        md << "- **" << cv.references[r] << "**:";
        for (const StandIn* s : per) {
            md << "\n  - **" << s->candidate << "**" << (cv.tuned(s->candidate) ? " (tuned)" : "")
               << " " << stand_in_sentence(*s);
            if (s->speedup_count > 0) {
                md << "; " << pace_against_pour(s->speedup)
                   << " the DEM pour at N = " << s->speedup_count;
            }
            md << ".";
        }
        md << "\n";
    }
    if (!cv.class_pairs.empty()) {
        md << "\n### The DEM classes against each other\n\n";
        md << "Each pair of classes judged by the same rule, the first as candidate. Classes "
              "that stand in for each other are one family: their physics is not told apart "
              "at these margins.\n\n";
        for (const auto& pair : cv.class_pairs) {
            md << "- **" << pair.a << "** against **" << pair.b
               << "**: " << (pair.one_family() ? "one family; " : "")
               << stand_in_sentence(pair.record) << ".\n";
        }
    }
}

/// The verdict of one metric of `candidate` against reference `reference` at count `n`
/// (Info when the pair was not compared there).
Verdict verdict_at(const CrossValidation& cv, const std::string& candidate, std::size_t reference,
                   std::size_t n, const std::string& metric) {
    for (const auto& row : cv.rows) {
        if (row.group == candidate && row.count == n && !row.against[reference].rows.empty()) {
            return row.against[reference].row(metric).verdict;
        }
    }
    return Verdict::Info;
}

/// Whether `candidate` was compared with reference `reference` at count `n`.
bool compared_at(const CrossValidation& cv, const std::string& candidate, std::size_t reference,
                 std::size_t n) {
    return std::any_of(cv.rows.begin(), cv.rows.end(), [&](const HeadlineRow& row) {
        return row.group == candidate && row.count == n && !row.against[reference].rows.empty();
    });
}

/// Tally of verdicts over some metrics (and counts).
struct Tally {
    std::size_t agree = 0;
    std::size_t differ = 0;
    std::size_t inconclusive = 0;
    [[nodiscard]] std::size_t judged() const { return agree + differ + inconclusive; }
    void add(Verdict v) {
        agree += v == Verdict::Agree ? 1 : 0;
        differ += v == Verdict::Differ ? 1 : 0;
        inconclusive += v == Verdict::Inconclusive ? 1 : 0;
    }
    /// "k ✓ d ✗ i ◌" (the zero ones left out, "0 ✓" kept), or "·" when none was judged:
    /// short enough for eight counts and the total in 1400 px.
    [[nodiscard]] std::string text() const {
        if (judged() == 0) {
            return "·";
        }
        std::string s = std::to_string(agree) + "\u00a0✓";
        if (differ > 0) {
            s += " " + std::to_string(differ) + "\u00a0✗";
        }
        if (inconclusive > 0) {
            s += " " + std::to_string(inconclusive) + "\u00a0◌";
        }
        return s;
    }
};

std::vector<const MetricRule*> judged_rules() {
    std::vector<const MetricRule*> judged;
    for (const auto& rule : metric_rules()) {
        if (rule.judged) {
            judged.push_back(&rule);
        }
    }
    return judged;
}

/// Per mode and class, per count: how many judged metrics agree, differ, stay undecided.
void summary_markdown(std::ostringstream& md, const CrossValidation& cv,
                      const std::vector<const MetricRule*>& judged) {
    md << "\n## Verdicts per count\n\n";
    md << "Per SGMP mode and DEM class: of the metrics judged at each particle count, how "
          "many agree (✓), differ (✗) or stay inconclusive (◌); the last column adds up every "
          "count. The metric by metric marks are in the verdict matrix below.\n\n";
    md << "| SGMP mode | DEM class |";
    for (const std::size_t n : cv.counts) {
        md << " N = " << n << " |";
    }
    md << " all counts |\n| --- | --- |";
    for (std::size_t i = 0; i <= cv.counts.size(); ++i) {
        md << " --- |";
    }
    md << "\n";
    for (const auto& candidate : cv.candidates) {
        for (std::size_t r = 0; r < cv.references.size(); ++r) {
            md << "| " << candidate << " | " << cv.references[r] << " |";
            Tally all;
            for (const std::size_t n : cv.counts) {
                Tally at;
                for (const auto* rule : judged) {
                    const Verdict v = verdict_at(cv, candidate, r, n, rule->name);
                    at.add(v);
                    all.add(v);
                }
                md << " " << at.text() << " |";
            }
            md << " **" << all.text() << "** |\n";
        }
    }
}

void matrix_markdown(std::ostringstream& md, const CrossValidation& cv) {
    const auto judged = judged_rules();
    summary_markdown(md, cv, judged);
    md << "\n## Verdict matrix\n\n";
    md << "One row per SGMP mode and DEM class compared at that count, under a header row "
          "per particle count: ✓ "
          "agree, ✗ differ, ◌ inconclusive (the interval straddles the margin), · not compared "
          "or information only (a contact metric below the overlap depth). Columns: φ of the "
          "control volume; Z at gap tolerance δ; the split ratio g(√3·d)/g(2·d); the Voronoi "
          "local φ, mean and sd; Q6 global and local; g(r) beyond contact; P(Z) at δ; and how "
          "many of the judged metrics agree. Rules at the end of the page.\n\n";
    std::vector<std::string> labels;
    for (const auto* rule : judged) {
        labels.emplace_back(rule->short_label);
    }
    detail::matrix_header(md, labels);
    for (const std::size_t n : cv.counts) {
        detail::count_header_row(md, n, judged.size());
        for (const auto& candidate : cv.candidates) {
            for (std::size_t r = 0; r < cv.references.size(); ++r) {
                if (!compared_at(cv, candidate, r, n)) {
                    continue;  // no pours of that class at this count
                }
                md << "| " << candidate << " | " << cv.references[r] << " |";
                Tally at;
                for (const auto* rule : judged) {
                    const Verdict v = verdict_at(cv, candidate, r, n, rule->name);
                    at.add(v);
                    md << " " << verdict_mark(v) << " |";
                }
                md << " " << detail::agree_cell(at.agree, at.judged()) << " |\n";
            }
        }
    }
}

void headline_markdown(std::ostringstream& md, const CrossValidation& cv) {
    md << "\n## Headline\n\n";
    md << "SGMP means over seeds; against each DEM class the marks of φ, Z(δ = 10⁻³), "
          "Z(δ = 10⁻²), split ratio, P(Z) at δ = 10⁻³ and g(r) (in that order), the g(r) "
          "ratio (distance over its margin) and the speed-up over the DEM pour. Seconds: mean wall "
          "time per SGMP pack, of the packs timed by the run that wrote the manifest (a reused "
          "pack carries no time); the speed-up sets it against the pours' recorded wall times, "
          "from other runs and loads.\n\n";
    md << "| N | SGMP mode | s | φ | Z(10⁻³) | Z(10⁻²) | split |";
    for (const auto& ref : cv.references) {
        md << " " << ref << ": marks | g(r) ratio | speed-up |";
    }
    md << "\n| ---: | --- | ---: | ---: | ---: | ---: | ---: |";
    for (std::size_t r = 0; r < cv.references.size(); ++r) {
        md << " --- | ---: | ---: |";
    }
    md << "\n";
    for (const auto& row : cv.rows) {
        md << "| " << row.count << " | " << row.group << " | " << optional_fixed(row.seconds, 3);
        for (const metrics::MetricDescriptor* d : headline_scalars()) {
            md << " | " << fixed(row.value(d->name), d->digits);
        }
        md << " |";
        for (const auto& v : row.against) {
            if (v.rows.empty()) {
                md << " · | — | — |";
                continue;
            }
            std::string text;
            for (const auto& name : headline_metrics()) {
                text += verdict_mark(v.row(name).verdict);
            }
            const auto& gr = v.row(metrics::metric_with(metrics::MetricRole::PairCorrelation).name);
            md << " " << text << " | " << (gr.ratio ? sig(*gr.ratio) : "—") << " | "
               << speed(v.speedup) << " |";
        }
        md << "\n";
    }
}

void thesis_markdown(std::ostringstream& md, const CrossValidation& cv) {
    md << "\n## Beside the thesis\n\n";
    md << "The thesis' runtime (s, one core of a 2.0 GHz Core Duo) and control-volume φ "
          "(Tables 5.1, 6.1, 7.1, 8.1) next to ours; speed-up = thesis runtime / our mean "
          "runtime. d: sphere diameter (length units). Start height: top of the starting "
          "arrangement above the floor (length units; thesis Tables 6.2, 7.2, 8.2, which give "
          "none for the single column). — marks what the thesis does not give.\n\n";
    md << "| N | SGMP mode | d | thesis s | our s | speed-up | thesis φ | our φ | φ − thesis φ | "
          "thesis start height | our start height |\n"
          "| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    const std::string none = "—";
    for (const auto& row : cv.rows) {
        const auto& t = row.thesis;
        const double phi =
            row.value(metrics::metric_with(metrics::MetricRole::PackingFraction).name);
        md << "| " << row.count << " | " << row.group << " | " << fixed(row.diameter, 4) << " | "
           << (t ? fixed(t->runtime_seconds, 0) + " (" + t->table + ")" : none) << " | "
           << optional_fixed(row.seconds, 3) << " | " << speed(row.thesis_speedup) << " | "
           << (t ? fixed(t->packing_fraction, 4) : none) << " | " << fixed(phi, 4) << " | "
           << (t ? (phi >= t->packing_fraction ? "+" : "") + fixed(phi - t->packing_fraction, 4)
                 : none)
           << " | "
           << (row.thesis_start ? fixed(row.thesis_start->starting_height, 2) + " (" +
                                      row.thesis_start->table + ")"
                                : none)
           << " | " << optional_fixed(row.start_height, 2) << " |\n";
    }
}

}  // namespace

std::string_view verdict_mark(Verdict verdict) {
    switch (verdict) {
        case Verdict::Agree:
            return "✓";
        case Verdict::Differ:
            return "✗";
        case Verdict::Inconclusive:
            return "◌";
        case Verdict::Info:
            return "·";
    }
    return "·";
}

std::string render_headline_text(const CrossValidation& cv) {
    // At most 120 columns: the mode's values, then each reference's six marks under a
    // number; references beyond what one line holds go to a further block. The g(r) ratios
    // and speed-ups are in headline.csv and the report.
    constexpr std::size_t kReferencesPerBlock = 6;  // 63 + 6 · 9 = 117 columns
    std::ostringstream out;
    out << "marks: phi, Z(1e-3), Z(1e-2), split ratio, P(Z) at 1e-3, g(r); "
           "✓ agree, ✗ differ, ◌ inconclusive, · info\n";
    std::string legend = "references:";
    std::size_t width = legend.size();
    for (std::size_t r = 0; r < cv.references.size(); ++r) {
        const std::string item = " [" + std::to_string(r + 1) + "] " + cv.references[r];
        if (width + item.size() > 120) {  // wrap the legend, indented
            legend += "\n          ";
            width = 10;
        }
        legend += item;
        width += item.size();
    }
    out << legend << "\n";
    for (std::size_t first = 0; first < cv.references.size() || first == 0;
         first += kReferencesPerBlock) {
        const std::size_t last = std::min(cv.references.size(), first + kReferencesPerBlock);
        out << (first > 0 ? "\n" : "")
            << "N      SGMP mode          seconds  phi     Z(1e-3) Z(1e-2) split";
        for (std::size_t r = first; r < last; ++r) {
            const std::string number = "[" + std::to_string(r + 1) + "]";
            out << " | " << number << std::string(number.size() < 6 ? 6 - number.size() : 0, ' ');
        }
        out << "\n";
        for (const auto& row : cv.rows) {
            char head[192];
            // The four headline scalars (headline_scalars()), in a fixed text layout.
            const auto& h = headline_scalars();
            std::snprintf(head, sizeof head, "%-6zu %-18.18s %7s  %.4f  %5.2f   %5.2f  %5.3f",
                          row.count, row.group.c_str(), optional_fixed(row.seconds, 3).c_str(),
                          row.value(h.at(0)->name), row.value(h.at(1)->name),
                          row.value(h.at(2)->name), row.value(h.at(3)->name));
            out << head;
            for (std::size_t r = first; r < last && r < row.against.size(); ++r) {
                const auto& v = row.against[r];
                std::string text;
                for (const auto& name : headline_metrics()) {
                    text += v.rows.empty() ? std::string("-")
                                           : std::string(verdict_mark(v.row(name).verdict));
                }
                out << " | " << text;
            }
            out << "\n";
        }
        if (cv.references.empty()) {
            break;
        }
    }
    return out.str();
}

std::string render_crossval_markdown(const CrossValidation& cv) {
    std::ostringstream md;
    answer_markdown(md, cv);
    stand_in_markdown(md, cv);
    tuning_markdown(md, cv);
    dem_parameters_markdown(md, cv);
    matrix_markdown(md, cv);
    species_matrix_markdown(md, cv);
    headline_markdown(md, cv);
    thesis_markdown(md, cv);
    return md.str();
}

namespace detail {

/// The headline's scalar metrics, in headline order: the value columns of its tables.
const std::vector<const metrics::MetricDescriptor*>& headline_scalars() {
    static const std::vector<const metrics::MetricDescriptor*> scalars = [] {
        std::vector<const metrics::MetricDescriptor*> h;
        for (const auto* d : metrics::ranked_metrics(&metrics::MetricDescriptor::headline_rank)) {
            if (d->kind == metrics::MetricKind::Scalar) {
                h.push_back(d);
            }
        }
        return h;
    }();
    return scalars;
}

}  // namespace detail

}  // namespace sgmp::report
