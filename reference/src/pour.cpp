#include "sgmp/reference/pour.hpp"
#include "sgmp/reference/pour_parameters.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <limits>

#include "pour_result.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/child_process.hpp"
#include "sgmp/pack/color_bins.hpp"
#include "sgmp/pack/executables.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_overlaps.hpp"
#include "sgmp/pack/sphere_box_volume.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/reference/input_script.hpp"
#include "sgmp/reference/launcher.hpp"
#include "sgmp/reference/start_jitter.hpp"

namespace sgmp::reference {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kTailLines = 25;

/// The directory LIGGGHTS runs in: the caller's (kept) or a temporary (removed).
/// Work directories of earlier runs that were killed (SIGKILL leaves no chance to clean
/// up): named sgmp-reference-PID-XXXXXX, removed when no process PID is running.
void remove_orphaned_work_directories() {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path(), ec)) {
        const std::string name = entry.path().filename().string();
        const std::string prefix = "sgmp-reference-";
        if (name.rfind(prefix, 0) != 0 || !entry.is_directory(ec)) {
            continue;
        }
        const std::size_t dash = name.find('-', prefix.size());
        const std::string pid = name.substr(prefix.size(), dash - prefix.size());
        if (dash == std::string::npos || pid.empty() ||
            pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) {
            continue;
        }
        if (::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) {
            fs::remove_all(entry.path(), ec);
        }
    }
}

class WorkDirectory {
  public:
    explicit WorkDirectory(const fs::path& requested) {
        if (!requested.empty()) {
            path_ = requested;
            std::error_code ec;
            fs::create_directories(path_, ec);
            if (ec || !fs::is_directory(path_)) {
                throw PourError("cannot create work directory " + path_.string() + ": " +
                                ec.message());
            }
            fs::remove(path_ / "final.dump", ec);  // never read a dump of an earlier run
            return;
        }
        remove_orphaned_work_directories();
        try {
            scratch_.emplace("sgmp-reference");
        } catch (const std::runtime_error& e) {
            throw PourError(e.what());
        }
        path_ = scratch_->path();
    }
    [[nodiscard]] const fs::path& path() const { return path_; }

  private:
    fs::path path_;
    std::optional<ScratchDirectory> scratch_;  ///< a temporary, removed with the object
};

/// The pack library's plain write, failing as a PourError.
void write_text(const fs::path& path, const std::string& text) {
    try {
        write_text_file(path, text);
    } catch (const std::runtime_error& e) {
        throw PourError(e.what());
    }
}

/// LIGGGHTS data file with the starting spheres (atom_style granular:
/// id type diameter density x y z) and the simulation box.
std::string start_data(const PourParams& p, const StartPositions& start, double top) {
    const Container container;
    std::string text = "LIGGGHTS data file: SGMP arrangement " + start.name + "\n\n";
    text += std::to_string(start.centers.size()) + " atoms\n1 atom types\n\n";
    text += format_number(container.x_min) + " " + format_number(container.x_max) + " xlo xhi\n";
    text += format_number(container.floor) + " " + format_number(top) + " ylo yhi\n";
    text += format_number(container.z_min) + " " + format_number(container.z_max) + " zlo zhi\n";
    text += "\nAtoms\n\n";
    const std::string d = format_number(p.diameter());
    const std::string rho = format_number(p.density);
    for (std::size_t i = 0; i < start.centers.size(); ++i) {
        const Vec3& c = start.centers[i];
        text += std::to_string(i + 1) + " 1 " + d + " " + rho + " " + format_number(c.x()) + " " +
                format_number(c.y()) + " " + format_number(c.z()) + "\n";
    }
    return text;
}

double start_top_of(const PourRequest& request) {
    if (!request.start) {
        return request.parameters.cloud_top();
    }
    double top = Container{}.floor;
    for (const Vec3& c : request.start->centers) {
        top = std::max(top, c.y());
    }
    return top + request.parameters.diameter() / 2.0;
}

void check_start(const PourRequest& request) {
    if (!request.start) {
        return;
    }
    const auto& centers = request.start->centers;
    if (centers.size() != request.parameters.count) {
        throw PourError("arrangement " + request.start->name + " has " +
                        std::to_string(centers.size()) + " spheres, not " +
                        std::to_string(request.parameters.count));
    }
    const Container container;
    const double r = request.parameters.diameter() / 2.0;
    const double allowed_over_d = request.start->penetration_allowed_over_d;
    const double allowed = allowed_over_d * 2.0 * r + 1e-9 * r;
    const auto short_number = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", value);
        return std::string(text);
    };
    for (std::size_t i = 0; i < centers.size(); ++i) {
        const double penetration = container.penetration(centers[i], r);
        if (penetration > allowed) {
            const std::string rule = allowed_over_d > 0.0
                                         ? " reaches " + short_number(penetration / (2.0 * r)) +
                                               " d through a wall or the floor (at most " +
                                               short_number(allowed_over_d) + " d)"
                                         : " lies outside the container";
            throw PourError("arrangement " + request.start->name + ": sphere " +
                            std::to_string(i + 1) + rule);
        }
    }
}

