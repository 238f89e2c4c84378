#include "own_holes.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::growth::detail {

namespace {

// The circumradius of the triangle (0, a, b); infinite when degenerate.
double circumradius(Vector a, Vector b) {
    const double cross = a.x * b.y - a.y * b.x;
    if (cross == 0) return INFINITY;
    return a.length() * b.length() * (a - b).length() / (2 * std::abs(cross));
}

}  // namespace

std::vector<double> own_hole_radii(const ReferenceData& reference, double spacing) {
    std::vector<double> radii;
    if (!(spacing > 0)) return radii;
    for (int c : reference.candidates) {
        const std::vector<RingSlot>& ring = reference.rings[static_cast<std::size_t>(c)];
        double widest = -1;
        for (std::size_t k = 0; k < ring.size(); ++k) {
            if (!ring[k].closed) continue;
            const double r = circumradius(ring[k].offset, ring[(k + 1) % ring.size()].offset);
            if (std::isfinite(r)) widest = std::max(widest, r);
        }
        if (widest >= 0) radii.push_back(widest / spacing);
    }
    return radii;
}

double quantile(std::vector<double> radii, double q) {
    if (radii.empty()) return 0;
    const auto k = static_cast<std::size_t>(
        std::clamp(q, 0.0, 1.0) * static_cast<double>(radii.size() - 1) + 0.5);
    std::nth_element(radii.begin(), radii.begin() + static_cast<long>(k), radii.end());
    return radii[k];
}

}  // namespace acanthus::growth::detail
