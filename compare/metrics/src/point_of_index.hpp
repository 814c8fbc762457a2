#pragma once
/// @file point_of_index.hpp
/// The property map through which the metrics' CGAL kd-tree (neighbour_index.cpp) reads
/// the point of an index: the trees store indices only, the points
/// stay in one vector the map points to.
#include <boost/property_map/property_map.hpp>
#include <vector>

#include "sgmp/metrics/neighbour_index.hpp"

namespace sgmp::metrics::detail {

template <class Point>
struct PointOfIndex {
    using key_type = Index;
    using value_type = Point;
    using reference = const Point&;
    using category = boost::readable_property_map_tag;
    const std::vector<Point>* points = nullptr;
    friend reference get(const PointOfIndex& map, Index i) { return (*map.points)[i]; }
};

}  // namespace sgmp::metrics::detail
