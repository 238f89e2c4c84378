// What an SVG renderer fills for a set of shapes: each shape by its own fill rule, then the
// union of all of them (nonzero across shapes), computed with Clipper on finely flattened
// boundaries and handed back as exact curves (region_trace.hpp).
#pragma once

#include <2geom/pathvector.h>

#include <vector>

#include "region/filled_shape.hpp"

namespace acanthus::detail {

// Chords used to decide the union stay within this fraction of the shapes' bounding size of
// the exact curves; the curves themselves are kept exact.
inline constexpr double kFillTolerance = 1e-6;

// Closed, non-crossing loops (they may touch at points), each with the filled side on its left:
// outer loops have positive signed area, holes negative. Loops come in the order of the first
// input curve they follow; a loop that is a whole input subpath is that subpath, unchanged (or
// reversed). Shapes must hold Bézier curves and line segments only (arcs_to_cubics).
Geom::PathVector filled_area(const std::vector<FilledShape>& shapes);

}  // namespace acanthus::detail
