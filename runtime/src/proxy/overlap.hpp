// Exact overlap tests between proxies (areas: circle, polygon; curves: arc, linesegment,
// bezier; point), and between a proxy and the region boundary. Touching within `tolerance`
// (user units) is not overlap.
#pragma once

#include <acanthus/proxy.hpp>
#include <acanthus/region.hpp>
#include <cmath>

namespace acanthus::detail {

// True when a and b share more than a touching contact: areas overlap in area, curves cross
// or come closer than -tolerance into each other, a curve enters an area's interior.
bool overlaps(const Proxy& a, const Proxy& b, double tolerance);
// True when any part of the proxy lies outside the region (beyond tolerance) or crosses its
// boundary.
bool leaves_region(const Proxy& p, const Region& region, double tolerance);
// The same against the region's internal paths (tests build a RegionData directly).
bool leaves_region(const Proxy& p, const detail::RegionData& region, double tolerance);
// Distance from a point to the proxy (0 inside an area proxy).
// With `limit`: exact when the distance is at most `limit`, else some value above it (curves
// whose bounds lie beyond it are not solved for).
double distance_to(const Proxy& p, Point q, double limit = INFINITY);

}  // namespace acanthus::detail
