// The --metrics report and the coverage figure it carries.
#pragma once

#include <acanthus/growth.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/region.hpp>
#include <string>
#include <vector>

namespace acanthus::detail {

// One JSON object on one line (no newline): elements, iterations, rules (list of {"rule", "line",
// "successes", "failures"} in Pattern::rules order), exclude_points, coverage, seconds {total,
// growth, render}, engine ("incremental" or "reference"), and with a region its bounds and area
// (region {bounds [x0, y0, x1, y1], area}: what a viewer needs to place seeds and strokes on the
// picture, without the element tree). Growth seconds come from `stats`.
std::string metrics_json(const Pattern& pattern, const GrowthStats& stats, long elements,
                         double coverage, double total_seconds, double render_seconds,
                         bool reference_engine, const Region* region = nullptr);

}  // namespace acanthus::detail
