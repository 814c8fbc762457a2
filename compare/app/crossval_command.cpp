// sgmp-compare crossval and regress: the cross-validation report of candidate groups
// (SGMP arrangements) against reference groups (DEM friction classes), and regression
// checks of a run's metrics against a stored baseline.
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "command_support.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/report/baseline.hpp"
#include "sgmp/report/crossval.hpp"
#include "sgmp/report/crossval_render.hpp"
#include "sgmp/report/json_input.hpp"
#include "sgmp/report/manifest.hpp"
#include "sgmp/report/report_files.hpp"
#include "sgmp/report/report_pictures.hpp"
#include "sgmp/report/sequential_rows.hpp"
#include "sgmp/report/thesis_table.hpp"

namespace sgmp::compare::cli {
namespace {

/// Exit status of a regression whose metrics moved beyond their tolerances.
constexpr int kRegressionFailed = 3;

std::ifstream open_input(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path, 0, "cannot open for reading");
    }
    return in;
}

nlohmann::json read_json(const std::string& path) {
    auto in = open_input(path);
    std::ostringstream text;
    text << in.rdbuf();
    return parse_json_input(text.str(), path);
}

struct CrossvalOptions {
    std::string manifest;
    std::string thesis;
    std::string thesis_start;
    std::string tuning;
    bool pictures = false;
    int picture_size = 600;
    SequentialDesign sequential{5, 5, 0, 0.05};  // --max-seeds (0: not given), --first-look, …
    std::string seeds_needed;                    // --seeds-needed FILE
    CommonOptions common;
};

nlohmann::ordered_json manifest_json(const std::vector<ManifestEntry>& manifest) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& e : manifest) {
        list.push_back(
            {{"role", to_string(e.role)},
             {"group", e.group},
             {"count", e.count},
             {"seed", e.seed},
             {"seconds", e.seconds ? nlohmann::ordered_json(*e.seconds) : nlohmann::ordered_json()},
             {"path", e.path},
             {"container", e.container ? nlohmann::ordered_json(e.container->to_string())
                                       : nlohmann::ordered_json()}});
    }
    return list;
}

/// The count a manifest line states is the count of the pack it names (a pack of another
/// count would leave its group silently).
void check_counts(const std::vector<ManifestEntry>& manifest, const std::vector<Group>& groups,
                  const std::string& source) {
    std::map<std::string, std::size_t> held;  // path -> spheres in the file
    for (const auto& g : groups) {
        for (const auto& p : g.packs) {
            held.emplace(p.source, p.count);
        }
    }
    for (std::size_t i = 0; i < manifest.size(); ++i) {
        const auto found = held.find(manifest[i].path);
        if (found != held.end() && found->second != manifest[i].count) {
            throw InputError(source, 0,
                             manifest[i].path + ": the manifest says " +
                                 std::to_string(manifest[i].count) + " spheres, the pack holds " +
                                 std::to_string(found->second));
        }
    }
}

/// The manifest's container column, per pack; a row that states other walls than
/// --container contradicts it.
void state_containers(const std::vector<ManifestEntry>& manifest, const std::string& source,
                      CommonOptions& o) {
    for (const auto& e : manifest) {
        if (!e.container) {
            continue;
        }
        if (o.stated && !same_container(o.stated->walls, *e.container)) {
            throw InputError(source, e.line,
                             "container '" + e.container->to_string() +
                                 "' contradicts --container '" + o.stated->walls.to_string() + "'");
        }
        o.stated_per_pack[e.path] =
            StatedContainer{*e.container, "manifest " + source + ":" + std::to_string(e.line)};
    }
}

/// One pack is one seed (reliability finding 8): two rows naming one file (`p1.xyz`,
/// `./p1.xyz`, a link) or byte-identical copies are refused in one line naming both rows,
/// before anything is measured.
void refuse_same_packs(const std::vector<ManifestEntry>& manifest, const std::string& source) {
    std::vector<std::string> paths;
    paths.reserve(manifest.size());
    for (const auto& e : manifest) {
        paths.push_back(e.path);
    }
    const auto same = find_same_pack(paths);
    if (!same) {
        return;
    }
    const ManifestEntry& a = manifest[same->first];
    const ManifestEntry& b = manifest[same->second];
    throw InputError(source, b.line,
                     "rows " + std::to_string(a.line) + " and " + std::to_string(b.line) +
                         " name one pack ('" + a.path + "' and '" + b.path + "', " +
                         (same->same_file ? "the same file" : "byte-identical copies") +
                         "): each pack counts once");
}

/// The thesis' tables of --thesis and --thesis-start (each empty when not given).
ThesisTables read_thesis_tables(const CrossvalOptions& o) {
    ThesisTables thesis;
    if (!o.thesis.empty()) {
        auto in = open_input(o.thesis);
        thesis.results = read_thesis_results(in, o.thesis);
    }
    if (!o.thesis_start.empty()) {
        auto in = open_input(o.thesis_start);
        thesis.starts = read_thesis_starts(in, o.thesis_start);
    }
    return thesis;
}

