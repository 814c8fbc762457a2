#include "sgmp/report/report_plots.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/child_process.hpp"
#include "sgmp/pack/executables.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp::report {

using metrics::coordination_tolerance_names;
using metrics::coordination_tolerances;
namespace fs = std::filesystem;
namespace {

/// A gnuplot string literal of any text: single-quoted, where gnuplot substitutes nothing
/// (no backquoted shell commands, no escapes, no macros), a quote doubled, and control
/// characters (a newline would end the command) made spaces. User text reaches gnuplot
/// only through this.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) {
        if (c == '\'') {
            out += "''";
        } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out + "'";
}

std::string columns(const std::vector<double>& x, const std::vector<double>& y) {
    std::ostringstream out;
    for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) {
        out << format_number(x[k]) << ' ' << format_number(y[k]) << '\n';
    }
    return out.str();
}

std::vector<double> integers(std::size_t n) {
    std::vector<double> x(n);
    for (std::size_t k = 0; k < n; ++k) {
        x[k] = static_cast<double>(k);
    }
    return x;
}

/// Okabe–Ito colours (distinguishable with the common colour-vision deficiencies), no yellow,
/// for candidates (linetypes 1–8); darker tones of four of them for reference classes
/// (linetypes 11–14), so a band never shares a candidate's colour.
constexpr const char* kPalette =
    "set linetype 1 lc rgb '#0072B2' lw 2\nset linetype 2 lc rgb '#D55E00' lw 2\n"
    "set linetype 3 lc rgb '#009E73' lw 2\nset linetype 4 lc rgb '#CC79A7' lw 2\n"
    "set linetype 5 lc rgb '#E69F00' lw 2\nset linetype 6 lc rgb '#56B4E9' lw 2\n"
    "set linetype 7 lc rgb '#000000' lw 2\nset linetype 8 lc rgb '#999999' lw 2\n"
    "set linetype 11 lc rgb '#B84A00' lw 2\nset linetype 12 lc rgb '#007A5A' lw 2\n"
    "set linetype 13 lc rgb '#A24E8E' lw 2\nset linetype 14 lc rgb '#A87400' lw 2\n";
constexpr int kCandidateColours = 8;
constexpr int kReferenceColours = 4;

/// How one series of a plot is drawn: candidates in colours 1–8 with their own point shape;
/// each reference class in its own darker colour, dashed; a class's hard-sphere limit in the
/// class's colour, dotted, its band hatched.
struct SeriesStyle {
    std::string line;  // " lt N dt M" (and " pt P" for candidates)
    std::string band;  // the fill of a ± 2 sd band
};

/// Styles of the series of one plot, in order; `labels` with `reference` flags.
std::vector<SeriesStyle> series_styles(const std::vector<std::pair<std::string, bool>>& series) {
    static const int kPoints[] = {7, 5, 9, 11, 13, 15, 4, 6};
    std::vector<std::string> classes;
    std::vector<SeriesStyle> styles;
    int candidates = 0;
    for (const auto& [label, reference] : series) {
        if (!reference) {
            const int k = candidates++ % kCandidateColours;
            styles.push_back({" lt " + std::to_string(k + 1) + " pt " + std::to_string(kPoints[k]),
                              " fs transparent solid 0.3"});
            continue;
        }
        auto it = std::find(classes.begin(), classes.end(), label);
        if (it == classes.end()) {
            classes.push_back(label);
            it = classes.end() - 1;
        }
        const int colour = 11 + static_cast<int>(it - classes.begin()) % kReferenceColours;
        styles.push_back({" lt " + std::to_string(colour) + " dt 2", " fs transparent solid 0.3"});
    }
    return styles;
}

/// The style without its point shape, for lines and bands.
std::string line_only(const std::string& style) {
    const auto at = style.find(" pt ");
    return at == std::string::npos ? style : style.substr(0, at);
}

