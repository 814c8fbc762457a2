// The engine's speed work must not change a single result: packs pinned bit for bit, and the
// stalled-cycle jump checked against stepping the drop loop's counters one move at a time.
#include <boost/test/unit_test.hpp>

#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/stall_cycle.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

/// FNV-1a (64 bit) over the little-endian bytes of every centre's x, y, z in id order.
std::uint64_t centers_hash(const Pack& pack) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const Particle& p : pack.particles) {
        for (const double v : {p.center.x(), p.center.y(), p.center.z()}) {
            const auto bits = std::bit_cast<std::uint64_t>(v);
            for (int b = 0; b < 8; ++b) {
                h ^= (bits >> (8 * b)) & 0xffU;
                h *= 0x100000001b3ULL;
            }
        }
    }
    return h;
}

struct Pinned {
    Arrangement arrangement;
    std::size_t count;
    FallMode fall;
    ContactModel contact;
    std::uint64_t seed;
    std::uint64_t hash;
    long long moves;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(pinned_packs)

// The hashes and move counts are those of the packs written by the engine before its speed
// work (grid storage, free-run guesses, the stalled-cycle jump), read back from the pack
// files' shortest round-trip text by an independent script (numpy-free Python, struct.pack).
BOOST_AUTO_TEST_CASE(packs_keep_their_centers_bit_for_bit) {
    const std::vector<Pinned> pinned = {
        {Arrangement::SingleColumn, 600, FallMode::Exact, ContactModel::None, 1,
         0xd387dd7815106ecaULL, 90606},
        {Arrangement::SmallDense, 1002, FallMode::Exact, ContactModel::Settle, 2,
         0xf798a3042f79c6b9ULL, 36964},
        {Arrangement::LargeDense, 1002, FallMode::Exact, ContactModel::Roll, 3,
         0x80a8b00c3de5d32aULL, 23321},
        {Arrangement::LooseRandom, 2000, FallMode::Exact, ContactModel::None, 4,
         0x709b3b739b1f5b82ULL, 74604},
        {Arrangement::LooseRandom, 1002, FallMode::Step, ContactModel::None, 5,
         0xc92c735ef727db08ULL, 63550},
        {Arrangement::SmallDense, 1002, FallMode::Step, ContactModel::Roll, 6,
         0x43ac8697f1ae2b03ULL, 65944},
        {Arrangement::SingleColumn, 400, FallMode::Step, ContactModel::Settle, 7,
         0xd704ef6d4848bf4bULL, 63228},
        {Arrangement::LargeDense, 1500, FallMode::Step, ContactModel::None, 8,
         0xe3ad9b9581e2aa40ULL, 75025},
    };
    for (const Pinned& p : pinned) {
        PackRequest request;
        request.arrangement = p.arrangement;
        request.count = p.count;
        request.seed = p.seed;
        request.protocol.fall = p.fall;
        request.protocol.contact = p.contact;
        PackStats stats;
        const Pack pack = make_pack(request, {}, &stats);
        BOOST_TEST_CONTEXT(to_string(p.arrangement) << " N=" << p.count << " seed " << p.seed) {
            BOOST_TEST(centers_hash(pack) == p.hash);
            BOOST_TEST(stats.moves == p.moves);
        }
    }
}

// A drop whose stalled states run through a prefix and then a cycle: stepping the counters
// one move at a time (the protocol's loop) and jumping with StallCycle end alike.
BOOST_AUTO_TEST_CASE(the_cycle_jump_ends_where_stepping_ends) {
    int cases = 0;
    for (long prefix = 0; prefix <= 4; ++prefix) {
        for (long period = 1; period <= 4; ++period) {
            for (long stall_moves : {1L, 3L, 7L, 50L}) {
                for (long max_moves : {2L, 5L, 9L, 60L, 100000L}) {
                    for (long first_move : {0L, 1L, 3L}) {
                        // State of the k-th stalled move: distinct in the prefix, then cyclic.
                        const auto state = [&](long k) {
                            const long i = k < prefix ? k : prefix + (k - prefix) % period;
                            return Vec3(0.25 * static_cast<double>(i), -0.0, 1e-3);
                        };
                        // Stepping: move first_move + k has stalled = 1 + k.
                        long k = 0;
                        long moves = first_move;
                        for (;; ++k, ++moves) {
                            const long stalled = 1 + k;
                            if ((moves > 0 && stalled > stall_moves) || moves >= max_moves) {
                                break;
                            }
                        }
                        const bool expect_stalled = moves > 0 && 1 + k > stall_moves;
                        // Jumping.
                        StallCycle cycle;
                        std::optional<StallCycle::End> end;
                        long j = 0;
                        for (; j <= k; ++j) {
                            end = cycle.observe(state(j), 0.5, -0.5, 1 + j, first_move + j,
                                                stall_moves, max_moves);
                            if (end) {
                                break;
                            }
                        }
                        if (!end) {
                            continue;  // the loop ended before any state repeated
                        }
                        ++cases;
                        BOOST_TEST_CONTEXT("prefix " << prefix << " period " << period << " stall "
                                                     << stall_moves << " max " << max_moves
                                                     << " from " << first_move) {
                            BOOST_TEST((end->center == state(k)));
                            BOOST_TEST(std::bit_cast<std::uint64_t>(end->center.y()) ==
                                       std::bit_cast<std::uint64_t>(-0.0));
                            BOOST_TEST(end->moves == moves);
                            BOOST_TEST(end->stalled == expect_stalled);
                        }
                    }
                }
            }
        }
    }
    BOOST_TEST(cases > 300);  // most combinations reach a repeat before their limit
}

BOOST_AUTO_TEST_CASE(a_different_previous_move_or_a_signed_zero_is_another_state) {
    StallCycle cycle;
    BOOST_TEST(!cycle.observe(Vec3(0.0, 1.0, 2.0), 0.5, 0.5, 1, 1, 50, 1000));
    BOOST_TEST(!cycle.observe(Vec3(0.0, 1.0, 2.0), 0.5, -0.5, 2, 2, 50, 1000));
    BOOST_TEST(!cycle.observe(Vec3(-0.0, 1.0, 2.0), 0.5, 0.5, 3, 3, 50, 1000));
    const auto end = cycle.observe(Vec3(0.0, 1.0, 2.0), 0.5, 0.5, 4, 4, 50, 1000);
    BOOST_TEST_REQUIRE(end.has_value());
    // Period 3 from stalled = 4 to stalled = 51: 47 moves on, 47 mod 3 = 2 states along.
    BOOST_TEST(end->moves == 51);
    BOOST_TEST(end->stalled);
    BOOST_TEST(std::bit_cast<std::uint64_t>(end->center.x()) == std::bit_cast<std::uint64_t>(-0.0));
    cycle.forget();
    BOOST_TEST(!cycle.observe(Vec3(0.0, 1.0, 2.0), 0.5, 0.5, 5, 5, 50, 1000));
}

BOOST_AUTO_TEST_SUITE_END()