/// The provenance every crossval output records: the tool, the command, its inputs and the
/// measure parameters.
nlohmann::ordered_json crossval_provenance(const CrossvalOptions& o, const std::string& command) {
    return nlohmann::ordered_json{{"schema_version", kSchemaVersion},
                                  {"tool", "sgmp-compare crossval"},
                                  {"version", sgmp::version()},
                                  {"command", command},
                                  {"manifest", o.manifest},
                                  {"thesis", o.thesis},
                                  {"thesis_start", o.thesis_start},
                                  {"tuning", o.tuning},
                                  {"parameters", cli::measure_parameters(o.common)}};
}

/// With --pictures: renders the chosen packs and puts them in the report (their section
/// after the first, before the verdict matrix; their files beside it); says on stderr what
/// was made or why nothing was.
void add_pictures(const CrossvalOptions& o, const std::vector<ManifestEntry>& manifest,
                  ReportContext& context) {
    auto choices = choose_pictures(manifest);
    for (auto& choice : choices) {
        choice.container = stated_for(choice.path, o.common);
    }
    PictureSet set = render_pictures(choices, o.picture_size);
    // After the first section (which mode stands in for which class), before the matrix.
    const auto at = context.lead_markdown.find("\n## Verdict matrix");
    context.lead_markdown.insert(at == std::string::npos ? context.lead_markdown.size() : at,
                                 pictures_markdown(choices, set));
    if (!set.made) {
        std::cerr << "sgmp-compare: pictures skipped: " << set.note << "\n";
    } else {
        std::cerr << "sgmp-compare: " << set.files.size() << " pictures rendered in " << set.seconds
                  << " s\n";
    }
    context.extra_files = std::move(set.files);
}

int run_crossval(CrossvalOptions& o, const std::string& command) {
    auto manifest_in = open_input(o.manifest);
    const auto manifest = read_manifest(manifest_in, o.manifest);
    refuse_same_packs(manifest, o.manifest);
    const ThesisTables thesis = read_thesis_tables(o);
    std::vector<TunedParameter> tuning;
    if (!o.tuning.empty()) {
        auto in = open_input(o.tuning);
        tuning = read_tuning(in, o.tuning);
    }
    GroupPlan plan;
    try {
        plan = plan_groups(manifest);
    } catch (const std::invalid_argument& error) {
        throw InputError(o.manifest, 0, error.what());
    }
    apply(o.common);
    state_containers(manifest, o.manifest, o.common);

    std::vector<Group> groups;
    for (std::size_t g = 0; g < plan.labels.size(); ++g) {
        groups.push_back(measure_group(plan.labels[g], plan.paths[g], o.common));
    }
    check_counts(manifest, groups, o.manifest);
    plan.plan.sequential = o.sequential;
    if (o.sequential.max_seeds == 0) {  // no --max-seeds: one look at the seeds there are
        plan.plan.sequential->first_look = std::numeric_limits<std::size_t>::max();
        plan.plan.sequential->max_seeds = 1;
    }
    Report report;
    try {
        report = build_report(std::move(groups), plan.plan);
    } catch (const std::invalid_argument& error) {
        throw InputError(o.manifest, 0, error.what());
    }
    withhold_tuned(report, tuning, manifest);
    CrossValidation cv = cross_validate(report, manifest, thesis);
    cv.tuning = tuning;

    const nlohmann::ordered_json provenance = crossval_provenance(o, command);
    ReportContext context;
    context.title = "SGMP against DEM: cross-validation report";
    context.command = command;
    context.parameters = provenance["parameters"];
    context.lead_markdown = render_crossval_markdown(cv);
    context.plots_per_count = true;
    if (o.pictures) {
        add_pictures(o, manifest, context);
    }
    nlohmann::ordered_json crossval = crossval_json(cv);
    crossval["provenance"] = provenance;
    crossval["packs"] = manifest_json(manifest);
    context.extra_files.insert(
        context.extra_files.end(),
        {{"headline.csv", render_headline_csv(cv, command)},
         {"crossval.json", crossval.dump(2) + "\n"},
         {"baseline.json", baseline_json(baseline_entries(report), provenance).dump(2) + "\n"}});
    if (!o.seeds_needed.empty()) {  // before the report: its directory is replaced whole
        const std::string text =
            render_seeds_needed_csv(seeds_needed(report, *report.plan.sequential));
        sgmp::write_file_atomically(o.seeds_needed, o.common.force,
                                    [&](std::ostream& out) { out << text; });
    }
    const auto used = write_report(o.common.out, o.common.force, report, context);
    std::cout << render_headline_text(cv);
    if (!used.plots_made) {
        std::cerr << "sgmp-compare: plots skipped: " << used.plots_note << "\n";
    }
    return 0;
}

struct RegressOptions {
    std::string baseline;
    std::string current;
    bool all = false;
};

