#include "command_support.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/pack_content_error.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>

#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/metrics/parallel.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/report/json_input.hpp"
#include "sgmp/report/precomputed.hpp"

namespace fs = std::filesystem;

namespace sgmp::compare::cli {

namespace {

/// A measured pack's file (its metrics.json or a curve's CSV), at most kMaxMetricsBytes.
std::string read_text(const std::string& path) {
    return read_bounded_file(path, kMaxMetricsBytes, "a measured pack's file");
}

PackSummary read_measured(const std::string& path, const CommonOptions& o) {
    const auto metrics = parse_json_input<nlohmann::ordered_json>(read_text(path), path);
    return summary_from_measure(
        path, metrics,
        read_text(
            sibling_csv(path, metrics::metric_with(metrics::MetricRole::PairCorrelation).name)),
        read_text(sibling_csv(path, "phi_y")), measure_parameters(o));
}

/// FNV-1a over a file's bytes; nullopt when it cannot be read.
std::optional<std::uint64_t> content_hash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    std::uint64_t hash = 14695981039346656037ull;
    std::vector<char> chunk(1 << 16);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        for (std::size_t i = 0; i < got; ++i) {
            hash = (hash ^ static_cast<unsigned char>(chunk[i])) * 1099511628211ull;
        }
    }
    return in.bad() ? std::nullopt : std::optional(hash);
}

bool same_bytes(const std::string& a, const std::string& b) {
    std::ifstream in_a(a, std::ios::binary);
    std::ifstream in_b(b, std::ios::binary);
    return in_a && in_b &&
           std::equal(std::istreambuf_iterator<char>(in_a), std::istreambuf_iterator<char>(),
                      std::istreambuf_iterator<char>(in_b), std::istreambuf_iterator<char>());
}

}  // namespace

std::optional<SamePack> find_same_pack(const std::vector<std::string>& paths) {
    std::map<std::string, std::size_t> by_path;  // canonical path -> first entry
    std::map<std::uintmax_t, std::vector<std::size_t>> by_size;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        std::error_code error;
        const std::string key = fs::weakly_canonical(paths[i], error).string();
        const auto [it, fresh] = by_path.emplace(error ? paths[i] : key, i);
        if (!fresh) {
            return SamePack{it->second, i, true};
        }
        const auto size = fs::file_size(paths[i], error);
        if (!error) {
            by_size[size].push_back(i);
        }
    }
    std::optional<SamePack> found;
    for (const auto& [size, entries] : by_size) {
        if (entries.size() < 2) {
            continue;  // a copy has the size of its original
        }
        std::map<std::uint64_t, std::vector<std::size_t>> by_hash;
        for (const std::size_t i : entries) {
            const auto hash = content_hash(paths[i]);
            if (!hash) {
                continue;
            }
            for (const std::size_t earlier : by_hash[*hash]) {
                if (same_bytes(paths[earlier], paths[i]) &&
                    (!found || std::pair(i, earlier) < std::pair(found->second, found->first))) {
                    found = SamePack{earlier, i, false};
                }
            }
            by_hash[*hash].push_back(i);
        }
    }
    return found;
}

void add_precomputed(CLI::App* command, CommonOptions& o) {
    command->add_option("--metrics", o.metrics,
                        "batch summaries (sgmp batch --measure) whose rows stand for the packs "
                        "they name: those packs are not read again (scalar metrics only; "
                        "curves and Q6 are then not measured: inconclusive)");
}

void add_common(CLI::App* command, CommonOptions& o) {
    command->add_option("--out", o.out, "output directory (created atomically)")->required();
    command->add_flag("--force", o.force, "replace an existing output directory");
    command
        ->add_option("--region", o.region,
                     "box measured: xlo xhi ylo yhi zlo zhi (length units; default the control "
                     "volume -0.5 0.5 -0.5 0.5 -0.5 0.5, times the file's length_scale when it "
                     "has one); must lie inside the container")
        ->expected(6);
    command->add_option("--slab", o.measure.slab_thickness,
                        "phi(y) slab thickness, in mean diameters d (default 1)");
    command->add_option("--gr-bin", o.measure.gr_bin_width, "g(r) bin width, in d (default 0.02)");
    command->add_option("--gr-range", o.measure.gr_range, "g(r) range, in d (default 5)");
    command->add_flag("--gr-thesis", o.measure.gr_thesis,
                      "also the thesis' single-particle RDF (eq. 3.7-3.10), column g_thesis");
    command->add_flag("--gr-container-space", o.measure.gr_container_space,
                      "g(r) shells and density in the container up to the top sphere (the "
                      "5 literally) instead of the space of centres (container shrunk by d/2)");
    command
        ->add_option("--gr-density", o.gr_density,
                     "g(r)'s density: 'neighbours' (default; the density the origins see out to "
                     "the range, so g -> 1 far from contact for any pack shape) or 'space' "
                     "(N / volume of the g(r) space)")
        ->check(CLI::IsMember({"neighbours", "space"}));
    command->add_flag("!--no-voronoi", o.measure.voronoi,
                      "skip the Voronoi local packing fraction (voro++; its own stage)");
    command->add_option("--q6-cutoff", o.measure.q6_cutoff,
                        "Q6 bonds join centres within this x (ri + rj) (default 1.2)");
    command->add_option("--overlap-floor", o.measure.overlap_floor,
                        "overlaps deeper than this x d are counted (default 1e-9)");
    command
        ->add_option("--threads", o.threads,
                     "worker threads, at most 256 (default: the CPUs the process may use; results "
                     "do not depend on it)")
        ->check([](const std::string& text) {
            return finite_range_rule(text, 0.0, 256.0, "[0, 256] (0: all cores)");
        });
    command->add_flag("--timings", o.timings, "print the seconds of each stage to stderr");
    // Short: CLI11 does not wrap, and --help lines stay under 100 columns.
    o.container_option =
        command->add_option("--container", o.container,
                            "walls \"x_min x_max z_min z_max floor\" (header key container)");
}

