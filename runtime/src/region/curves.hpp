// Curve work that lib2geom 1.2.2 gets wrong for elliptical arcs (its arc-arc intersection
// misses crossings, its arc winding numbers and pointAndDerivatives() are off), so regions
// hold Bézier curves only and count windings here.
#pragma once

#include <2geom/pathvector.h>

namespace acanthus::detail {

// Replaces every elliptical arc by cubic Béziers of at most 15 degrees each (deviation below
// 6e-9 of the radius); endpoints stay exact.
Geom::PathVector arcs_to_cubics(const Geom::PathVector& paths);

// Winding number of closed paths of Bézier curves around p: a ray to +x, each y-monotone
// piece counted half-open, crossings found by bisection.
int winding_number(const Geom::PathVector& paths, Geom::Point p);
// One curve's share of that count.
int winding_number(const Geom::Curve& curve, Geom::Point p);

}  // namespace acanthus::detail
