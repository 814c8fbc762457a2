#pragma once
/// @file free_arcs.hpp
/// Which sweep samples are free, as runs of consecutive samples.
///
/// Every obstacle of a sweep is a linear constraint on the unit offset u = (sin θ, cos θ)
/// of a sample: it blocks the sample iff a·u_x + b·u_z < q. For a sphere j and sweep radius
/// s, with δ = c − c_j and D = r + r_j, |δ + s·u|² < D² gives a = 2s·δ_x, b = 2s·δ_z,
/// q = D² − |δ|² − s²; a wall is a constraint with b = 0 (or a = 0).
///
/// Writing a·sin θ + b·cos θ = R cos(θ − ψ) (R = √(a² + b²), ψ = atan2(a, b)), one
/// constraint blocks exactly the open arc θ ∈ (ψ + β, ψ + 2π − β), β = acos(q/R): one run
/// of samples. `free_runs` finds each run's ends from that formula and then settles them by
/// evaluating the constraint at the samples there, so the result is exactly that of testing
/// every sample (`free_runs_by_samples`), at a cost that does not grow with the number of
/// samples. Near tangency (|q/R| within 1e-6 of 1), where rounding could break a run, it
/// tests every sample instead. Consecutive calls on one `FreeRuns` start from the runs of the
/// previous call (an obstacle's run moves by a sample or two per move), settled the same way,
/// so most calls evaluate no trigonometric estimate at all; the result does not depend on it.
#include <cstdint>
#include <vector>

#include "sgmp/engine/sweep_table.hpp"

namespace sgmp::engine {

/// Blocks the sample at unit offset u iff a·u_x + b·u_z < q.
struct Blocker {
    double a = 0.0;
    double b = 0.0;
    double q = 0.0;
};

/// Runs of free samples [start, start + length), ascending, within [0, n) — a run that
/// wraps round angle 0 appears as two (one starting at 0, one ending at n).
struct FreeRuns {
    std::vector<int> start;
    std::vector<int> length;
    int free_count = 0;
    // Scratch space, reused between calls.
    std::vector<std::uint64_t> bits;
    std::vector<std::pair<long, long>> blocked;
    /// Each constraint's blocked run of the last call ([lo, hi] within [lo, lo + n); empty
    /// when hi < lo) and the sample count it was found for: the next call's first guesses.
    std::vector<std::pair<long, long>> guess;
    long guess_positions = 0;
};

/// The free runs of `table`'s samples under `blockers` (see the file comment).
void free_runs(const SweepTable& table, const std::vector<Blocker>& blockers, FreeRuns& out);

/// The same by testing every sample (reference; used near tangency).
void free_runs_by_samples(const SweepTable& table, const std::vector<Blocker>& blockers,
                          FreeRuns& out);

}  // namespace sgmp::engine
