// Reliability finding 7: a wide size ratio made the settled grid's dense layers explode
// (cells of the small diameter: ~q³ cells per large sphere; `pack --count 200 --size-modes
// 1:0.5,0.01:0.5` took 718 MB, ratios of 1000 and 10⁶ ran out of memory in
// SettledGrid::insert). The grid now keeps its occupied cells only once dense layers would
// outgrow 64 cells per sphere, and its scans see the same spheres in the same order.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <tuple>
#include <vector>

#include "sgmp/engine/settled_grid.hpp"
#include "sgmp/pack/random.hpp"
#include "test_support.hpp"

using namespace sgmp;
using namespace sgmp::engine;

namespace {

/// Spheres as a scan must yield them: by layer, column x, column z, then insertion order.
std::vector<std::tuple<int, int, int, std::size_t>> expected_order(
    const SettledGrid& grid, const std::vector<Sphere>& spheres, const Vec3& lo, const Vec3& hi) {
    const CellRange xs = grid.x_range(lo.x(), hi.x());
    const CellRange zs = grid.z_range(lo.z(), hi.z());
    const int top = std::min(grid.layer_of(hi.y()), grid.layers() - 1);
    std::vector<std::tuple<int, int, int, std::size_t>> order;
    for (std::size_t k = 0; k < spheres.size(); ++k) {
        const Sphere& s = spheres[k];
        const int l = grid.layer_of(s.y);
        const int ix = grid.x_range(s.x, s.x).lo;
        const int iz = grid.z_range(s.z, s.z).lo;
        if (l >= grid.layer_of(lo.y()) && l <= top && ix >= xs.lo && ix <= xs.hi && iz >= zs.lo &&
            iz <= zs.hi) {
            order.emplace_back(l, ix, iz, k);
        }
    }
    std::sort(order.begin(), order.end());
    return order;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(wide_ratio)

// Cells of 0.002 (a small diameter 1/500 of the large) over the container: 625² cells a
// layer, 72 bytes each, 28 MB a layer, and 500 layers to a height of 1: 14 GB dense. The
// grid goes sparse and holds the spheres in O(N); every scan yields exactly the spheres of
// the cells it meets, in the dense order.
BOOST_AUTO_TEST_CASE(a_grid_of_tiny_cells_goes_sparse_and_scans_as_the_dense_one) {
    SettledGrid grid(Container{}, 0.002);
    BOOST_TEST(!grid.sparse());
    Random rng(7);
    std::vector<Sphere> spheres;
    for (int i = 0; i < 3000; ++i) {
        const double r = i % 10 == 0 ? 0.05 : 0.0001;
        spheres.push_back(Sphere{rng.uniform(-0.625, 0.625), rng.uniform(-0.625, 0.4),
                                 rng.uniform(-0.625, 0.625), r});
        // Many in one cell too: a cell's spheres keep their insertion order.
        if (i % 100 == 0) {
            for (int k = 0; k < 5; ++k) {
                spheres.push_back(Sphere{0.1001, 0.1001, 0.1001, 0.0001});
            }
        }
    }
    for (const Sphere& s : spheres) {
        grid.insert(s);
    }
    BOOST_TEST(grid.sparse());
    BOOST_TEST(grid.size() == spheres.size());
    for (int query = 0; query < 200; ++query) {
        const Vec3 c(rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.5), rng.uniform(-0.7, 0.7));
        const double half = query % 2 == 0 ? 0.01 : 0.1;
        const Vec3 lo = c - Vec3::Constant(half);
        const Vec3 hi = c + Vec3::Constant(half);
        std::vector<std::tuple<double, double, double, double>> seen;
        grid.for_each_in_box(lo, hi,
                             [&](const Sphere& s) { seen.emplace_back(s.x, s.y, s.z, s.r); });
        std::vector<std::tuple<double, double, double, double>> expected;
        for (const auto& entry : expected_order(grid, spheres, lo, hi)) {
            const Sphere& s = spheres[std::get<3>(entry)];
            expected.emplace_back(s.x, s.y, s.z, s.r);
        }
        BOOST_TEST_INFO("query " << query);
        BOOST_TEST(seen.size() == expected.size());
        BOOST_TEST((seen == expected));
    }
    // Reset: dense again, and empty.
    grid.reset(Container{});
    BOOST_TEST(!grid.sparse());
    BOOST_TEST(grid.size() == 0u);
}

// A grid whose dense layers stay within budget stays dense (the packs of every ratio up to
// ~4, and every monodisperse pack, are made as before).
BOOST_AUTO_TEST_CASE(a_grid_of_diameter_cells_stays_dense) {
    SettledGrid grid(Container{}, 0.14);
    Random rng(3);
    for (int i = 0; i < 2000; ++i) {
        grid.insert(
            Sphere{rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6), 0.07});
    }
    BOOST_TEST(!grid.sparse());
}

BOOST_AUTO_TEST_SUITE_END()
