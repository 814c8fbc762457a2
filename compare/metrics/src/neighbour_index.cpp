#include "sgmp/metrics/neighbour_index.hpp"

#include <CGAL/Euclidean_distance.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "point_of_index.hpp"
#include "sgmp/pack/cell_grid.hpp"

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
using Distance = CGAL::Distance_adapter<Index, PointOfIndex, CGAL::Euclidean_distance<BaseTraits>>;
using KSearch = CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree>;

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
    NeighbourBox box;
    std::vector<Vec3> given;    ///< the points as given
    std::vector<Point> points;  ///< the points in the tree (wrapped when periodic)
    Traits traits;
    Tree tree;

    Impl(std::vector<Vec3> input, const NeighbourBox& space)
        : box(space),
          given(std::move(input)),
          points(tree_points(given, box)),
          traits(PointOfIndex{&points}),
          tree(Splitter(kBucketSize), traits) {
        std::vector<Index> keys(points.size());
        for (Index i = 0; i < keys.size(); ++i) {
            keys[i] = i;
        }
        tree.insert(keys.begin(), keys.end());
        tree.build();
    }

    static std::vector<Point> tree_points(const std::vector<Vec3>& input, const NeighbourBox& box) {
        if (input.size() >= std::numeric_limits<Index>::max()) {
            throw std::length_error("too many points for the neighbour index");
        }
        std::vector<Point> result;
        result.reserve(input.size());
        for (const Vec3& given : input) {
            const Vec3 p = box.wrapped(given);
            result.emplace_back(p.x(), p.y(), p.z());
        }
        return result;
    }

    /// The shifts (0 first) of the query point's images whose ball of radius `wide`
    /// meets the cell; {0} alone in an open box.
    [[nodiscard]] std::vector<Vec3> image_shifts(const Vec3& q, double wide) const {
        std::vector<Vec3> shifts{Vec3::Zero()};
        if (!box.periodic) {
            return shifts;
        }
        const auto meeting = [&](double v, double lo, double hi) {
            const double period = hi - lo;
            std::vector<double> s{0.0};
            for (const double shift : {period, -period}) {
                if (v + shift - wide <= hi && v + shift + wide >= lo) {
                    s.push_back(shift);
                }
            }
            return s;
        };
        for (const double sx : meeting(q.x(), box.x_min, box.x_max)) {
            for (const double sz : meeting(q.z(), box.z_min, box.z_max)) {
                if (sx != 0.0 || sz != 0.0) {
                    shifts.emplace_back(sx, 0.0, sz);
                }
            }
        }
        return shifts;
    }

    /// The points within the box's distance² `limit` of q, each once, found by
    /// fuzzy-sphere queries of radius `wide` from q's wrapped position and its images.
    void gather(const Vec3& q, double wide, double limit, std::vector<Neighbour>& out) const {
        out.clear();
        const Vec3 w = box.wrapped(q);
        std::vector<Index> candidates;
        for (const Vec3& shift : image_shifts(w, wide)) {
            const Vec3 c = w + shift;
            tree.search(std::back_inserter(candidates),
                        Sphere(Point(c.x(), c.y(), c.z()), wide, 0.0, traits));
        }
        if (box.periodic) {
            std::sort(candidates.begin(), candidates.end());
            candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        }
        for (const Index j : candidates) {
            const double d2 = box.distance2(q, given[j]);
            if (d2 <= limit) {
                out.push_back({j, d2});
            }
        }
    }
};

namespace {

double widened(double radius) {
    return radius * (1.0 + kWiden) + std::numeric_limits<double>::min();
}

}  // namespace

NeighbourIndex::NeighbourIndex(const std::vector<Vec3>& points, const NeighbourBox& box)
    : impl_(std::make_unique<Impl>(points, box)) {}

NeighbourIndex::NeighbourIndex(const std::vector<Particle>& particles, const NeighbourBox& box)
    : impl_(std::make_unique<Impl>(centers_of(particles), box)) {}

NeighbourIndex::~NeighbourIndex() = default;

std::size_t NeighbourIndex::size() const {
    return impl_->points.size();
}

const NeighbourBox& NeighbourIndex::box() const {
    return impl_->box;
}

const Vec3& NeighbourIndex::point(std::size_t i) const {
    return impl_->given[i];
}

void NeighbourIndex::within(const Vec3& q, double radius, std::vector<Index>& out) const {
    out.clear();
    if (impl_->points.empty() || !(radius >= 0.0)) {
        return;
    }
    if (impl_->box.periodic) {
        std::vector<Neighbour> found;
        neighbours_within(q, radius, found);
        for (const Neighbour& n : found) {
            out.push_back(static_cast<Index>(n.index));
        }
        return;
    }
    const Sphere sphere(Point(q.x(), q.y(), q.z()), widened(radius), 0.0, impl_->traits);
    impl_->tree.search(ExactFilter{&impl_->points, q.x(), q.y(), q.z(), radius * radius, &out},
                       sphere);
}

void NeighbourIndex::neighbours_within(const Vec3& q, double radius,
                                       std::vector<Neighbour>& out) const {
    out.clear();
    if (impl_->points.empty() || !(radius >= 0.0)) {
        return;
    }
    impl_->gather(q, widened(radius), radius * radius, out);
}

std::vector<Neighbour> NeighbourIndex::nearest(const Vec3& q, std::size_t k) const {
    std::vector<Neighbour> found;
    k = std::min(k, size());
    if (k == 0) {
        return found;
    }
    // CGAL's k nearest of q's wrapped position and of its images one period away: among
    // them the k-th smallest distance bounds the k nearest, which one exact radius query
    // then finds with every tie.
    const Vec3 w = impl_->box.wrapped(q);
    const Distance distance(PointOfIndex{&impl_->points});
    std::vector<Index> candidates;
    for (const Vec3& shift : impl_->image_shifts(w, std::numeric_limits<double>::infinity())) {
        const Vec3 c = w + shift;
        const KSearch search(impl_->tree, Point(c.x(), c.y(), c.z()), static_cast<unsigned>(k), 0.0,
                             true, distance);
        for (const auto& [j, ignored] : search) {
            candidates.push_back(j);
        }
    }
    std::sort(candidates.begin(), candidates.end());  // a point met from two images: once
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<double> d2;
    for (const Index j : candidates) {
        d2.push_back(impl_->box.distance2(q, impl_->given[j]));
    }
    std::nth_element(d2.begin(), d2.begin() + static_cast<std::ptrdiff_t>(k - 1), d2.end());
    const double limit = d2[k - 1];
    impl_->gather(q, widened(std::sqrt(limit)), limit, found);
    std::sort(found.begin(), found.end(), nearer);
    found.resize(k);
    return found;
}

}  // namespace sgmp::metrics
