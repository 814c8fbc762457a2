// The testbed's one cell grid (IncrementalGrid): a box scan meets exactly the items whose
// cell meets the box (brute force over the layout's own cell rule), in the grid's stated
// order, whether the items were inserted one at a time (dense layers), turned sparse, or
// filed all at once (packed); and its refusals.
#include <algorithm>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sgmp/pack/incremental_grid.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;

namespace {

struct Item {  // 32 bytes, as the grid asks
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    std::uint64_t index = 0;
};

/// The indices a scan of [lo, hi] must meet, in the stated order: layer by layer upward,
/// then x, then z, each cell's items in the order given (brute force over every item).
std::vector<std::uint64_t> expected_scan(const CellLayout& at, int layers,
                                         const std::vector<Item>& items, const Vec3& lo,
                                         const Vec3& hi) {
    // (layer, column x, column z, place in the input) of every item whose cell is in range,
    // sorted: the stated order.
    std::vector<std::array<std::int64_t, 4>> met;
    const int top = std::min(at.layer_of(hi.y()), layers - 1);
    for (std::size_t k = 0; k < items.size(); ++k) {
        const Item& item = items[k];
        const int l = at.layer_of(item.y);
        const int ix = at.column_x(item.x);
        const int iz = at.column_z(item.z);
        if (l >= at.layer_of(lo.y()) && l <= top && ix >= at.column_x(lo.x()) &&
            ix <= at.column_x(hi.x()) && iz >= at.column_z(lo.z()) && iz <= at.column_z(hi.z())) {
            met.push_back({l, ix, iz, static_cast<std::int64_t>(k)});
        }
    }
    std::sort(met.begin(), met.end());
    std::vector<std::uint64_t> out;
    for (const auto& m : met) {
        out.push_back(items[static_cast<std::size_t>(m[3])].index);
    }
    return out;
}

template <class Grid>
std::vector<std::uint64_t> scan(const Grid& grid, const Vec3& lo, const Vec3& hi) {
    std::vector<std::uint64_t> out;
    grid.for_each_in_box(lo, hi, [&](const Item& item) { out.push_back(item.index); });
    return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(dense_sparse_and_packed_grids_scan_the_brute_force_cells_in_order) {
    // 600 items in a 1 × 2 × 1 region with cells of 0.1 (a dense grid), the same with cells
    // of 0.004 (which turns sparse past its budget of cells per item), and the first packed
    // (the second's 3·10⁷ cells are past a packed grid's budget: refused, next test): 300
    // random boxes each, against brute force over the cell rule. Exact: the same sequence.
    Random random(11);
    std::vector<Item> items(600);
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        items[i] = {random.uniform(0, 1), random.uniform(0, 2), random.uniform(0, 1), i};
    }
    for (const double side : {0.1, 0.004}) {
        Container box;
        box.x_min = 0.0;
        box.x_max = 1.0;
        box.z_min = 0.0;
        box.z_max = 1.0;
        box.floor = 0.0;
        const CellLayout layout = CellLayout::over(box, side);
        IncrementalGrid<Item> inserted(layout);
        for (const Item& item : items) {
            inserted.insert(item);
        }
        BOOST_TEST(inserted.sparse() == (side < 0.01));
        const auto file = [&](const CellLayout& at) {
            return IncrementalGrid<Item>::packed(
                at, items.size(), [&](std::size_t k) { return items[k]; },
                [](const Item& item) { return Vec3(item.x, item.y, item.z); });
        };
        if (side < 0.01) {
            BOOST_CHECK_THROW(file(layout), std::length_error);
        }
        const auto packed = file(side < 0.01 ? CellLayout::over(box, 0.1) : layout);
        BOOST_TEST(packed.is_packed());
        BOOST_TEST(packed.size() == items.size());
        BOOST_TEST(packed.layers() == (side > 0.01 ? inserted.layers() : packed.layers()));
        std::size_t met = 0;
        for (int q = 0; q < 300; ++q) {
            const Vec3 c(random.uniform(-0.1, 1.1), random.uniform(-0.1, 2.1),
                         random.uniform(-0.1, 1.1));
            const double h = random.uniform(0.0, 0.4);
            const Vec3 lo = c - Vec3::Constant(h);
            const Vec3 hi = c + Vec3::Constant(h);
            const auto expected = expected_scan(layout, inserted.layers(), items, lo, hi);
            met += expected.size();
            BOOST_TEST(scan(inserted, lo, hi) == expected, "side " << side << " box " << q);
            if (side > 0.01) {
                BOOST_TEST(scan(packed, lo, hi) == expected, "side " << side << " box " << q);
            }
        }
        BOOST_TEST(met > 3000u);  // the boxes meet items (6,218 and more: not a vacuous check)
    }
}

BOOST_AUTO_TEST_CASE(a_packed_grid_refuses_inserts_and_oversized_layouts) {
    CellLayout layout;
    layout.hx = layout.hz = layout.hy = 1.0;
    layout.nx = layout.nz = 1;
    const std::vector<Item> one{{0.5, 0.5, 0.5, 0}};
    auto grid = IncrementalGrid<Item>::packed(
        layout, 1, [&](std::size_t k) { return one[k]; },
        [](const Item& item) { return Vec3(item.x, item.y, item.z); });
    BOOST_CHECK_THROW(grid.insert(one[0]), std::logic_error);
    // One item 10⁹ layers up: 10⁹ cells for one item is refused, not allocated.
    const std::vector<Item> high{{0.5, 1e9, 0.5, 0}};
    BOOST_CHECK_THROW(IncrementalGrid<Item>::packed(
                          layout, 1, [&](std::size_t k) { return high[k]; },
                          [](const Item& item) { return Vec3(item.x, item.y, item.z); }),
                      std::length_error);
}
