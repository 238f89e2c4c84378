#include "field/distinct_circles.hpp"

#include <algorithm>

namespace acanthus::detail {

std::vector<Circle> distinct_circles(std::vector<Circle> circles) {
    std::stable_sort(circles.begin(), circles.end(),
                     [](const Circle& a, const Circle& b) { return a.radius > b.radius; });
    std::vector<Circle> kept;
    for (const Circle& c : circles) {
        bool covered = std::any_of(kept.begin(), kept.end(), [&](const Circle& k) {
            return distance(k.center, c.center) < k.radius + c.radius;
        });
        if (!covered) kept.push_back(c);
    }
    return kept;
}

}  // namespace acanthus::detail
