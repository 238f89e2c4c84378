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
// growth, render}, engine ("incremental" or "reference"). Growth seconds come from `stats`.
std::string metrics_json(const Pattern& pattern, const GrowthStats& stats, long elements,
                         double coverage, double total_seconds, double render_seconds,
                         bool reference_engine);

}  // namespace acanthus::detail
