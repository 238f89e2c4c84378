// Resolves crossings between the subpaths of one shape (and within a subpath) by splitting
// the boundary at every crossing and reconnecting the strands with their direction kept
// (Seifert smoothing). Winding numbers, and so the filled set under either fill rule, stay
// the same, but the resulting loops only touch, never cross: each one then either separates
// filled from empty or can be dropped.
#pragma once

#include <2geom/pathvector.h>

namespace acanthus::detail {

// Closed paths in, closed non-crossing loops out. Inputs with coincident crossings (three
// strands through one point) or more than 10000 crossings are returned unchanged.
Geom::PathVector uncross(const Geom::PathVector& paths);

}  // namespace acanthus::detail
