#pragma once
/// @file protocol.hpp
/// The Spin Gap Move Protocol (thesis chapter 4) for one particle at a time, against the
/// particles settled so far. A drop repeats four phases until the particle stops:
///
/// 1. **Fall** straight down to the first contact below: the highest of the floor
///    (y = floor + r) and, for every settled sphere j with horizontal centre distance
///    h < r + r_j, the contact height y_j + √((r + r_j)² − h²). `exact` ends there,
///    touching; `step` ends at the last multiple of the fall step above it, as the thesis'
///    stepping would (a colliding step is never taken, so no overlap is ever created).
/// 2. **Sweep**: the particle is tried at n positions on a horizontal circle of radius
///    s = d / F around its centre (same height), at the angles of the precomputed offset
///    table (sweep_table.hpp). A position is free when it overlaps no settled sphere
///    (overlap: |c − c_j|² < (r + r_j)²; touching is free) — and, with the `block` wall
///    rule, crosses no wall. With several stages (e.g. 8,120,720) the next stage is swept
///    only when the previous one found no free position at all.
/// 3. **Gap selection**: runs of consecutive free positions form free arcs (the circle
///    wraps). The largest arc (or, with `random`, a random arc) is bisected.
/// 4. **Move** to the point of the circle at the bisector (the half-step entry of the
///    offset table; when that point itself is not free — possible only between two free
///    samples — the arc's middle sample is used). Then fall again.
///
/// A particle the protocol leaves resting is handed to the contact model of `--contact`
/// (contact_model.hpp: none, settle, roll).
///
/// Stopping rules (thesis §4.2): touching the floor fixes a particle; with the `fix` wall
/// rule a move that would cross a wall ends where the particle touches the wall, and fixes
/// it; a sweep with no free position (in every stage) leaves the particle resting where
/// its last fall put it. Choices where the thesis is silent:
///  - every position free (the particle sits on the very top of a sphere, closer than s/2
///    to its axis): the move goes to a uniformly random sample;
///  - the move length is the sweep radius s (to the circle point at the bisector);
///  - a falling particle is not stopped by a wall it slides along; only a sweep move that
///    reaches a wall fixes it (a particle already touching a wall after a fall is fixed);
///  - only settled particles are obstacles; particles waiting in the starting arrangement
///    are not. A particle whose starting place a settled one has taken meanwhile is first
///    lifted straight up to the lowest height where it is free, then falls as usual;
///  - with the step fall the sweep is made at the last free step, less than a step above
///    the contact (sweeping at the colliding step, one step lower, would leave almost every
///    particle stuck on its first contact: a d/50 sideways move cannot undo a 0.001 overlap
///    near the top of a sphere, giving φ ≈ 0.45 where the thesis reports ≈ 0.59);
///  - a particle that makes `stall_moves` consecutive moves without falling at all rests
///    (a step fall can otherwise leave a particle shuffling forever between supports);
///  - `max_moves` bounds the cycles per particle (it rests after its last fall);
///  - particles are dropped one at a time in id order (the arrangement's drop order); the
///    thesis' 10-particle lower neighbour list is replaced by the exact column scan below,
///    so `lower_neighbours` never changes a result (a list that misses a sphere is one
///    likely cause of the overlaps the thesis reports in §5.4).
///
/// Neighbour search uses a `SettledGrid` (cells of one largest diameter): a long fall
/// scans only the column of cells below the particle, top down, stopping once no lower
/// cell can hold a higher contact. Around the moving particle a local list holds every
/// settled sphere within r + r_max + s + skin (skin = r_max/2) of where it was built; the
/// sweep and short falls use it until the particle has moved more than the skin. Work per
/// drop does not grow with N, and the drop loop allocates nothing once buffers are warm.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sgmp/engine/contact_search.hpp"
#include "sgmp/engine/free_arcs.hpp"
#include "sgmp/engine/protocol_params.hpp"
#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/engine/stall_cycle.hpp"
#include "sgmp/engine/sweep_table.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"
#include "sgmp/pack/random.hpp"

namespace sgmp::engine {

/// Why a particle stopped.
enum class StopReason {
    Floor,      ///< touched the floor
    Wall,       ///< a move reached a side wall (fix rule)
    NoFreeArc,  ///< a sweep found no free position: it rests
    Stalled,    ///< stall_moves consecutive moves without falling: it rests
    MoveLimit,  ///< reached max_moves cycles: it rests
};

struct DropOutcome {
    Vec3 center = Vec3::Zero();
    StopReason reason = StopReason::NoFreeArc;
    /// Sweep-and-move cycles the particle made.
    long moves = 0;
};

class Protocol {
  public:
    /// `max_radius`: the largest radius of any particle that will settle (sets the grid and
    /// the neighbour reach). Parameters must be valid (see `validate`).
    ///
    /// `small_max_radius` > 0 (a wide blend, contact model none: the largest radius at or
    /// below max_radius / 2) keeps the small spheres in a grid of their own, with cells and
    /// reaches sized for them, and the few larger ones in another: every query looks in
    /// both, each within its own reach, so a fine particle no longer scans cells one coarse
    /// diameter wide. The spheres found, hence the pack, are the same as with one grid up
    /// to the order in which exact ties are met.
    Protocol(const Container& container, const ProtocolParams& params, double max_radius,
             double small_max_radius = 0.0);

