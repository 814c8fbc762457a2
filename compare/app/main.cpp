// sgmp-compare: metrics of sphere packs and agreement reports between groups of packs.
#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include "command_support.hpp"
#include "sgmp/compare/agreement.hpp"
#include "sgmp/compare/measure.hpp"
#include "sgmp/compare/metrics_output.hpp"
#include "sgmp/compare/parallel.hpp"
#include "sgmp/compare/report_files.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/interrupt.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/version.hpp"

namespace fs = std::filesystem;
using namespace sgmp;
using namespace sgmp::compare;

namespace {

using namespace sgmp::compare::cli;

int run_measure(const std::vector<std::string>& packs, CommonOptions& o, const std::string& cmd) {
    apply(o);
    std::map<std::string, std::string> stems;
    for (const auto& path : packs) {
        const auto [it, fresh] = stems.emplace(stem_of(path), path);
        if (!fresh) {
            throw UsageError("packs " + it->second + " and " + path +
                             " would write the same output names '" + it->first + ".*'");
        }
    }
    write_directory_atomically(o.out, o.force, [&](const fs::path& dir) {
        for (const auto& path : packs) {
            const auto read_start = std::chrono::steady_clock::now();
            const Pack pack = read_pack(path);
            if (o.timings) {
                std::cerr << "timings " << path << ": read "
                          << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                           read_start)
                                 .count()
                          << " s\n";
            }
            const Measurement m = measure_pack(path, pack, o);
            auto prov = provenance(path, pack, o.measure);
            prov["command"] = cmd;
            const std::string stem = stem_of(path);
            std::ofstream json(dir / (stem + ".metrics.json"));
            json << metrics_json(m, prov).dump(2) << "\n";
            std::ofstream g(dir / (stem + ".g_r.csv"));
            write_g_r_csv(g, m, prov);
            std::ofstream phi(dir / (stem + ".phi_y.csv"));
            write_phi_y_csv(phi, m, prov);
            std::ofstream pz(dir / (stem + ".p_z.csv"));
            write_p_z_csv(pz, m, prov);
            std::ofstream voronoi(dir / (stem + ".voronoi_phi.csv"));
            write_voronoi_csv(voronoi, m, prov);
            voronoi.flush();
            json.flush();
            g.flush();
            phi.flush();
            pz.flush();
            if (!json || !g || !phi || !pz || !voronoi) {
                throw std::runtime_error((dir / stem).string() + ": cannot write outputs");
            }
        }
    });
    return 0;
}

int run_report(const std::vector<std::string>& a, const std::vector<std::string>& b,
               const std::string& label_a, const std::string& label_b, CommonOptions& o,
               const std::string& cmd) {
    if (label_a == label_b) {
        throw UsageError("--label-a and --label-b must differ (both are '" + label_a + "')");
    }
    for (const auto& label : {label_a, label_b}) {
        if (label.empty() || label.find_first_of(",\n\"") != std::string::npos) {
            throw UsageError("labels must be non-empty without commas, quotes or line breaks: '" +
                             label + "'");
        }
    }
    apply(o);
    std::vector<Group> groups{measure_group(label_a, a, o), measure_group(label_b, b, o)};
    ReportPlan plan;
    plan.comparisons = {{0, 1}};
    const Report report = build_report(std::move(groups), plan);
    ReportContext context;
    context.command = cmd;
    context.parameters = measure_parameters(o);
    const auto used = write_report(o.out, o.force, report, context);
    if (!used.plots_made) {
        std::cerr << "sgmp-compare: plots skipped: " << used.plots_note << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "sgmp-compare " + std::string(sgmp::version()) +
        ": metrics of sphere packs (packing fraction, overlaps, coordination, g(r), Q6) and "
        "agreement reports between groups of packs. Lengths are in the pack's units (the "
        "control volume's side); *_over_d values and g(r) distances are in mean diameters d."};
    app.set_version_flag("--version", std::string(sgmp::version()));
    app.require_subcommand(1);

    std::vector<std::string> packs;
    CommonOptions measure_options;
    CLI::App* measure_cmd = app.add_subcommand(
        "measure",
        "measure packs: per pack <stem>.metrics.json, "
        "<stem>.g_r.csv, <stem>.phi_y.csv, <stem>.p_z.csv, <stem>.voronoi_phi.csv");
    measure_cmd->add_option("packs", packs, "pack files (extended XYZ or LIGGGHTS dump, .gz ok)")
        ->required();
    add_common(measure_cmd, measure_options);

    std::vector<std::string> a;
    std::vector<std::string> b;
    std::string label_a = "A";
    std::string label_b = "B";
    CommonOptions report_options;
    CLI::App* report_cmd = app.add_subcommand(
        "report",
        "agreement report of packs A against reference packs B, per particle count: "
        "report.md, report.csv, report.json, plots/*.svg, index.html");
    report_cmd->add_option("--a", a, "candidate packs")->required();
    report_cmd
        ->add_option("--b", b, "reference packs (their seed-to-seed spread sets the tolerance)")
        ->required();
    report_cmd->add_option("--label-a", label_a, "name of the A side (default A)");
    report_cmd->add_option("--label-b", label_b, "name of the B side (default B)");
    add_common(report_cmd, report_options);
    add_precomputed(report_cmd, report_options);

    const auto crossval = register_crossval(app);
    const auto regress = register_regress(app);

    const std::string cmd = command_line(argc, argv);
    return ::sgmp::cli::run_main(
        "sgmp-compare", app, [&] { app.parse(argc, argv); },
        [&] {
            install_interrupt_handler("sgmp-compare");
            if (*measure_cmd) {
                return run_measure(packs, measure_options, cmd);
            }
            for (const auto& run : {crossval, regress}) {
                if (const int status = run(cmd); status >= 0) {
                    return status;
                }
            }
            return run_report(a, b, label_a, label_b, report_options, cmd);
        });
}