int run_regress(const RegressOptions& o) {
    const nlohmann::json baseline_file = read_json(o.baseline);
    const nlohmann::json current_file = read_json(o.current);
    const auto baseline = parse_baseline(baseline_file, o.baseline);
    const auto current = parse_baseline(current_file, o.current);
    check_measured_alike(baseline_file, o.baseline, current_file, o.current);
    if (baseline.empty()) {
        throw InputError(o.baseline, 0, "the baseline has no entries");
    }
    const auto rows = regress(baseline, current);
    std::size_t failed = 0;
    for (const auto& row : rows) {
        failed += row.pass ? 0 : 1;
    }
    if (failed == 0) {
        if (o.all) {
            std::cout << render_regression_table(rows, false);
        }
        std::cout << "regress: all " << rows.size() << " metrics within their tolerances of "
                  << o.baseline << "\n";
        return 0;
    }
    std::cout << render_regression_table(rows, !o.all);
    std::cout << "regress: " << failed << " of " << rows.size()
              << " metrics moved beyond their tolerances of " << o.baseline << "\n";
    return kRegressionFailed;
}

/// The group-sequential options (compare/README.md, "Seeds added until decided").
void add_sequential(CLI::App* cmd, CrossvalOptions& o) {
    cmd->add_option("--max-seeds", o.sequential.max_seeds,
                    "the last look: candidate seeds per mode and count at most (2 to 10000); "
                    "each candidate row is judged look by look as seeds are added, with the "
                    "error rates held at 5 % per side over all looks (default: one look at the "
                    "seeds there are, the fixed-sample test; scripts/run passes 50)")
        ->check(CLI::Range(2, 10000));
    cmd->add_option("--first-look", o.sequential.first_look,
                    "the seeds the first look sees (scripts/run: its --seeds)")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    cmd->add_option("--seed-block", o.sequential.block, "seeds added between looks (1 to 1000)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--seeds-needed", o.seeds_needed,
                    "write CSV 'mode,count,seeds_now,seeds_next,rows': each mode and count with "
                    "rows undecided before the last look, and the seeds of its next look");
}

}  // namespace

CommandRunner register_crossval(CLI::App& app) {
    auto options = std::make_shared<CrossvalOptions>();
    CLI::App* cmd = app.add_subcommand(
        "crossval",
        "cross-validation report: every candidate group of a manifest (e.g. SGMP "
        "arrangements) against every reference group (e.g. DEM friction classes), per particle "
        "count; report.md, report.csv, report.json, headline.csv, crossval.json, baseline.json, "
        "plots/*.svg, index.html; prints the headline table");
    cmd->add_option("--manifest", options->manifest,
                    "CSV 'role,group,count,seed,seconds,path[,container]' listing the packs (role "
                    "candidate or reference; paths relative to the current directory)")
        ->required();
    cmd->add_option("--thesis", options->thesis,
                    "the thesis' results CSV (data/thesis/results.csv) to show beside ours");
    cmd->add_option("--thesis-start", options->thesis_start,
                    "the thesis' starting-pack CSV (data/thesis/starting_packs.csv) to show "
                    "starting heights beside ours");
    cmd->add_option(
        "--tuning", options->tuning,
        "CSV 'group,parameter,value,reference,count,seeds,note' of candidate "
        "parameters tuned against reference packs (data/tuning/tuned_parameters.csv): listed on "
        "every page; comparisons on the seeds they were tuned on are not judged");
    cmd->add_flag("--pictures,!--no-pictures", options->pictures,
                  "add pictures of packs rendered with POV-Ray: at N = 9000 (or the largest "
                  "count with both roles) one seed of each candidate group beside one pack of "
                  "each reference group, cut away so the inside shows (pictures/*.png; a "
                  "missing POV-Ray is a one-line note)");
    cmd->add_option("--picture-size", options->picture_size,
                    "side of each picture in pixels (64 to 2048)")
        ->check(CLI::Range(64, 2048))
        ->capture_default_str();
    add_sequential(cmd, *options);
    add_common(cmd, options->common);
    add_precomputed(cmd, options->common);
    return [options, cmd](const std::string& command) {
        return *cmd ? run_crossval(*options, command) : -1;
    };
}

CommandRunner register_regress(CLI::App& app) {
    auto options = std::make_shared<RegressOptions>();
    CLI::App* cmd = app.add_subcommand(
        "regress",
        "compare a run's metrics (its baseline.json from crossval) with a stored baseline; "
        "exit 0 when every metric is within its tolerance, 3 (and a table of what moved) "
        "when not");
    cmd->add_option("--baseline", options->baseline, "stored baseline (e.g. data/baselines/*.json)")
        ->required();
    cmd->add_option("--current", options->current, "the current run's baseline.json")->required();
    cmd->add_flag("--all", options->all, "print every metric, not only those that moved");
    return [options, cmd](const std::string&) { return *cmd ? run_regress(*options) : -1; };
}

}  // namespace sgmp::compare::cli