    /// Runs the protocol for `particle` from its current centre against the settled
    /// particles; returns where it stops. Does not settle it (call `settle`).
    DropOutcome drop(const Particle& particle, Random& rng);
    /// Adds a particle at its final position; it becomes an obstacle for later drops.
    void settle(const Particle& particle);
    [[nodiscard]] std::size_t settled_count() const {
        return grid_.size() + (large_grid_ ? large_grid_->size() : 0);
    }

  private:
    /// The first contact of a fall (contact_search.hpp).
    using Fall = FirstContact;
    struct Move {
        double x;  ///< unit offset
        double z;
    };

    [[nodiscard]] Fall fall_exact(const Vec3& c, double r) const;
    /// First contact below using the local list (falls back to the grid when the fall
    /// leaves the list's skin).
    [[nodiscard]] Fall contact_below(const Vec3& c, double r);
    [[nodiscard]] Fall fall(const Vec3& c, double r);
    /// Local (Verlet) list: every settled sphere within r + r_max + s + skin of `origin`.
    void rebuild_local(const Vec3& origin, double r, double s);
    void gather_near(const Vec3& c, double r, double s);
    /// True when the centre displaced by (ox, oz) from c overlaps no settled sphere.
    [[nodiscard]] bool free_at(const Vec3& c, double r, double ox, double oz) const;
    // (The wall tests are defined here so that the drop loop inlines them: once per move.
    // Periodic sides have no walls.)
    [[nodiscard]] bool crosses_wall(double x, double z, double r) const {
        return !container_.periodic && (x - r < container_.x_min || x + r > container_.x_max ||
                                        z - r < container_.z_min || z + r > container_.z_max);
    }
    [[nodiscard]] bool touches_wall(const Vec3& c, double r) const {
        return !container_.periodic &&
               (c.x() - r <= container_.x_min || c.x() + r >= container_.x_max ||
                c.z() - r <= container_.z_min || c.z() + r >= container_.z_max);
    }
    /// Chooses the move direction; false when no stage has a free position.
    bool choose_move(const Vec3& c, double r, double s, const Move& previous, Random& rng,
                     Move& chosen);
    bool pick_in_arc(const SweepTable& table, int start, int length, const Vec3& c, double r,
                     double s, const Move& previous, Move& chosen) const;
    /// Where a move from c toward `target` first touches a wall (coordinates snapped).
    [[nodiscard]] Vec3 wall_contact(const Vec3& c, const Vec3& target, double r) const;
    /// A resting particle goes to the contact model (contact_model.hpp).
    [[nodiscard]] DropOutcome rest(const Vec3& c, double r, StopReason reason, long moves) const;

    Container container_;
    ProtocolParams params_;
    double max_radius_;
    double small_max_radius_;  ///< of grid_'s spheres: max_radius_ unless split
    SettledGrid grid_;
    std::optional<SettledGrid> large_grid_;  ///< a wide blend's spheres above small_max_radius_
    std::vector<SweepTable> tables_;
    // Scratch buffers reused by every drop (no allocation in the drop loop).
    /// Obstacles of the current sweep as linear constraints (free_arcs.hpp).
    std::vector<Blocker> near_;
    FreeRuns runs_;
    std::vector<Sphere> local_;
    Vec3 local_origin_ = Vec3::Zero();
    bool local_valid_ = false;
    double skin_ = 0.0;
    std::vector<std::pair<double, double>> lift_scratch_;
    /// Stalled states of the current drop, to jump over their cycle (stall_cycle.hpp).
    StallCycle cycle_;
    long draws_ = 0;  ///< random choices drawn by choose_move so far
};

/// Hand-made beds (tests, figures): drops `falling` from its centre onto `settled` (all
/// fixed where they are) in `container` and returns where the protocol stops it. Random
/// choices come from Random(seed).
DropOutcome drop_onto(const std::vector<Particle>& settled, const Particle& falling,
                      const ProtocolParams& params = {}, std::uint64_t seed = 1,
                      const Container& container = {});

}  // namespace sgmp::engine
