#pragma once
/// @file stall_cycle.hpp
/// Jumping over the repeated moves of a stalled particle, with the same result.
///
/// While a particle stalls (its fall finds no whole step below it, so it does not fall),
/// each sweep-and-move cycle maps its state — centre c and previous move u — to the next by
/// a fixed rule: the bed does not change during a drop, and nothing else enters unless a
/// random choice is drawn. So when a state repeats exactly (bit for bit) with no draw in
/// between, the states cycle with that period p from then on, every cycle passes the same
/// floor, wall and free-arc tests, and only the counters move: the drop ends at the first
/// k ≥ 0 with stalled + k > stall_moves (it rests, `Stalled`) or moves + k ≥ max_moves
/// (`MoveLimit`), at the state k cycles on. With the thesis' step fall most particles end
/// this way, on a two-state cycle reached after about six stalled moves, while
/// stall_moves = 50.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sgmp/pack/geometry.hpp"

namespace sgmp::engine {

class StallCycle {
  public:
    /// Where and how a cycling drop ends.
    struct End {
        Vec3 center;
        bool stalled;  ///< true: stall_moves exceeded; false: max_moves reached
        long moves;
    };

    /// Forgets the states seen (the particle fell, or a random choice was drawn).
    void forget() { states_.clear(); }

    /// Records the state of a stalled cycle (after its fall, before its tests) and, when it
    /// repeats an earlier state, returns where the drop ends.
    std::optional<End> observe(const Vec3& c, double previous_x, double previous_z, long stalled,
                               long moves, long stall_moves, long max_moves) {
        const State now{bits(c.x()), bits(c.y()), bits(c.z()), bits(previous_x), bits(previous_z)};
        for (std::size_t j = 0; j < states_.size(); ++j) {
            if (states_[j] == now) {
                const long period = static_cast<long>(states_.size() - j);
                const long to_stall = std::max(0L, stall_moves + 1 - stalled);
                const long to_limit = std::max(0L, max_moves - moves);
                const long k = std::min(to_stall, to_limit);
                const State& at = states_[j + static_cast<std::size_t>(k % period)];
                return End{Vec3(std::bit_cast<double>(at.x), std::bit_cast<double>(at.y),
                                std::bit_cast<double>(at.z)),
                           to_stall <= to_limit, moves + k};
            }
        }
        states_.push_back(now);
        return std::nullopt;
    }

  private:
    struct State {
        std::uint64_t x, y, z, px, pz;
        bool operator==(const State&) const = default;
    };
    static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }
    std::vector<State> states_;
};

}  // namespace sgmp::engine