/// The style with its dash pattern replaced by `dash`.
std::string dashed(const std::string& style, const std::string& dash) {
    const auto at = style.find(" dt ");
    if (at == std::string::npos) {
        return style + dash;
    }
    const auto end = style.find(' ', at + 4);
    return style.substr(0, at) + dash + (end == std::string::npos ? "" : style.substr(end));
}

std::vector<SeriesStyle> panel_styles(const PlotPanel& panel) {
    if (!panel.series.empty()) {  // a part: the whole panel's styles, each curve its own
        const auto all = series_styles(panel.series);
        std::vector<SeriesStyle> styles;
        for (const auto& curve : panel.curves) {
            styles.push_back(all.at(curve.slot));
        }
        return styles;
    }
    std::vector<std::pair<std::string, bool>> series;
    for (const auto& curve : panel.curves) {
        series.emplace_back(curve.group.empty() ? curve.label : curve.group, curve.reference);
    }
    return series_styles(series);
}

/// Tick labels 10ᵏ for a log axis from 10⁻⁶ to 10⁻¹.
constexpr const char* kPowerTicks =
    "'10⁻⁶' 1e-6, '10⁻⁵' 1e-5, '10⁻⁴' 1e-4, '10⁻³' 1e-3, '10⁻²' 1e-2, '10⁻¹' 1e-1";

/// Mean ± 2 sd as three columns (x, low, high), for bands.
std::string band_columns(const std::vector<double>& x, const std::vector<double>& mean,
                         const std::vector<double>& sd) {
    std::ostringstream out;
    for (std::size_t k = 0; k < x.size() && k < mean.size() && k < sd.size(); ++k) {
        out << format_number(x[k]) << ' ' << format_number(mean[k] - 2.0 * sd[k]) << ' '
            << format_number(mean[k] + 2.0 * sd[k]) << '\n';
    }
    return out.str();
}

/// g(r) beyond contact (r ≥ 1.1 d, where the verdict is judged) at a readable scale, the
/// references as mean ± 2 sd bands, and an inset of the contact region 0.9–1.15 d.
void write_gr_plot(std::ostringstream& gp, const fs::path& plots, const PlotPanel& panel) {
    const std::string& stem = panel.stem;
    std::ostringstream main;
    std::ostringstream inset;
    const auto styles = panel_styles(panel);
    for (std::size_t k = 0; k < panel.curves.size(); ++k) {
        const auto& curve = panel.curves[k];
        const std::string file = stem + "_gr_" + std::to_string(k) + ".dat";
        write_text_file(plots / file, columns(curve.curves->gr_r, curve.curves->gr));
        const std::string color = line_only(styles[k].line);
        if (curve.reference) {
            const std::string band = stem + "_grband_" + std::to_string(k) + ".dat";
            write_text_file(plots / band, band_columns(curve.curves->gr_r, curve.curves->gr,
                                                       curve.curves->gr_sd));
            // Solid for every reference: a hatch drowns the curves' peaks.
            main << "'" << band << "' using 1:2:3 with filledcurves fs transparent solid 0.25"
                 << color << " notitle, ";
        }
        main << "'" << file << "' with lines" << color << " title "
             << quoted(curve.label + (curve.reference ? " ± 2 sd" : "")) << ", ";
        inset << "'" << file << "' with lines" << color << " notitle, ";
    }
    const auto trimmed = [](std::string text) { return text.substr(0, text.size() - 2); };
    gp << "set output '" << stem << "_gr.svg'\nset multiplot\nset title "
       << quoted("g(r) beyond contact: " + panel.what)
       << "\nset xlabel 'r / d (mean diameter)'\nset ylabel 'g(r) (ratio)'\nunset logscale\n"
       << "set xrange [1.1:5]\nset yrange [0:*]\nplot " << trimmed(main.str()) << "\n"
       << "set origin 0.36,0.56\nset size 0.28,0.34\nunset title\n"
       << "set xlabel 'contact region, r / d' offset 0,0.5\nunset ylabel\n"
       << "set xrange [0.9:1.15]\nset yrange [0:*]\nset xtics 0.1\nset ytics 10\n"
       << "set object 1 rectangle from graph 0,0 to graph 1,1 behind fc rgb 'white' fs solid\n"
       << "plot " << trimmed(inset.str()) << "\n"
       << "unset object 1\nunset multiplot\nset origin 0,0\nset size 1,1\n"
       << "set xrange [*:*]\nset yrange [*:*]\nset xtics autofreq\nset ytics autofreq\n";
}

