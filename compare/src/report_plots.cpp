#include "sgmp/compare/report_plots.hpp"

#include <unistd.h>
#include <cstdlib>
#include <fstream>
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

PlotResult make_plots(const Report& report, const fs::path& directory) {
    PlotResult result;
    const auto gnuplot = find_gnuplot();
    if (!gnuplot) {
        result.note = "gnuplot was not found (install gnuplot-nox)";
        return result;
    }
    if (report.comparisons.empty()) {
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
    for (std::size_t i = 0; i < report.comparisons.size(); ++i) {
        const Comparison& c = report.comparisons[i];
        const std::string stem = "c" + std::to_string(i) + "_N" + std::to_string(c.count);
        const std::string ta = mean_label(c.candidate, c.candidate_packs);
        const std::string tb = mean_label(c.reference, c.reference_packs);
        const std::string what =
            c.candidate + " vs " + c.reference + ", N = " + std::to_string(c.count);
        const auto& a = c.candidate_curves;
        const auto& b = c.reference_curves;

        write_text(plots / (stem + "_gr_a.dat"), columns(a.gr_r, a.gr));
        write_text(plots / (stem + "_gr_b.dat"), columns(b.gr_r, b.gr));
        gp << "set output '" << stem << "_gr.svg'\nset title " << quoted("g(r): " + what)
           << "\nset xlabel 'r / d (mean diameter)'\nset ylabel 'g(r) (ratio)'\nunset logscale\n"
           << "plot '" << stem << "_gr_a.dat' with lines lw 2 title " << quoted(ta) << ", '" << stem
           << "_gr_b.dat' with lines lw 2 dt 2 title " << quoted(tb) << "\n";
        files.push_back("plots/" + stem + "_gr.svg");

        gp << "set output '" << stem << "_pz.svg'\nset title " << quoted("P(Z): " + what)
           << "\nset xlabel 'Z (contacts)'\nset ylabel 'P(Z) (fraction of particles)'\nplot ";
        bool first = true;
        for (const std::size_t t : kPlottedPzTolerances) {
            for (const auto& [side, curves, label] :
                 {std::tuple{"a", &a, ta}, std::tuple{"b", &b, tb}}) {
                const std::string file = stem + "_pz_" + side + "_" + names[t] + ".dat";
                write_text(plots / file, columns(integers(curves->p_z[t].size()), curves->p_z[t]));
                gp << (first ? "" : ", ") << "'" << file << "' with linespoints lw 2"
                   << (std::string(side) == "b" ? " dt 2" : "") << " title "
                   << quoted(label + ", gap <= " + names[t] + " d");
                first = false;
            }
        }
        gp << "\n";
        files.push_back("plots/" + stem + "_pz.svg");

        std::vector<double> deltas;
        std::vector<double> za;
        std::vector<double> zb;
        for (std::size_t t = 0; t < tolerances.size(); ++t) {
            if (tolerances[t] > 0.0) {
                deltas.push_back(tolerances[t]);
                za.push_back(a.z_mean[t]);
                zb.push_back(b.z_mean[t]);
            }
        }
        write_text(plots / (stem + "_zd_a.dat"), columns(deltas, za));
        write_text(plots / (stem + "_zd_b.dat"), columns(deltas, zb));
        gp << "set output '" << stem << "_zdelta.svg'\nset title "
           << quoted("Z(delta), gap <= delta d: " + what)
           << "\nset logscale x\nset xlabel 'delta (ratio to d)'\nset ylabel 'mean Z "
              "(contacts/particle)'\n"
           << "plot '" << stem << "_zd_a.dat' with linespoints lw 2 title " << quoted(ta) << ", '"
           << stem << "_zd_b.dat' with linespoints lw 2 dt 2 title " << quoted(tb)
           << "\nunset logscale\n";
        files.push_back("plots/" + stem + "_zdelta.svg");

        write_text(plots / (stem + "_phiy_a.dat"), columns(a.phi_y_mid, a.phi_y));
        write_text(plots / (stem + "_phiy_b.dat"), columns(b.phi_y_mid, b.phi_y));
        gp << "set output '" << stem << "_phiy.svg'\nset title " << quoted("phi(y): " + what)
           << "\nset xlabel 'phi (ratio)'\nset ylabel 'y (length units)'\n"
           << "plot '" << stem << "_phiy_a.dat' using 2:1 with lines lw 2 title " << quoted(ta)
           << ", '" << stem << "_phiy_b.dat' using 2:1 with lines lw 2 dt 2 title " << quoted(tb)
           << "\n";
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
