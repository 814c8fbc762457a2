#pragma once
// What the cross-validation's Markdown and text views (crossval_render.cpp) and its JSON and
// CSV views (crossval_json.cpp) share.
#include <vector>

#include "sgmp/metrics/metric_descriptors.hpp"

namespace sgmp::report::detail {

/// The headline's scalar metrics, in headline order: the value columns of its tables.
const std::vector<const metrics::MetricDescriptor*>& headline_scalars();

}  // namespace sgmp::report::detail
