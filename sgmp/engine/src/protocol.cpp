#include "sgmp/engine/protocol.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "sgmp/engine/contact_model.hpp"
#include "sgmp/pack/periodic_images.hpp"

namespace sgmp::engine {

namespace {

/// Cell side: one largest diameter, so a sweep looks at a few cells in each direction.
double cell_side(double max_radius) {
    return 2.0 * max_radius;
}

}  // namespace

Protocol::Protocol(const Container& container, const ProtocolParams& params, double max_radius,
                   double small_max_radius)
    : container_(container),
      params_(params),
      max_radius_(max_radius),
      small_max_radius_(small_max_radius > 0.0 ? small_max_radius : max_radius),
      grid_(container, cell_side(small_max_radius_)) {
    validate(params, 2.0 * max_radius);
    if (small_max_radius_ < max_radius_) {
        if (params.contact != ContactModel::None) {
            throw std::logic_error("Protocol: split grids need the contact model none");
        }
        large_grid_.emplace(container, cell_side(max_radius));
    }
    for (const int n : params.sweep_stages) {
        tables_.emplace_back(n);
    }
    const int largest = params.sweep_stages.back();
    runs_.start.reserve(static_cast<std::size_t>(largest));
    runs_.length.reserve(static_cast<std::size_t>(largest));
    runs_.bits.reserve(static_cast<std::size_t>((largest + 63) / 64));
    runs_.blocked.reserve(64);
    near_.reserve(64);
    local_.reserve(256);
    skin_ = 0.5 * small_max_radius_;
}

void Protocol::settle(const Particle& p) {
    SettledGrid& grid = large_grid_ && p.radius > small_max_radius_ ? *large_grid_ : grid_;
    grid.insert(Sphere{p.center.x(), p.center.y(), p.center.z(), p.radius});
    if (!container_.periodic) {
        return;
    }
    // Its images one period away, wherever a sphere inside the cell (or one moving up to
    // a period's margin outside it before it is wrapped) could reach them: within
    // 2·r_max + the reach of a sweep of the face. The grid keeps points beyond its
    // columns in its edge cells, where the scans near a face find them.
    const double margin = 4.0 * max_radius_;
    for (const Vec3& at : periodic_image_centers(p.center, container_, margin)) {
        grid.insert(Sphere{at.x(), at.y(), at.z(), p.radius});
    }
}

Protocol::Fall Protocol::fall_exact(const Vec3& c, double r) const {
    const Fall small = first_contact_below(grid_, container_, small_max_radius_, c, r);
    if (!large_grid_) {
        return small;
    }
    const Fall large = first_contact_below(*large_grid_, container_, max_radius_, c, r);
    return large.y > small.y ? large : small;
}

DropOutcome Protocol::rest(const Vec3& c, double r, StopReason reason, long moves) const {
    return apply_contact_model(params_.contact, grid_, container_, max_radius_, c, r, reason,
                               moves);
}

void Protocol::rebuild_local(const Vec3& origin, double r, double s) {
    local_.clear();
    const auto gather = [&](const SettledGrid& grid, double grid_max_radius) {
        const Vec3 span = Vec3::Constant(r + grid_max_radius + s + skin_);
        grid.for_each_in_box(origin - span, origin + span, [&](const Sphere& j) {
            const double dx = origin.x() - j.x;
            const double dy = origin.y() - j.y;
            const double dz = origin.z() - j.z;
            const double limit = r + j.r + s + skin_;
            if (dx * dx + dy * dy + dz * dz < limit * limit) {
                local_.push_back(j);
            }
        });
    };
    gather(grid_, small_max_radius_);
    if (large_grid_) {
        gather(*large_grid_, max_radius_);
    }
    local_origin_ = origin;
    local_valid_ = true;
}

// If both ends of the fall lie within the skin of the list's origin, so does every point
// between them, and any sphere touched on the way is within r + r_j + skin of the origin:
// it is in the list. Otherwise the grid is scanned.
Protocol::Fall Protocol::contact_below(const Vec3& c, double r) {
    const double s = 2.0 * r / params_.circle_factor;
    // The skin tests compare squares: where rounding puts their boundary decides only when
    // the list is rebuilt, never which spheres a fall or sweep sees (the reach has s to spare).
    const double skin2 = skin_ * skin_;
    if (!local_valid_ || (c - local_origin_).squaredNorm() > skin2) {
        rebuild_local(c, r, s);
    }
    Fall result{container_.floor + r, true, Sphere{}};
    for (const Sphere& j : local_) {
        const double y = contact_height(c, r, j);
        if (y > result.y) {
            result = Fall{y, false, j};
        }
    }
    if ((Vec3(c.x(), result.y, c.z()) - local_origin_).squaredNorm() <= skin2) {
        return result;
    }
    result = fall_exact(c, r);
    rebuild_local(Vec3(c.x(), result.y, c.z()), r, s);
    return result;
}

Protocol::Fall Protocol::fall(const Vec3& c, double r) {
    Fall hit = contact_below(c, r);
    if (params_.fall == FallMode::Exact || hit.on_floor) {
        return hit;  // the floor is met exactly in both modes: touching it fixes a particle
    }
    // Thesis stepping: k whole steps fit above the contact; the (k+1)-th would collide.
    const double step = params_.fall_step;
    double k = std::floor((c.y() - hit.y) / step);
    double y = c.y() - k * step;
    while (y < hit.y && k > 0.0) {  // rounding of k·step
        k -= 1.0;
        y = c.y() - k * step;
    }
    hit.y = std::max(y, hit.y);
    return hit;
}

void Protocol::gather_near(const Vec3& c, double r, double s) {
    near_.clear();
    for (const Sphere& j : local_) {
        const double dx = c.x() - j.x;
        const double dy = c.y() - j.y;
        const double dz = c.z() - j.z;
        const double d2 = dx * dx + dy * dy + dz * dz;
        const double contact = r + j.r;
        const double q = contact * contact - d2 - s * s;
        const double a = 2.0 * s * dx;
        const double b = 2.0 * s * dz;
        // Some sample can collide only if q > min over u of (a·u_x + b·u_z) = −√(a² + b²).
        if (q >= 0.0 || q * q < a * a + b * b) {
            near_.push_back(Blocker{a, b, q});
        }
    }
    if (params_.walls == WallRule::Block && !container_.periodic) {
        // A wall is one more linear constraint: the sample crosses x_max iff
        // c_x + s·u_x + r > x_max ⟺ −s·u_x < c_x + r − x_max (likewise for the others).
        const auto wall = [&](double a, double b, double q) {
            if (q > -std::abs(a) - std::abs(b)) {
                near_.push_back(Blocker{a, b, q});
            }
        };
        wall(-s, 0.0, c.x() + r - container_.x_max);
        wall(s, 0.0, container_.x_min + r - c.x());
        wall(0.0, -s, c.z() + r - container_.z_max);
        wall(0.0, s, container_.z_min + r - c.z());
    }
}

bool Protocol::free_at(const Vec3& c, double r, double ox, double oz) const {
    const double x = c.x() + ox;
    const double z = c.z() + oz;
    for (const Sphere& j : local_) {
        const double dx = x - j.x;
        const double dy = c.y() - j.y;
        const double dz = z - j.z;
        const double contact = r + j.r;
        if (dx * dx + dy * dy + dz * dz < contact * contact) {
            return false;
        }
    }
    return true;
}

bool Protocol::pick_in_arc(const SweepTable& table, int start, int length, const Vec3& c, double r,
                           double s, const Move& previous, Move& chosen) const {
    const int n = table.positions();
    const bool momentum = params_.momentum > 0.0 && (previous.x != 0.0 || previous.z != 0.0);
    // Indices wrap by one subtraction (start < n, length <= n): no integer division per move.
    const auto wrap = [](int k, int period) { return k >= period ? k - period : k; };
    const int middle_half = wrap(2 * start + length - 1, 2 * n);
    if (momentum) {
        // Aim between the bisector and the previous move; take the arc's closest sample.
        const double m = params_.momentum;
        const double tx = (1.0 - m) * table.x(middle_half) + m * previous.x;
        const double tz = (1.0 - m) * table.z(middle_half) + m * previous.z;
        int best = start;
        double best_dot = -std::numeric_limits<double>::infinity();
        for (int i = 0; i < length; ++i) {
            const int h = 2 * wrap(start + i, n);
            const double dot = tx * table.x(h) + tz * table.z(h);
            if (dot > best_dot) {
                best_dot = dot;
                best = h;
            }
        }
        chosen = Move{table.x(best), table.z(best)};
        return true;
    }
    if (middle_half % 2 == 1) {
        // The bisector lies between two free samples: use it when it is free too.
        const double ox = s * table.x(middle_half);
        const double oz = s * table.z(middle_half);
        const bool wall_ok =
            params_.walls == WallRule::Fix || !crosses_wall(c.x() + ox, c.z() + oz, r);
        if (wall_ok && free_at(c, r, ox, oz)) {
            chosen = Move{table.x(middle_half), table.z(middle_half)};
            return true;
        }
    }
    const int h = 2 * wrap(start + (length - 1) / 2, n);
    chosen = Move{table.x(h), table.z(h)};
    return true;
}

bool Protocol::choose_move(const Vec3& c, double r, double s, const Move& previous, Random& rng,
                           Move& chosen) {
    for (const SweepTable& table : tables_) {
        const int n = table.positions();
        free_runs(table, near_, runs_);
        const int free_count = runs_.free_count;
        std::vector<int>& starts = runs_.start;
        std::vector<int>& lengths = runs_.length;
        if (free_count == 0) {
            continue;  // next, finer stage
        }
        if (free_count == n) {
            // On the very top of a sphere: every direction is downhill alike.
            ++draws_;
            const int k = static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
            chosen = Move{table.x(2 * k), table.z(2 * k)};
            return true;
        }
        if (starts.size() >= 2 && starts.front() == 0 && starts.back() + lengths.back() == n) {
            lengths.back() += lengths.front();
            starts.front() = starts.back();
            lengths.front() = lengths.back();
            starts.pop_back();
            lengths.pop_back();
        }
        std::size_t pick = 0;
        if (params_.gap == GapRule::Random) {
            ++draws_;
            pick = static_cast<std::size_t>(rng.below(starts.size()));
        } else {
            for (std::size_t a = 1; a < starts.size(); ++a) {
                const bool longer = lengths[a] > lengths[pick];
                const bool tie_earlier = lengths[a] == lengths[pick] && starts[a] < starts[pick];
                if (longer || tie_earlier) {
                    pick = a;
                }
            }
        }
        return pick_in_arc(table, starts[pick], lengths[pick], c, r, s, previous, chosen);
    }
    return false;
}

Vec3 Protocol::wall_contact(const Vec3& c, const Vec3& target, double r) const {
    const Vec3 step = target - c;
    double t = 1.0;
    // Parameter at which the sphere reaches each wall it would cross.
    const auto limit = [&](double from, double delta, double bound) {
        if (delta != 0.0) {
            t = std::min(t, std::max(0.0, (bound - from) / delta));
        }
    };
    if (target.x() + r > container_.x_max)
        limit(c.x(), step.x(), container_.x_max - r);
    if (target.x() - r < container_.x_min)
        limit(c.x(), step.x(), container_.x_min + r);
    if (target.z() + r > container_.z_max)
        limit(c.z(), step.z(), container_.z_max - r);
    if (target.z() - r < container_.z_min)
        limit(c.z(), step.z(), container_.z_min + r);
    Vec3 p = c + t * step;
    // Snap onto the wall(s) reached, and never beyond any wall.
    p.x() = std::clamp(p.x(), container_.x_min + r, container_.x_max - r);
    p.z() = std::clamp(p.z(), container_.z_min + r, container_.z_max - r);
    return p;
}

DropOutcome Protocol::drop(const Particle& particle, Random& rng) {
    const double r = particle.radius;
    const double s = 2.0 * r / params_.circle_factor;
    Vec3 c = particle.center;
    local_valid_ = false;  // the grid has changed since the last drop
    // Particles waiting in the arrangement are no obstacles, so a settled particle may have
    // come to rest where this one waits: it is first lifted straight up until it is free.
    c.y() = lowest_free_height(grid_, c.x(), c.z(), r, small_max_radius_, c.y(), lift_scratch_);
    while (large_grid_) {  // free of both grids: lift until neither moves it
        const double lifted =
            lowest_free_height(*large_grid_, c.x(), c.z(), r, max_radius_, c.y(), lift_scratch_);
        if (lifted == c.y()) {
            break;
        }
        c.y() =
            lowest_free_height(grid_, c.x(), c.z(), r, small_max_radius_, lifted, lift_scratch_);
        if (c.y() == lifted) {
            break;
        }
    }
    Move previous{0.0, 0.0};
    long stalled = 0;
    cycle_.forget();
    for (long moves = 0;; ++moves) {
        const Fall hit = fall(c, r);
        stalled = hit.y < c.y() ? 0 : stalled + 1;
        c.y() = hit.y;
        if (stalled == 0) {
            cycle_.forget();
        } else if (const auto end = cycle_.observe(c, previous.x, previous.z, stalled, moves,
                                                   params_.stall_moves, params_.max_moves)) {
            // A repeated stalled state: the moves cycle until a limit (stall_cycle.hpp).
            return rest(end->center, r, end->stalled ? StopReason::Stalled : StopReason::MoveLimit,
                        end->moves);
        }
        if (hit.on_floor) {
            return DropOutcome{c, StopReason::Floor, moves};
        }
        if (params_.walls == WallRule::Fix && touches_wall(c, r)) {
            return DropOutcome{c, StopReason::Wall, moves};
        }
        if (moves > 0 && stalled > params_.stall_moves) {
            return rest(c, r, StopReason::Stalled, moves);
        }
        if (moves >= params_.max_moves) {
            return rest(c, r, StopReason::MoveLimit, moves);
        }
        gather_near(c, r, s);
        Move move{};
        const long draws = draws_;
        if (!choose_move(c, r, s, previous, rng, move)) {
            return rest(c, r, StopReason::NoFreeArc, moves);
        }
        if (draws_ != draws) {
            cycle_.forget();  // a random choice: the states no longer repeat by rule alone
        }
        const Vec3 target(c.x() + s * move.x, c.y(), c.z() + s * move.z);
        if (params_.walls == WallRule::Fix && crosses_wall(target.x(), target.z(), r)) {
            const Vec3 at_wall = wall_contact(c, target, r);
            if (free_at(c, r, at_wall.x() - c.x(), at_wall.z() - c.z())) {
                return DropOutcome{at_wall, StopReason::Wall, moves + 1};
            }
            return rest(c, r, StopReason::NoFreeArc, moves);
        }
        c = container_.wrapped(target);  // periodic sides: back into the cell
        previous = move;
    }
}

DropOutcome drop_onto(const std::vector<Particle>& settled, const Particle& falling,
                      const ProtocolParams& params, std::uint64_t seed,
                      const Container& container) {
    double max_radius = falling.radius;
    for (const Particle& p : settled) {
        max_radius = std::max(max_radius, p.radius);
    }
    Protocol protocol(container, params, max_radius);
    for (const Particle& p : settled) {
        protocol.settle(p);
    }
    Random rng(seed);
    return protocol.drop(falling, rng);
}

}  // namespace sgmp::engine
