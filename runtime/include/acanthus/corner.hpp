// A corner of a panel's boundary: a signal point (Wong et al. section 2.1.3) where an
// ornament places a motif, such as the tip of a heart, a frame's corners, the apex of an arch.
#pragma once

#include <acanthus/point.hpp>
#include <cmath>

namespace acanthus {

struct Corner {
    Point at;          // on the boundary
    Direction inward;  // bisects the region's angle at the corner, pointing into the region
    double angle = 0;  // the region's angle there, radians: under pi convex, over pi concave

    bool convex() const { return angle < M_PI; }
    // Centre of the circle of `radius` that fits into the corner: touching both sides of a
    // convex corner, or touching the point of a concave one.
    Point nestled(double radius) const {
        return at.offset(inward, convex() ? radius / std::sin(angle / 2) : radius);
    }
};

}  // namespace acanthus