std::vector<std::string> command_line(const PourRequest& request) {
    const auto liggghts = find_executable(request.liggghts);
    if (!liggghts) {
        throw PourError("'" + request.liggghts +
                        "' not found on PATH: install the Debian package 'liggghts'");
    }
    std::vector<std::string> argv;
    if (request.parameters.ranks > 1) {
        try {
            argv = launch_words(request.launcher, request.parameters.ranks,
                                current_launch_environment());
        } catch (const ParameterError&) {
            throw;  // a bad --launcher: the front end names the option
        } catch (const std::invalid_argument& error) {
            throw PourError(
                std::string(error.what()) +
                (request.launcher == "mpirun" ? ": install the Debian package 'openmpi-bin'" : ""));
        }
    }
    // Line-buffered output: progress arrives as it happens and no message is lost when
    // LIGGGHTS aborts.
    if (const auto stdbuf = find_executable("stdbuf")) {
        argv.insert(argv.end(), {stdbuf->string(), "-oL", "-eL"});
    }
    argv.insert(argv.end(), {liggghts->string(), "-in", "in.pour", "-log", "log.liggghts"});
    return argv;
}

/// Follows the child's output: progress, the marker lines, and the last lines for errors.
struct RunWatch {
    PourLog log;
    std::deque<std::string> tail;
    bool short_insertion = false;
    std::size_t expected = 0;

    void take(const std::string& line, const PourObserver& observer) {
        if (!line.empty()) {
            tail.push_back(line);
            if (tail.size() > kTailLines) {
                tail.pop_front();
            }
        }
        const bool changed = log.take(line);
        if (log.inserted && static_cast<std::size_t>(*log.inserted) < expected) {
            short_insertion = true;
        }
        if (changed && observer) {
            observer(log.progress);
        }
    }
    [[nodiscard]] std::vector<std::string> tail_lines() const { return {tail.begin(), tail.end()}; }
};

std::string ratio_text(double ratio) {
    return format_number(ratio);
}

/// The line that says why: LIGGGHTS' first ERROR, else an output line with a letter in it
/// (a launcher's banner of dashes says nothing): the first such line of a launcher that
/// never started LIGGGHTS (its message leads), the last of LIGGGHTS; else "no output".
std::string failure_reason(const RunWatch& watch, bool launcher) {
    if (!watch.log.first_error.empty()) {
        return watch.log.first_error;
    }
    const auto says = [](const std::string& line) {
        return std::any_of(line.begin(), line.end(),
                           [](unsigned char c) { return std::isalpha(c) != 0; });
    };
    if (launcher) {
        const auto line = std::find_if(watch.tail.begin(), watch.tail.end(), says);
        return line != watch.tail.end() ? *line : "no output";
    }
    const auto line = std::find_if(watch.tail.rbegin(), watch.tail.rend(), says);
    return line != watch.tail.rend() ? *line : "no output";
}

void check_run(const ChildResult& run, const RunWatch& watch, const PourRequest& request) {
    const PourParams& p = request.parameters;
    if (watch.short_insertion) {
        throw PourError("LIGGGHTS inserted only " + std::to_string(*watch.log.inserted) + " of " +
                        std::to_string(p.count) +
                        " spheres: the starting cloud is too dense, lower --cloud-fraction");
    }
    switch (run.end) {
        case ChildEnd::stopped:
            throw PourError("interrupted at step " + std::to_string(watch.log.steps) +
                            ": LIGGGHTS stopped, no pack written");
        case ChildEnd::timed_out:
            throw PourError("timed out after " + format_number(request.timeout->count()) +
                            " s (--timeout) at step " + std::to_string(watch.log.steps) +
                            ": LIGGGHTS stopped, no pack written");
        case ChildEnd::signalled:
            throw PourError("liggghts was killed by signal " + std::to_string(run.signal),
                            watch.tail_lines());
        case ChildEnd::exited:
            break;
    }
    if (run.exit_code != 0) {
        // Under a launcher the child is the launcher: a failure before LIGGGHTS wrote its
        // log (a refused start, as Open MPI's as root) is the launcher's.
        const bool started = !watch.log.liggghts_version.empty();  // its banner was seen
        const bool launcher = p.ranks > 1 && !started;
        const std::string who = launcher ? "the launcher '" + request.launcher + "' (--launcher)"
                                         : std::string("liggghts");
        throw PourError(who + " failed (exit code " + std::to_string(run.exit_code) +
                            "): " + failure_reason(watch, launcher),
                        watch.tail_lines());
    }
    if (!watch.log.inserted || static_cast<std::size_t>(*watch.log.inserted) != p.count) {
        throw PourError("LIGGGHTS did not report the " + std::to_string(p.count) +
                            " spheres it should have placed",
                        watch.tail_lines());
    }
    if (!watch.log.settled || !watch.log.done) {
        throw PourError("LIGGGHTS ended before the pour finished (no result reported)",
                        watch.tail_lines());
    }
    if (!*watch.log.settled) {
        throw PourError("not settled within the step cap of " +
                        std::to_string(watch.log.step_cap.value_or(0)) + " steps (" +
                        format_number(p.max_time) +
                        " s simulated): KE_trans/(m g d) = " + ratio_text(watch.log.ke_ratio) +
                        ", threshold " + format_number(p.settle_threshold));
    }
}

