#include "sgmp/metrics/kd_columns.hpp"

#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Splitters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "point_of_index.hpp"
#include "sgmp/metrics/parallel.hpp"

namespace sgmp::metrics {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_2;

using PointOfKey = detail::PointOfIndex<Point>;  // (x, y) of a member position

using BaseTraits = CGAL::Search_traits_2<Kernel>;
using Traits = CGAL::Search_traits_adapter<Index, PointOfKey, BaseTraits>;
using Splitter = CGAL::Sliding_midpoint<Traits>;
using CgalTree = CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_false>;
using Node = CgalTree::Node_const_handle;

/// Columns per parallel part of the sort (fixed: the arrays never depend on the thread
/// count).
constexpr std::size_t kColumnsPerPart = 64;

std::vector<Index> every_index(std::size_t n) {
    if (n >= std::numeric_limits<Index>::max()) {
        throw std::length_error("too many particles for the neighbour search");
    }
    std::vector<Index> all(n);
    for (std::size_t i = 0; i < n; ++i) {
        all[i] = static_cast<Index>(i);
    }
    return all;
}

/// Distance from the interval [u, v] to [a, b] (0 when they meet).
double interval_gap(double u, double v, double a, double b) {
    return std::max({0.0, a - v, u - b});
}

}  // namespace

struct KdColumns::Tree {
    std::vector<Point> points;
    Traits traits;
    CgalTree tree;
    std::vector<Index> column_of_key;

    Tree(std::vector<Point> input, unsigned bucket)
        : points(std::move(input)),
          traits(PointOfKey{&points}),
          tree(Splitter(bucket), traits),
          column_of_key(points.size(), 0) {
        std::vector<Index> keys(points.size());
        for (Index i = 0; i < keys.size(); ++i) {
            keys[i] = i;
        }
        tree.insert(keys.begin(), keys.end());
        tree.build();
        // The walks below read only the nodes and the leaves' keys: the coordinates the
        // splitter needed are let go (16 bytes per centre).
        std::vector<Point>().swap(points);
    }

    /// f(leaf) for every non-empty leaf, lower child first.
    template <class F>
    static void for_each_leaf(Node node, F&& f) {
        if (node->is_leaf()) {
            const auto leaf = static_cast<CgalTree::Leaf_node_const_handle>(node);
            if (leaf->size() > 0) {
                f(leaf);
            }
            return;
        }
        const auto inner = static_cast<CgalTree::Internal_node_const_handle>(node);
        for_each_leaf(inner->lower(), f);
        for_each_leaf(inner->upper(), f);
    }

    /// f(column) for every column of a leaf under `node` whose tight bounds along every
    /// cutting dimension on the way meet [lo, hi], lower child first.
    template <class F>
    void for_each_near_leaf(Node node, const double (&lo)[2], const double (&hi)[2], F&& f) const {
        if (node->is_leaf()) {
            const auto leaf = static_cast<CgalTree::Leaf_node_const_handle>(node);
            if (leaf->size() > 0) {
                f(static_cast<std::size_t>(column_of_key[*leaf->begin()]));
            }
            return;
        }
        const auto inner = static_cast<CgalTree::Internal_node_const_handle>(node);
        const int d = inner->cutting_dimension();
        if (inner->lower_high_value() >= lo[d] && inner->lower_low_value() <= hi[d]) {
            for_each_near_leaf(inner->lower(), lo, hi, f);
        }
        if (inner->upper_high_value() >= lo[d] && inner->upper_low_value() <= hi[d]) {
            for_each_near_leaf(inner->upper(), lo, hi, f);
        }
    }
};

KdColumns::KdColumns(const std::vector<Particle>& particles, double side, unsigned threads)
    : KdColumns(particles, every_index(particles.size()), side, threads) {}