/// φ(N), Z(N) and split ratio (N): every candidate as points and lines, every reference as
/// a mean ± 2 sd band over its seeds.
std::vector<std::string> write_trend_plots(std::ostringstream& gp, const fs::path& plots,
                                           const std::vector<Trend>& trends) {
    std::vector<std::string> files;
    std::vector<std::string> metrics;
    for (const auto& t : trends) {
        if (std::find(metrics.begin(), metrics.end(), t.metric) == metrics.end()) {
            metrics.push_back(t.metric);
        }
    }
    for (const auto& metric : metrics) {
        std::string label;
        std::vector<const Trend*> series;
        std::vector<std::pair<std::string, bool>> labels;
        for (const auto& t : trends) {
            if (t.metric == metric) {
                series.push_back(&t);
                labels.emplace_back(t.label, t.reference);
            }
        }
        const auto styles = series_styles(labels);  // the same style in every part
        std::vector<bool> reference;
        for (const Trend* t : series) {
            reference.push_back(t->reference);
        }
        const auto parts = split_series(reference);
        for (std::size_t p = 0; p < parts.size(); ++p) {
            std::ostringstream part;
            for (const std::size_t i : parts[p]) {
                const Trend* t = series[i];
                label = t->metric_label;
                const SeriesStyle& style = styles[i];
                const std::string file = "trend_" + metric + "_" + std::to_string(i + 1) + ".dat";
                if (t->reference) {
                    write_text_file(plots / file, band_columns(t->count, t->mean, t->sd));
                    part << "'" << file << "' using 1:2:3 with filledcurves" << style.band
                         << line_only(style.line) << " title " << quoted(t->label + " ± 2 sd")
                         << ", ";
                } else {
                    write_text_file(plots / file, columns(t->count, t->mean));
                    part << "'" << file << "' with linespoints ps 1.2" << style.line << " title "
                         << quoted(t->label) << ", ";
                }
            }
            const std::string text = part.str();
            const std::string name =
                "trend_" + metric + (p == 0 ? "" : "_" + std::to_string(p + 1)) + ".svg";
            const std::string of = parts.size() > 1 ? " (" + std::to_string(p + 1) + " of " +
                                                          std::to_string(parts.size()) + ")"
                                                    : "";
            gp << "set output '" << name << "'\nset title " << quoted(label + " against N" + of)
               << "\nset logscale x\nset xlabel 'N (particles)'\nset ylabel " << quoted(label)
               << "\nplot " << text.substr(0, text.size() - 2) << "\nunset logscale\n";
            files.push_back("plots/" + name);
        }
    }
    return files;
}

/// `stem`_`kind`_`k`.dat: the data file of curve k of a panel.
std::string data_file(const PlotPanel& panel, const std::string& kind, std::size_t k) {
    return panel.stem + "_" + kind + "_" + std::to_string(k) + ".dat";
}

