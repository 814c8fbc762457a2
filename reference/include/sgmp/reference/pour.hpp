#pragma once
/// @file pour.hpp
/// One LIGGGHTS pour, from parameters to a settled pack.
///
/// Writes the input script (and, for an arrangement start, start.data) into a work
/// directory, runs `liggghts -in in.pour` (or, on K ranks, `mpirun -np K liggghts`, `srun -n
/// K liggghts` or any launcher, with a processor grid of the container's shape), follows
/// its progress, and reads the final dump back
/// into a Pack with provenance. Every failure throws PourError; nothing is printed.

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sgmp/pack/pack.hpp"
#include "sgmp/reference/pour_params.hpp"
#include "sgmp/reference/progress.hpp"

namespace sgmp::reference {

/// A pour that failed. `what()` is one line; `log_tail` holds the last lines LIGGGHTS
/// printed when they help (empty otherwise).
class PourError : public std::runtime_error {
  public:
    PourError(const std::string& message, std::vector<std::string> log_tail = {})
        : std::runtime_error(message), log_tail_(std::move(log_tail)) {}
    [[nodiscard]] const std::vector<std::string>& log_tail() const { return log_tail_; }

  private:
    std::vector<std::string> log_tail_;
};

/// Starting positions given by the caller (an SGMP arrangement), project units. Sphere i
/// gets id i + 1 and keeps colour `colors[i]` when colours are given.
struct StartPositions {
    std::string name;
    std::vector<Vec3> centers;
    std::vector<int> colors;  ///< empty: colours drawn from the ten bins
    /// How far a start sphere may reach through a wall or the floor, over d: 0 (up to
    /// rounding) for an SGMP arrangement; a settled pour's bound when the start is a pack
    /// file, whose DEM pours keep their soft wall contacts (up to 0.006 d in the stored set).
    double penetration_allowed_over_d = 0.0;
};

struct PourRequest {
    PourParams parameters;
    std::optional<StartPositions> start;   ///< empty: a loose random cloud
    std::filesystem::path work_directory;  ///< empty: a temporary, removed afterwards
    std::string liggghts = "liggghts";     ///< program name or path
    /// How ranks > 1 are started: mpirun, srun or a command line with {np} (launcher.hpp).
    std::string launcher = "mpirun";
    std::optional<std::chrono::duration<double>> timeout;
    std::function<bool()> should_stop;  ///< e.g. set by SIGINT
};

/// Bounds a settled pour must keep, in diameters d. The Hertz contacts are soft, so
/// spheres overlap and press into the walls a little: the stored reference set shows at
/// most 0.0074 d between spheres and 0.0059 d at a wall. The bounds are about seven times
/// that, far below what a blow-up or a corrupt dump gives (up to a whole d).
inline constexpr double kMaxSettledOverlapOverD = 0.05;
inline constexpr double kMaxSettledPenetrationOverD = 0.05;

struct PourResult {
    Pack pack;
    double wall_seconds = 0.0;
    double max_overlap_over_d = 0.0;
    double max_wall_penetration_over_d = 0.0;
    double phi_control_volume = 0.0;
    std::int64_t steps = 0;
    double ke_ratio = 0.0;
};

using PourObserver = std::function<void(const PourProgress&)>;

PourResult pour(const PourRequest& request, const PourObserver& observer = {});

}  // namespace sgmp::reference