KdColumns::KdColumns(const std::vector<Particle>& particles, const std::vector<Index>& members,
                     double side, unsigned threads) {
    if (!(side > 0.0) || !std::isfinite(side)) {
        throw std::invalid_argument("the column side of the neighbour search must be positive");
    }
    const std::size_t n = members.size();
    if (n >= std::numeric_limits<Index>::max()) {
        throw std::length_error("too many particles for the neighbour search");
    }
    std::vector<Point> points;
    points.reserve(n);
    double lo[2] = {std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[2] = {-lo[0], -lo[1]};
    for (const Index m : members) {
        const Vec3& c = particles[m].center;
        if (!c.allFinite()) {
            throw std::invalid_argument("a centre of the neighbour search is not finite");
        }
        points.emplace_back(c.x(), c.y());
        for (int a = 0; a < 2; ++a) {
            lo[a] = std::min(lo[a], c[a]);
            hi[a] = std::max(hi[a], c[a]);
        }
    }
    if (n == 0) {
        return;
    }
    // Leaves of at most 2·n·side²/A centres (sliding-midpoint leaves hold about half their
    // bound: columns of about side²); the extents widened by one side so that a line or a
    // point of centres still gives columns of about side (and never a bucket of 0).
    const double area = (hi[0] - lo[0] + side) * (hi[1] - lo[1] + side);
    const double bucket = std::ceil(2.0 * static_cast<double>(n) * side * side / area);
    tree_ = std::make_unique<Tree>(std::move(points),
                                   static_cast<unsigned>(std::clamp(bucket, 1.0, 1e9)));

    // Columns in the tree's order; each column sorted by z, then index.
    x.resize(n);
    y.resize(n);
    z.resize(n);
    index.resize(n);
    std::vector<CgalTree::Leaf_node_const_handle> leaves;
    Tree::for_each_leaf(tree_->tree.root(),
                        [&](CgalTree::Leaf_node_const_handle leaf) { leaves.push_back(leaf); });
    start_.assign(leaves.size() + 1, 0);
    for (std::size_t c = 0; c < leaves.size(); ++c) {
        start_[c + 1] = start_[c] + leaves[c]->size();
        for (auto key = leaves[c]->begin(); key != leaves[c]->end(); ++key) {
            tree_->column_of_key[*key] = static_cast<Index>(c);
        }
    }
    footprints_.resize(leaves.size());
    parallel_for(threads, (leaves.size() + kColumnsPerPart - 1) / kColumnsPerPart,
                 [&](std::size_t part) {
                     const std::size_t last = std::min(leaves.size(), (part + 1) * kColumnsPerPart);
                     std::vector<std::pair<double, Index>> column;  // (z, particle index)
                     for (std::size_t c = part * kColumnsPerPart; c < last; ++c) {
                         column.clear();
                         for (auto key = leaves[c]->begin(); key != leaves[c]->end(); ++key) {
                             const Index i = members[*key];
                             column.emplace_back(particles[i].center.z(), i);
                         }
                         std::sort(column.begin(), column.end());
                         for (std::size_t k = 0; k < column.size(); ++k) {
                             const std::size_t at = start_[c] + k;
                             const Vec3& p = particles[column[k].second].center;
                             x[at] = p.x();
                             y[at] = p.y();
                             z[at] = column[k].first;
                             index[at] = column[k].second;
                         }
                         footprints_[c] = footprint(start_[c], start_[c + 1]);
                     }
                 });
}

KdColumns::~KdColumns() = default;

std::array<double, 4> KdColumns::footprint(std::size_t begin, std::size_t end) const {
    std::array<double, 4> f{x[begin], x[begin], y[begin], y[begin]};
    for (std::size_t p = begin; p < end; ++p) {
        f[0] = std::min(f[0], x[p]);
        f[1] = std::max(f[1], x[p]);
        f[2] = std::min(f[2], y[p]);
        f[3] = std::max(f[3], y[p]);
    }
    return f;
}

void KdColumns::columns_within(const std::array<double, 4>& footprint, double radius,
                               std::size_t first_column, std::vector<Reach>& out) const {
    out.clear();
    if (!tree_) {
        return;
    }
    // Widened far beyond rounding: the kernels' exact distance tests decide.
    const double wide = radius * (1.0 + 1e-12) + 1e-300;
    const double wide2 = wide * wide;
    const double lo[2] = {footprint[0] - wide, footprint[2] - wide};
    const double hi[2] = {footprint[1] + wide, footprint[3] + wide};
    tree_->for_each_near_leaf(tree_->tree.root(), lo, hi, [&](std::size_t c) {
        if (c < first_column) {
            return;
        }
        const std::array<double, 4>& f = footprints_[c];
        const double sx = interval_gap(footprint[0], footprint[1], f[0], f[1]);
        const double sy = interval_gap(footprint[2], footprint[3], f[2], f[3]);
        const double rest = wide2 - sx * sx - sy * sy;
        if (rest >= 0.0) {
            out.push_back({c, std::sqrt(rest)});
        }
    });
}

}  // namespace sgmp::metrics