void record(Metadata& m, const PourRequest& request, const PourLog& log, const PourResult& r) {
    const PourParams& p = request.parameters;
    const LiggghtsSeeds seeds = liggghts_seeds(p.seed);
    m.set("generator", "liggghts");
    m.set("version", version());
    m.set("liggghts_version", log.liggghts_version.empty() ? "unknown" : log.liggghts_version);
    record_pour_parameters(p, "count", m);
    m.set_number("diameter", p.diameter());
    record_pour_parameters(p, "identity", m);
    m.set("start", request.start ? "arrangement" : "cloud");
    if (request.start) {
        m.set("arrangement", request.start->name);
    }
    record_pour_parameters(p, "start", m);
    m.set("contact_model", std::string("hertz tangential_history rolling_friction_cdt") +
                               (p.tangential_damping ? "" : " no_tangential_damping"));
    record_pour_parameters(p, "material", m);
    m.set_number("metres_per_unit", kMetresPerUnit);
    m.set_number("timestep_s", log.timestep.value_or(0.0));
    m.set_number("rayleigh_time_s", log.rayleigh_time.value_or(0.0));
    record_pour_parameters(p, "numerics", m);
    m.set_integer("step_cap", log.step_cap.value_or(0));
    m.set_integer("steps", log.steps);
    m.set_number("settling_measure", log.ke_ratio);
    m.set_number("max_overlap_over_d", r.max_overlap_over_d);
    m.set_number("max_wall_penetration_over_d", r.max_wall_penetration_over_d);
    m.set_number("phi_control_volume", r.phi_control_volume);
    record_pour_parameters(p, "parallel", m);
    m.set("processor_grid", processor_grid(p));
    m.set("liggghts_seeds", std::to_string(seeds.particle_template) + " " +
                                std::to_string(seeds.distribution) + " " +
                                std::to_string(seeds.insertion));
    m.set_number("wall_seconds", std::round(r.wall_seconds * 100.0) / 100.0);
    m.set("container", Container{}.to_string());
    if (p.is_blend()) {
        std::string counts;
        for (const PourSpecies& s : p.species()) {
            counts += (counts.empty() ? "" : ",") + std::to_string(s.count);
        }
        m.set("species_counts", counts);
    }
}

}  // namespace

PourResult pour(const PourRequest& request, const PourObserver& observer) {
    const PourParams& p = request.parameters;
    try {
        p.validate();
    } catch (const std::invalid_argument& e) {
        throw PourError(e.what());
    }
    check_start(request);
    const std::vector<std::string> argv = command_line(request);
    std::optional<StartPositions> start = request.start;
    if (start) {
        Random jitter_random(p.seed ^ 0x7177E2ULL);  // apart from the other seeds
        jitter_horizontally(start->centers, p.diameter() / 2.0, p.start_jitter * p.diameter(),
                            Container{}, jitter_random);
    }
    const double start_top = start_top_of(request);

    WorkDirectory work(request.work_directory);
    write_text(work.path() / "in.pour", pour_script(p, start_top));
    if (request.start) {
        write_text(work.path() / "start.data",
                   start_data(p, *start, domain_top(start_top, p.diameter(), p.is_blend())));
    }

    RunWatch watch;
    watch.expected = p.count;
    ChildOptions options;
    options.argv = argv;
    options.working_directory = work.path();
    options.timeout = request.timeout;
    options.should_stop = [&] {
        return watch.short_insertion || (request.should_stop && request.should_stop());
    };
    const ChildResult run =
        run_child(options, [&](const std::string& line) { watch.take(line, observer); });
    check_run(run, watch, request);

    PourResult result;
    result.pack = detail::read_final(work.path() / "final.dump", p);
    result.wall_seconds = run.wall_seconds;
    result.steps = watch.log.steps;
    result.ke_ratio = watch.log.ke_ratio;
    const double d = p.diameter();
    const OverlapCount overlaps = count_overlaps(result.pack.particles, p.container(), 0.0);
    result.max_overlap_over_d = overlaps.max_pair / d;
    result.max_wall_penetration_over_d = overlaps.max_wall / d;
    result.phi_control_volume = packing_fraction(result.pack, control_volume());
    detail::check_settled(result);
    if (request.start && request.start->colors.size() == p.count) {
        for (std::size_t i = 0; i < p.count; ++i) {
            result.pack.particles[i].color = request.start->colors[i];
        }
    } else {
        Random color_random(p.seed ^ 0xC01005ULL);  // apart from the LIGGGHTS seeds
        const std::vector<int> bins = draw_colors(result.pack.particles.size(), color_random);
        for (std::size_t i = 0; i < bins.size(); ++i) {
            result.pack.particles[i].color = bins[i];
        }
    }
    record(result.pack.metadata, request, watch.log, result);
    return result;
}

}  // namespace sgmp::reference
