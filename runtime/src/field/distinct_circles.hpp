// What a debug frame shows of the candidate circles: the medial axis gives a ridge of pixels per
// empty region, each the centre of a nearly equal circle, so drawing them all draws dozens of
// near-concentric rings. Figure 8 draws one circle per empty region.
#pragma once

#include <acanthus/point.hpp>
#include <vector>

namespace acanthus::detail {

// The circles, largest first (ties keep their order), each kept only when it overlaps no larger
// circle kept before it: one circle per empty region, none drawn over another.
std::vector<Circle> distinct_circles(std::vector<Circle> circles);

}  // namespace acanthus::detail