/// P(Z) at the two plotted tolerances for a pair of curves; only the headline δ = 1e-2
/// when more curves share the plot.
void write_pz_plot(std::ostringstream& gp, const fs::path& plots, const PlotPanel& panel) {
    const auto& names = coordination_tolerance_names();
    std::vector<std::size_t> plotted(std::begin(kPlottedPzTolerances),
                                     std::end(kPlottedPzTolerances));
    if (panel.curves.size() > 2) {
        plotted = {kHeadlinePzTolerance};
    }
    gp << "set output '" << panel.stem << "_pz.svg'\nset title " << quoted("P(Z): " + panel.what)
       << "\nset xlabel 'Z (contacts)'\nset ylabel 'P(Z) (fraction of particles)'\nplot ";
    bool first = true;
    const auto styles = panel_styles(panel);
    for (const std::size_t t : plotted) {
        for (std::size_t k = 0; k < panel.curves.size(); ++k) {
            const auto& curve = panel.curves[k];
            const std::string file =
                panel.stem + "_pz_" + std::to_string(k) + "_" + names[t] + ".dat";
            static const std::vector<double> kNone;
            const auto& p_z = t < curve.curves->p_z.size() ? curve.curves->p_z[t] : kNone;
            write_text_file(plots / file, columns(integers(p_z.size()), p_z));
            // The second tolerance's curves dashed, when both are shown.
            const std::string line =
                t == plotted.front() ? styles[k].line : dashed(styles[k].line, " dt 4");
            gp << (first ? "" : ", ") << "'" << file << "' with linespoints lw 2" << line
               << " title " << quoted(curve.label + ", gap <= " + names[t] + " d");
            first = false;
        }
    }
    gp << "\n";
}

/// Mean Z against the gap tolerance δ > 0, on a log axis.
void write_zdelta_plot(std::ostringstream& gp, const fs::path& plots, const PlotPanel& panel) {
    const auto& tolerances = coordination_tolerances();
    const auto styles = panel_styles(panel);
    gp << "set output '" << panel.stem << "_zdelta.svg'\nset title "
       << quoted("Z(delta), gap <= delta d: " + panel.what) << "\nset logscale x\nset xtics ("
       << kPowerTicks
       << ")\nset xlabel 'δ (gap over d)'\nset ylabel 'mean Z (contacts/particle)'\nplot ";
    for (std::size_t k = 0; k < panel.curves.size(); ++k) {
        const auto& curve = panel.curves[k];
        std::vector<double> deltas;
        std::vector<double> z;
        for (std::size_t t = 0; t < tolerances.size(); ++t) {
            if (tolerances[t] > 0.0 && t < curve.curves->z_mean.size()) {
                deltas.push_back(tolerances[t]);
                z.push_back(curve.curves->z_mean[t]);
            }
        }
        write_text_file(plots / data_file(panel, "zd", k), columns(deltas, z));
        gp << (k == 0 ? "" : ", ") << "'" << data_file(panel, "zd", k) << "' with linespoints lw 2"
           << styles[k].line << " title " << quoted(curve.label);
    }
    gp << "\nunset logscale\nset xtics autofreq\n";
}

/// φ(y): height on the vertical axis.
void write_phiy_plot(std::ostringstream& gp, const fs::path& plots, const PlotPanel& panel) {
    const auto styles = panel_styles(panel);
    gp << "set output '" << panel.stem << "_phiy.svg'\nset title "
       << quoted("phi(y): " + panel.what)
       << "\nset xlabel 'φ (ratio)'\nset ylabel 'y (length units)'\nplot ";
    for (std::size_t k = 0; k < panel.curves.size(); ++k) {
        const auto& curve = panel.curves[k];
        write_text_file(plots / data_file(panel, "phiy", k),
                        columns(curve.curves->phi_y_mid, curve.curves->phi_y));
        gp << (k == 0 ? "" : ", ") << "'" << data_file(panel, "phiy", k)
           << "' using 2:1 with lines lw 2" << line_only(styles[k].line) << " title "
           << quoted(curve.label);
    }
    gp << "\n";
}

/// Whether some curve of `panel` holds the data `has` asks for (packs taken from a
/// `--metrics` summary hold no g(r), P(Z) or φ(y): their plots are left out, not drawn empty).
template <class Has>
bool any_curve(const PlotPanel& panel, const Has& has) {
    return std::any_of(panel.curves.begin(), panel.curves.end(),
                       [&](const PlotCurve& c) { return c.curves != nullptr && has(*c.curves); });
}

