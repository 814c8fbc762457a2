#pragma once
/// @file progress.hpp
/// Following a pour: the "SGMP-" marker lines the input script prints, and the state
/// they describe.

#include <cstdint>
#include <optional>
#include <string>

namespace sgmp::reference {

enum class PourPhase { starting, falling, settling, finished };

/// What the pour reports to its observer.
struct PourProgress {
    PourPhase phase = PourPhase::starting;
    std::int64_t step = 0;
    std::int64_t phase_steps = 0;  ///< fall steps while falling, the step cap while settling
    double ke_ratio = 0.0;         ///< KE_trans per particle / (m g d)
    double threshold = 0.0;        ///< settled below this
};

/// What the marker lines have told so far.
struct PourLog {
    std::string liggghts_version;  ///< e.g. "3.8.0", from the banner line
    std::optional<double> timestep;
    std::optional<double> rayleigh_time;
    std::optional<std::int64_t> step_cap;
    std::optional<std::int64_t> inserted;
    std::optional<bool> settled;
    std::int64_t steps = 0;
    double ke_ratio = 0.0;
    bool done = false;
    PourProgress progress;
    std::string first_error;  ///< first line starting "ERROR", if any

    /// Takes one output line; returns true when it changed `progress`.
    bool take(const std::string& line);
};

}  // namespace sgmp::reference
