// The reference's own empty circles: what a faithful copy of it leaves open, so that growth
// restarts only in a hole wider than the reference itself has (synthesis.cpp).
#pragma once

#include <vector>

#include "reference.hpp"

namespace acanthus::growth::detail {

// Per interior (candidate) element with a kept triangle, the largest circumradius of the kept
// triangles it is a corner of, in units of `spacing`: the widest empty circle its neighbourhood
// shows (a triangular lattice's 0.58, a square grid's 0.71, a honeycomb's 1).
std::vector<double> own_hole_radii(const ReferenceData& reference, double spacing);

// The `q` quantile (0 to 1) of `radii` (0 when empty).
double quantile(std::vector<double> radii, double q);

}  // namespace acanthus::growth::detail
