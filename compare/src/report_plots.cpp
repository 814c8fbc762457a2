#include "sgmp/compare/report_plots.hpp"

#include <unistd.h>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "sgmp/compare/measure.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp::compare {
namespace fs = std::filesystem;
namespace {

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
        }
        out += c;
    }
    return out + "\"";
}

std::string shell_quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) {
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) {
        throw std::runtime_error(path.string() + ": cannot write");
    }
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

std::string mean_label(const std::string& label, std::size_t packs) {
    return label + " (mean of " + std::to_string(packs) + ")";
}

}  // namespace

std::optional<fs::path> find_gnuplot() {
    if (const char* forced = std::getenv("SGMP_GNUPLOT")) {
        if (*forced == '\0' || ::access(forced, X_OK) != 0) {
            return std::nullopt;
        }
        return fs::path(forced);
    }
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "gnuplot";
        if (::access(candidate.c_str(), X_OK) == 0) {
            return candidate;
        }
    }
    return std::nullopt;
}

std::vector<PlotPanel> panels_per_comparison(const Report& report) {
    std::vector<PlotPanel> panels;
    for (std::size_t i = 0; i < report.comparisons.size(); ++i) {
        const Comparison& c = report.comparisons[i];
        panels.push_back(PlotPanel{
            "c" + std::to_string(i) + "_N" + std::to_string(c.count),
            c.candidate + " vs " + c.reference + ", N = " + std::to_string(c.count),
            {PlotCurve{mean_label(c.candidate, c.candidate_packs), &c.candidate_curves, false},
             PlotCurve{mean_label(c.reference, c.reference_packs), &c.reference_curves, true}}});
    }
    return panels;
}

std::vector<PlotPanel> panels_per_count(const Report& report) {
    std::vector<PlotPanel> panels;
    std::vector<std::set<std::string>> drawn;
    for (const Comparison& c : report.comparisons) {
        std::size_t k = 0;
        while (k < panels.size() && panels[k].stem != "N" + std::to_string(c.count)) {
            ++k;
        }
        if (k == panels.size()) {
            panels.push_back(
                PlotPanel{"N" + std::to_string(c.count), "N = " + std::to_string(c.count), {}});
            drawn.emplace_back();
        }
        if (drawn[k].insert(c.candidate).second) {
            panels[k].curves.push_back(
                PlotCurve{mean_label(c.candidate, c.candidate_packs), &c.candidate_curves, false});
        }
        if (drawn[k].insert(c.reference).second) {
            panels[k].curves.push_back(
                PlotCurve{mean_label(c.reference, c.reference_packs), &c.reference_curves, true});
        }
    }
    return panels;
}

PlotResult make_plots(const std::vector<PlotPanel>& panels, const fs::path& directory) {
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
    gp << "set terminal svg size 800,500 dynamic noenhanced font 'sans,12' background rgb "
          "'white'\nset key top right\nset grid\n";
    const auto& tolerances = coordination_tolerances();
    const auto& names = coordination_tolerance_names();
    std::vector<std::string> files;
    for (const PlotPanel& panel : panels) {
        const std::string& stem = panel.stem;
        const std::string& what = panel.what;
        const auto style = [](const PlotCurve& curve) {
            return std::string(curve.reference ? " dt 2" : "");
        };
        const auto data_file = [&](const std::string& kind, std::size_t k) {
            return stem + "_" + kind + "_" + std::to_string(k) + ".dat";
        };

        gp << "set output '" << stem << "_gr.svg'\nset title " << quoted("g(r): " + what)
           << "\nset xlabel 'r / d (mean diameter)'\nset ylabel 'g(r) (ratio)'\nunset logscale\n"
           << "plot ";
        for (std::size_t k = 0; k < panel.curves.size(); ++k) {
            const auto& curve = panel.curves[k];
            write_text(plots / data_file("gr", k), columns(curve.curves->gr_r, curve.curves->gr));
            gp << (k == 0 ? "" : ", ") << "'" << data_file("gr", k) << "' with lines lw 2"
               << style(curve) << " title " << quoted(curve.label);
        }
        gp << "\n";
        files.push_back("plots/" + stem + "_gr.svg");

        // Two tolerances for a pair of curves; only δ = 1e-2 when more curves share a plot.
        std::vector<std::size_t> plotted(std::begin(kPlottedPzTolerances),
                                         std::end(kPlottedPzTolerances));
        if (panel.curves.size() > 2) {
            plotted = {kHeadlinePzTolerance};
        }
        gp << "set output '" << stem << "_pz.svg'\nset title " << quoted("P(Z): " + what)
           << "\nset xlabel 'Z (contacts)'\nset ylabel 'P(Z) (fraction of particles)'\nplot ";
        bool first = true;
        for (const std::size_t t : plotted) {
            for (std::size_t k = 0; k < panel.curves.size(); ++k) {
                const auto& curve = panel.curves[k];
                const std::string file =
                    stem + "_pz_" + std::to_string(k) + "_" + names[t] + ".dat";
                write_text(plots / file,
                           columns(integers(curve.curves->p_z[t].size()), curve.curves->p_z[t]));
                gp << (first ? "" : ", ") << "'" << file << "' with linespoints lw 2"
                   << style(curve) << " title "
                   << quoted(curve.label + ", gap <= " + names[t] + " d");
                first = false;
            }
        }
        gp << "\n";
        files.push_back("plots/" + stem + "_pz.svg");

        gp << "set output '" << stem << "_zdelta.svg'\nset title "
           << quoted("Z(delta), gap <= delta d: " + what)
           << "\nset logscale x\nset xlabel 'delta (ratio to d)'\nset ylabel 'mean Z "
              "(contacts/particle)'\nplot ";
        for (std::size_t k = 0; k < panel.curves.size(); ++k) {
            const auto& curve = panel.curves[k];
            std::vector<double> deltas;
            std::vector<double> z;
            for (std::size_t t = 0; t < tolerances.size(); ++t) {
                if (tolerances[t] > 0.0) {
                    deltas.push_back(tolerances[t]);
                    z.push_back(curve.curves->z_mean[t]);
                }
            }
            write_text(plots / data_file("zd", k), columns(deltas, z));
            gp << (k == 0 ? "" : ", ") << "'" << data_file("zd", k) << "' with linespoints lw 2"
               << style(curve) << " title " << quoted(curve.label);
        }
        gp << "\nunset logscale\n";
        files.push_back("plots/" + stem + "_zdelta.svg");

        gp << "set output '" << stem << "_phiy.svg'\nset title " << quoted("phi(y): " + what)
           << "\nset key bottom left\nset xlabel 'phi (ratio)'\nset ylabel 'y (length "
              "units)'\nplot ";
        for (std::size_t k = 0; k < panel.curves.size(); ++k) {
            const auto& curve = panel.curves[k];
            write_text(plots / data_file("phiy", k),
                       columns(curve.curves->phi_y_mid, curve.curves->phi_y));
            gp << (k == 0 ? "" : ", ") << "'" << data_file("phiy", k)
               << "' using 2:1 with lines lw 2" << style(curve) << " title " << quoted(curve.label);
        }
        gp << "\nset key top right\n";
        files.push_back("plots/" + stem + "_phiy.svg");
    }
    gp << "unset output\n";
    write_text(plots / "plots.gp", gp.str());
    const std::string command = "cd " + shell_quoted(plots.string()) + " && " +
                                shell_quoted(gnuplot->string()) + " plots.gp > gnuplot.log 2>&1";
    if (std::system(command.c_str()) != 0) {
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

}  // namespace sgmp::compare
