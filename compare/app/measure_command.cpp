// sgmp-compare measure, report and header: metrics of single packs, the agreement report of
// two groups of packs, and one pack's provenance keys for scripts.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "command_support.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/report/agreement.hpp"
#include "sgmp/report/manifest.hpp"
#include "sgmp/report/report_files.hpp"

namespace sgmp::compare::cli {
namespace fs = std::filesystem;

namespace {

struct MeasureOptions {
    std::vector<std::string> packs;
    CommonOptions common;
};

struct ReportOptions {
    std::vector<std::string> a;
    std::vector<std::string> b;
    std::string label_a = "A";
    std::string label_b = "B";
    CommonOptions common;
};

struct HeaderOptions {
    std::string pack;
    std::vector<std::string> keys;
    bool allow_missing = false;
};

/// A pack's name reaches the JSON outputs (provenance.input): it must be UTF-8, or the
/// JSON writer fails after the whole measurement (reliability finding 14).
void check_utf8_names(const std::vector<std::string>& packs) {
    for (const auto& path : packs) {
        if (!is_utf8(path)) {
            throw UsageError("pack '" + path + "': a file name must be UTF-8 (a Latin-1 byte?)");
        }
    }
}

/// Every pack must write its own output names.
void check_distinct_stems(const std::vector<std::string>& packs) {
    check_utf8_names(packs);
    std::map<std::string, std::string> stems;
    for (const auto& path : packs) {
        const auto [it, fresh] = stems.emplace(stem_of(path), path);
        if (!fresh) {
            throw UsageError("packs " + it->second + " and " + path +
                             " would write the same output names '" + it->first + ".*'");
        }
    }
}

int run_measure(MeasureOptions& o, const std::string& cmd) {
    apply(o.common);
    check_distinct_stems(o.packs);
    write_directory_atomically(o.common.out, o.common.force, [&](const fs::path& dir) {
        for (const auto& path : o.packs) {
            const auto read_start = std::chrono::steady_clock::now();
            const Pack pack = read_pack(path, o.common.stated, o.common.threads);
            if (o.common.timings) {
                std::cerr << "timings " << path << ": read "
                          << std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                           read_start)
                                 .count()
                          << " s\n";
            }
            const Measurement m = measure_pack(path, pack, o.common);
            auto prov = provenance(path, pack, o.common.measure);
            prov["command"] = cmd;
            write_pack_metrics(dir, stem_of(path), m, prov);
        }
    });
    return 0;
}

void check_labels(const std::string& label_a, const std::string& label_b) {
    if (label_a == label_b) {
        throw UsageError("--label-a and --label-b must differ (both are '" + label_a + "')");
    }
    for (const auto& label : {label_a, label_b}) {
        if (label.empty() || label.find_first_of(",\n\"") != std::string::npos) {
            throw UsageError("labels must be non-empty without commas, quotes or line breaks: '" +
                             label + "'");
        }
        if (const auto rule = report::group_name_rule_broken(label)) {  // the manifest's rule
            throw UsageError("label '" + label + "': " + *rule);
        }
    }
}

/// One pack is one seed: a file given twice (by any spelling of its path, or as a
/// byte-identical copy) would count as two seeds with no spread between them.
void check_distinct(const std::vector<std::string>& a, const std::vector<std::string>& b) {
    std::vector<std::string> all = a;
    all.insert(all.end(), b.begin(), b.end());
    check_utf8_names(all);
    const auto same = find_same_pack(all);
    if (!same) {
        return;
    }
    const std::string& first = all[same->first];
    const std::string& second = all[same->second];
    throw UsageError(same->same_file
                         ? "pack '" + second + "' is given twice (as '" + first +
                               "'): each pack counts once"
                         : "packs '" + first + "' and '" + second +
                               "' are byte-identical copies of one pack: each pack counts once");
}

int run_report(ReportOptions& o, const std::string& cmd) {
    check_labels(o.label_a, o.label_b);
    check_distinct(o.a, o.b);
    apply(o.common);
    std::vector<Group> groups{measure_group(o.label_a, o.a, o.common),
                              measure_group(o.label_b, o.b, o.common)};
    ReportPlan plan;
    plan.comparisons = {{0, 1}};
    const Report report = build_report(std::move(groups), plan);
    ReportContext context;
    context.command = cmd;
    context.parameters = measure_parameters(o.common);
    const auto used = write_report(o.common.out, o.common.force, report, context);
    if (!used.plots_made) {
        std::cerr << "sgmp-compare: plots skipped: " << used.plots_note << "\n";
    }
    return 0;
}

/// Prints every key=value of the header, or the value of each asked key on its own line.
int run_header(const HeaderOptions& o) {
    ReadOptions as_written;
    as_written.as_written = true;  // the header as the file has it (up_axis, box)
    const Pack pack = read_pack_file(o.pack, as_written).pack;
    if (o.keys.empty()) {
        for (const auto& entry : pack.metadata.entries()) {
            std::cout << entry.first << "=" << entry.second << "\n";
        }
        return 0;
    }
    for (const auto& key : o.keys) {
        const auto value = pack.metadata.get(key);
        if (!value && !o.allow_missing) {
            throw InputError(o.pack, 2, "the header has no key '" + key + "'");
        }
        std::cout << value.value_or("") << '\n';
    }
    return 0;
}

}  // namespace

CommandRunner register_measure(CLI::App& app) {
    auto o = std::make_shared<MeasureOptions>();
    CLI::App* cmd = app.add_subcommand(
        "measure",
        "measure packs: per pack <stem>.metrics.json, "
        "<stem>.g_r.csv, <stem>.phi_y.csv, <stem>.p_z.csv, <stem>.voronoi_phi.csv");
    cmd->add_option("packs", o->packs, "pack files (extended XYZ or LIGGGHTS dump, .gz ok)")
        ->required();
    add_common(cmd, o->common);
    return [o, cmd](const std::string& command) { return *cmd ? run_measure(*o, command) : -1; };
}

CommandRunner register_report(CLI::App& app) {
    auto o = std::make_shared<ReportOptions>();
    CLI::App* cmd = app.add_subcommand(
        "report",
        "agreement report of packs A against reference packs B, per particle count: "
        "report.md, report.csv, report.json, plots/*.svg, index.html");
    cmd->add_option("--a", o->a, "candidate packs")->required();
    cmd->add_option("--b", o->b, "reference packs (their seed-to-seed spread sets the tolerance)")
        ->required();
    cmd->add_option("--label-a", o->label_a, "name of the A side (default A)");
    cmd->add_option("--label-b", o->label_b, "name of the B side (default B)");
    add_common(cmd, o->common);
    add_precomputed(cmd, o->common);
    return [o, cmd](const std::string& command) { return *cmd ? run_report(*o, command) : -1; };
}

CommandRunner register_header(CLI::App& app) {
    auto o = std::make_shared<HeaderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "header",
        "print a pack file's provenance keys: every key=value line, or the value of each KEY "
        "given, one per line (for scripts; the file is read and checked in full)");
    cmd->add_option("pack", o->pack, "pack file (extended XYZ or dump custom, .gz ok)")->required();
    cmd->add_option("keys", o->keys, "keys to print");
    cmd->add_flag("--allow-missing", o->allow_missing,
                  "print an empty line for a key the header lacks instead of failing");
    return [o, cmd](const std::string&) { return *cmd ? run_header(*o) : -1; };
}

}  // namespace sgmp::compare::cli
