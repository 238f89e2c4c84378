// The metric of the growth engine's distance field: exact Euclidean (the default) or the
// Manhattan (city-block) metric of Wong et al.'s medial axis transform (section 4.1).
#pragma once

#include <optional>
#include <string_view>

namespace acanthus {

enum class DistanceMetric { euclidean, manhattan };

inline std::string_view to_string(DistanceMetric m) {
    return m == DistanceMetric::manhattan ? "manhattan" : "euclidean";
}

inline std::optional<DistanceMetric> distance_metric_named(std::string_view name) {
    if (name == "euclidean") return DistanceMetric::euclidean;
    if (name == "manhattan") return DistanceMetric::manhattan;
    return std::nullopt;
}

}  // namespace acanthus
