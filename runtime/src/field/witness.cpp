#include "field/witness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace acanthus::detail {

namespace {

// The largest of |x - w| - gap(x, [b0, b1]) for x in [lo, hi]: piecewise linear, so at an end
// of the range or at a bend (w, b0, b1).
std::int64_t largest_lead(int lo, int hi, std::int64_t w, int b0, int b1) {
    std::int64_t best = std::numeric_limits<std::int64_t>::min();
    for (const std::int64_t x :
         {std::int64_t{lo}, std::int64_t{hi}, w, std::int64_t{b0}, std::int64_t{b1}}) {
        if (x < lo || x > hi) continue;
        const std::int64_t gap = std::max<std::int64_t>({0, b0 - x, x - b1});
        best = std::max(best, std::abs(x - w) - gap);
    }
    return best;
}

}  // namespace

bool outranks(int si, int sj, const PixelBox& sites, const PixelBox& r, DistanceMetric metric) {
    const std::int64_t wi = si, wj = sj;
    if (metric == DistanceMetric::manhattan) {
        // City-block distances separate: the largest of |p - w| - |p - box| over r is the
        // largest over its columns plus the largest over its rows.
        return largest_lead(r.x0, r.x1, wi, sites.x0, sites.x1) +
                   largest_lead(r.y0, r.y1, wj, sites.y0, sites.y1) <=
               0;
    }
    const std::int64_t fx = std::max(std::abs(r.x0 - wi), std::abs(r.x1 - wi));
    const std::int64_t fy = std::max(std::abs(r.y0 - wj), std::abs(r.y1 - wj));
    const std::int64_t gx = std::max({0, r.x0 - sites.x1, sites.x0 - r.x1});
    const std::int64_t gy = std::max({0, r.y0 - sites.y1, sites.y0 - r.y1});
    if (fx * fx + fy * fy <= gx * gx + gy * gy) return true;  // r's far corner nearer than the box
    // Else: no point of the box is nearer to a pixel p than |p - centre| - R (R the half
    // diagonal of the box), and the pixels with |p - centre| - |p - w| >= R form a convex set
    // (inside one branch of a hyperbola): testing r's corners is enough.
    const double cx = 0.5 * (sites.x0 + sites.x1), cy = 0.5 * (sites.y0 + sites.y1);
    const double bx = sites.x1 - sites.x0, by = sites.y1 - sites.y0;
    const double R = 0.5 * std::sqrt(bx * bx + by * by);
    for (const int x : {r.x0, r.x1})
        for (const int y : {r.y0, r.y1}) {
            const double ux = x - cx, uy = y - cy;
            const double vx = static_cast<double>(x - wi), vy = static_cast<double>(y - wj);
            // A margin far above the rounding of these square roots.
            if (std::sqrt(ux * ux + uy * uy) - std::sqrt(vx * vx + vy * vy) - R < 1e-6)
                return false;
        }
    return true;
}

}  // namespace acanthus::detail
