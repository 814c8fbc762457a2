#include "sgmp/metrics/neighbour_index.hpp"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "point_of_index.hpp"
#include "sgmp/metrics/parallel.hpp"

namespace sgmp::metrics {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;

using PointOfIndex = detail::PointOfIndex<Point>;

using BaseTraits = CGAL::Search_traits_3<Kernel>;
using Traits = CGAL::Search_traits_adapter<Index, PointOfIndex, BaseTraits>;
using Splitter = CGAL::Sliding_midpoint<Traits>;
using Tree = CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_false>;
using Sphere = CGAL::Fuzzy_sphere<Traits>;

/// Relative widening of each query: far above rounding, far below any bin width.
constexpr double kWiden = 1e-9;
constexpr unsigned kBucketSize = 16;

/// Output iterator keeping the candidates within the exact radius (assignable, as the
/// tree's search requires).
struct ExactFilter {
    using iterator_category = std::output_iterator_tag;
    using value_type = void;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = void;

    const std::vector<Point>* points;
    double x, y, z, limit;
    std::vector<Index>* out;

    ExactFilter& operator*() { return *this; }
    ExactFilter& operator++() { return *this; }
    ExactFilter operator++(int) { return *this; }
    ExactFilter& operator=(Index i) {
        const Point& p = (*points)[i];
        const double dx = p.x() - x;
        const double dy = p.y() - y;
        const double dz = p.z() - z;
        if (dx * dx + dy * dy + dz * dz <= limit) {
            out->push_back(i);
        }
        return *this;
    }
};

}  // namespace

struct NeighbourIndex::Impl {
    std::vector<Point> points;
    Traits traits;
    Tree tree;

    explicit Impl(std::vector<Point> input)
        : points(std::move(input)),
          traits(PointOfIndex{&points}),
          tree(Splitter(kBucketSize), traits) {
        std::vector<Index> keys(points.size());
        for (Index i = 0; i < keys.size(); ++i) {
            keys[i] = i;
        }
        tree.insert(keys.begin(), keys.end());
        tree.build();
    }

    /// The points of `input` (Vec3 or Particle, read by `center`).
    template <class T, class Center>
    static std::vector<Point> make_points(const std::vector<T>& input, Center center) {
        if (input.size() >= std::numeric_limits<Index>::max()) {
            throw std::length_error("too many points for the neighbour index");
        }
        std::vector<Point> result;
        result.reserve(input.size());
        for (const T& item : input) {
            const Vec3& p = center(item);
            result.emplace_back(p.x(), p.y(), p.z());
        }
        return result;
    }
};

NeighbourIndex::NeighbourIndex(const std::vector<Vec3>& points)
    : impl_(std::make_unique<Impl>(
          Impl::make_points(points, [](const Vec3& p) -> const Vec3& { return p; }))) {}

NeighbourIndex::NeighbourIndex(const std::vector<Particle>& particles)
    : impl_(std::make_unique<Impl>(Impl::make_points(
          particles, [](const Particle& p) -> const Vec3& { return p.center; }))) {}

NeighbourIndex::~NeighbourIndex() = default;

std::size_t NeighbourIndex::size() const {
    return impl_->points.size();
}

void NeighbourIndex::within(const Vec3& q, double radius, std::vector<Index>& out) const {
    out.clear();
    if (impl_->points.empty() || !(radius >= 0.0)) {
        return;
    }
    const double wide = radius * (1.0 + kWiden) + std::numeric_limits<double>::min();
    const Sphere sphere(Point(q.x(), q.y(), q.z()), wide, 0.0, impl_->traits);
    impl_->tree.search(ExactFilter{&impl_->points, q.x(), q.y(), q.z(), radius * radius, &out},
                       sphere);
}

std::vector<Index> NeighbourIndex::report_rank() const {
    const std::vector<Point>& points = impl_->points;
    std::vector<Index> order;
    order.reserve(points.size());
    if (!points.empty()) {
        double lo[3] = {points[0].x(), points[0].y(), points[0].z()};
        double hi[3] = {lo[0], lo[1], lo[2]};
        for (const Point& p : points) {
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], p[a]);
                hi[a] = std::max(hi[a], p[a]);
            }
        }
        const Point center(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]));
        double radius = 1.0;  // more than the whole box: the root reports every point
        for (int a = 0; a < 3; ++a) {
            radius += hi[a] - lo[a];
        }
        impl_->tree.search(std::back_inserter(order), Sphere(center, radius, 0.0, impl_->traits));
    }
    if (order.size() != points.size()) {
        throw std::logic_error("the kd-tree did not report every point once");
    }
    std::vector<Index> rank(points.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        rank[order[k]] = static_cast<Index>(k);
    }
    return rank;
}

std::vector<std::pair<Index, Index>> pairs_within(const std::vector<Vec3>& points, double cutoff,
                                                  unsigned threads) {
    const NeighbourIndex index(points);
    using Pairs = std::vector<std::pair<Index, Index>>;
    constexpr std::size_t kChunk = 4096;
    Pairs pairs = chunked_reduce(
        threads, points.size(), kChunk, Pairs{},
        [&](Pairs& partial, std::size_t begin, std::size_t end) {
            std::vector<Index> found;
            for (std::size_t i = begin; i < end; ++i) {
                index.within(points[i], cutoff, found);
                std::sort(found.begin(), found.end());
                for (const Index j : found) {
                    if (j > i) {
                        partial.emplace_back(static_cast<Index>(i), j);
                    }
                }
            }
        },
        [](Pairs& total, const Pairs& partial) {
            total.insert(total.end(), partial.begin(), partial.end());
        });
    return pairs;
}

}  // namespace sgmp::metrics