/// The four plots of a panel, each when some curve has its data; their SVG paths
/// (relative to the report) go to `files`.
void write_panel(std::ostringstream& gp, const fs::path& plots, const PlotPanel& panel,
                 std::vector<std::string>& files) {
    const auto& tolerances = coordination_tolerances();
    if (any_curve(panel, [](const auto& c) { return !c.gr.empty(); })) {
        write_gr_plot(gp, plots, panel);
        files.push_back("plots/" + panel.stem + "_gr.svg");
    }
    if (any_curve(panel, [&](const auto& c) {
            return c.p_z.size() == tolerances.size() && !c.p_z[kHeadlinePzTolerance].empty();
        })) {
        write_pz_plot(gp, plots, panel);
        files.push_back("plots/" + panel.stem + "_pz.svg");
    }
    if (any_curve(panel, [&](const auto& c) { return c.z_mean.size() == tolerances.size(); })) {
        write_zdelta_plot(gp, plots, panel);
        files.push_back("plots/" + panel.stem + "_zdelta.svg");
    }
    if (any_curve(panel, [](const auto& c) { return !c.phi_y.empty(); })) {
        write_phiy_plot(gp, plots, panel);
        files.push_back("plots/" + panel.stem + "_phiy.svg");
    }
}

/// Runs gnuplot on plots/plots.gp (its output in plots/gnuplot.log) and checks that every
/// one of `files` was written.
PlotResult run_gnuplot(const fs::path& gnuplot, const fs::path& directory,
                       const std::vector<std::string>& files) {
    PlotResult result;
    const fs::path plots = directory / "plots";
    std::string log;
    ChildOptions run;
    run.argv = {gnuplot.string(), "plots.gp"};
    run.working_directory = plots;
    run.timeout = std::chrono::minutes(5);
    const ChildResult ran = run_child(run, [&](const std::string& line) { log += line + "\n"; });
    write_text_file(plots / "gnuplot.log", log);
    if (ran.end != ChildEnd::exited || ran.exit_code != 0) {
        result.note = "gnuplot failed; see plots/gnuplot.log";
        return result;
    }
    for (const auto& file : files) {
        if (!fs::exists(directory / file)) {
            result.note = "gnuplot did not write " + file + "; see plots/gnuplot.log";
            return result;
        }
    }
    result.made = true;
    result.files = files;
    return result;
}

}  // namespace

std::optional<fs::path> find_gnuplot() {
    const char* forced = std::getenv("SGMP_GNUPLOT");
    if (forced != nullptr && *forced == '\0') {
        return std::nullopt;
    }
    return find_executable(forced != nullptr ? forced : "gnuplot");
}

PlotResult make_plots(const std::vector<PlotPanel>& panels, const std::vector<Trend>& trends,
                      const fs::path& directory) {
    PlotResult result;
    const auto gnuplot = find_gnuplot();
    if (!gnuplot) {
        result.note = "gnuplot was not found (install gnuplot-nox)";
        return result;
    }
    if (panels.empty()) {
        result.note = "nothing was compared";
        return result;
    }
    const fs::path plots = directory / "plots";
    fs::create_directories(plots);
    std::ostringstream gp;
    // Drawn at 800 px and shown at 640 px: 16 pt text reads as about 13 px; the key goes
    // below the plot, where it hides no curve.
    gp << "set terminal svg size 800,520 dynamic noenhanced font 'sans,16' background rgb "
          "'white'\nset key outside below center horizontal samplen 2 spacing 1.1\nset grid\n"
       << kPalette;
    std::vector<std::string> files = write_trend_plots(gp, plots, trends);
    for (const PlotPanel& panel : panels) {
        write_panel(gp, plots, panel, files);
    }
    gp << "unset output\n";
    write_text_file(plots / "plots.gp", gp.str());
    return run_gnuplot(*gnuplot, directory, files);
}

}  // namespace sgmp::report