void apply(CommonOptions& o) {
    if (o.container_option != nullptr && o.container_option->count() > 0) {
        try {
            o.stated = StatedContainer{Container::parse(o.container), "--container"};
        } catch (const ParameterError& error) {  // the header's parser and rule
            throw UsageError(::sgmp::cli::usage_message(error));
        }
    }
    o.measure.gr_density = o.gr_density == "space" ? RdfDensity::Space : RdfDensity::Neighbours;
    if (!o.region.empty()) {
        o.measure.region = Box{Vec3(o.region[0], o.region[2], o.region[4]),
                               Vec3(o.region[1], o.region[3], o.region[5])};
    }
    o.measure.threads = o.threads;  // passed to every measurement, never set globally
    validate(o.measure);
    // A directory may be typed with a trailing slash ("--out report/").
    while (o.out.size() > 1 && o.out.back() == '/') {
        o.out.pop_back();
    }
    try {
        check_writable(o.out, o.force);
    } catch (const std::runtime_error& error) {
        throw UsageError(std::string("--out ") + error.what());
    }
    for (const auto& path : o.metrics) {
        const std::string text = ::sgmp::cli::while_doing("reading the summary " + path, [&] {
            return read_bounded_file(path, kMaxSummaryBytes, "a batch summary");
        });
        for (auto& [pack, summary] : summaries_from_batch(text, path)) {
            o.precomputed[fs::path(pack).lexically_normal().string()] = std::move(summary);
        }
    }
}

std::string command_line(int argc, char** argv) {
    std::string line = "sgmp-compare";
    for (int i = 1; i < argc; ++i) {
        line += " ";
        line += argv[i];
    }
    return line;
}

std::optional<StatedContainer> stated_for(const std::string& path, const CommonOptions& o) {
    const auto found = o.stated_per_pack.find(path);
    return found != o.stated_per_pack.end() ? std::optional(found->second) : o.stated;
}

Pack read_pack(const std::string& path, const std::optional<StatedContainer>& stated,
               unsigned threads) {
    ReadOptions options;
    options.threads = resolved_threads(threads);  // parsed on the measurement's threads
    options.container = stated;
    PackRead read = ::sgmp::cli::while_doing("reading the pack " + path,
                                             [&] { return read_pack_file(path, options); });
    for (const std::string& warning : read.warnings) {
        std::cerr << "sgmp-compare: warning: " << path << ": " << warning << "\n";
    }
    Pack pack = std::move(read.pack);
    if (pack.particles.empty()) {
        throw InputError(path, 0, "the pack has no particles");
    }
    try {
        (void)container_of(pack);
    } catch (const std::invalid_argument& error) {
        throw InputError(path, 2, error.what());  // the header line holds the container key
    }
    return pack;
}

Measurement measure_pack(const std::string& path, const Pack& pack, const CommonOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    Measurement m;
    try {
        m = ::sgmp::cli::while_doing("measuring the pack " + path,
                                     [&] { return measure(pack, o.measure); });
    } catch (const PackContentError& error) {  // the file's fault: status 1
        throw InputError(path, 0, error.what());
    } catch (const ParameterError& error) {  // an option's: status 2
        throw UsageError(path + ": " + ::sgmp::cli::usage_message(error));
    } catch (const std::invalid_argument& error) {
        throw UsageError(path + ": " + error.what());
    }
    if (o.timings) {
        const auto& t = last_stage_times();
        const double total =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cerr << "timings " << path << ": index " << t.index << " s, phi " << t.phi
                  << " s, phi(y) " << t.phi_profile << " s, overlaps " << t.overlaps
                  << " s, Z(delta)+g(r)+Q6 " << t.local << " s, per species " << t.species
                  << " s, Voronoi " << t.voronoi << " s, total " << total << " s\n";
    }
    return m;
}

std::string stem_of(const std::string& path) {
    fs::path p(path);
    if (p.extension() == ".gz") {
        p = p.stem();
    }
    return p.stem().string();
}

Group measure_group(const std::string& label, const std::vector<std::string>& packs,
                    const CommonOptions& o) {
    Group group;
    group.label = label;
    for (const auto& path : packs) {
        if (is_metrics_json(path)) {
            group.packs.push_back(read_measured(path, o));
            continue;
        }
        if (const auto found = o.precomputed.find(fs::path(path).lexically_normal().string());
            found != o.precomputed.end()) {
            group.packs.push_back(found->second);
            continue;
        }
        const Pack pack = read_pack(path, stated_for(path, o), o.threads);
        group.packs.push_back(summarise(path, pack, measure_pack(path, pack, o)));
    }
    return group;
}

nlohmann::ordered_json measure_parameters(const CommonOptions& o) {
    return provenance("", Pack{}, o.measure)["parameters"];
}

}  // namespace sgmp::compare::cli
