// Conversion of proxies to exact lib2geom curves.
#pragma once

#include <2geom/path.h>
#include <2geom/pathvector.h>
#include <2geom/point.h>

#include <acanthus/proxy.hpp>

namespace acanthus::detail {

inline Geom::Point to_geom(Point p) { return {p.x, p.y}; }
inline Point from_geom(Geom::Point p) { return {p.x(), p.y()}; }

// Counter-clockwise sweep of an arc from `start` to `end` (end < start wraps), in [0, 2pi].
// A difference of 2pi or more is a full turn.
double arc_sweep(double start, double end);

// A circular arc as a path of pieces of at most a quarter turn each (well conditioned for
// lib2geom's endpoint parameterization). A zero sweep or radius gives a one-point segment.
Geom::Path arc_path(Point center, double radius, double start, double sweep);

// The proxy's curves: open for arc, linesegment and bezier; closed for circle and polygon
// (the closing edge is an explicit segment); an empty path at the point for a point proxy.
Geom::Path proxy_path(const Proxy& proxy);
Geom::PathVector proxy_paths(const Proxy& proxy);

}  // namespace acanthus::detail
