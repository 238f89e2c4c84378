// Exact intersections between two lib2geom curves. lib2geom's ellipse-ellipse solver finds
// nothing for two circles (a degenerate pencil of conics), so circular arcs meet in closed form.
#pragma once

#include <2geom/curve.h>

#include <vector>

namespace acanthus::detail {

std::vector<Geom::CurveIntersection> intersect_curves(const Geom::Curve& a, const Geom::Curve& b);

}  // namespace acanthus::detail
