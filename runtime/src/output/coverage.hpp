// How much of the region the grown elements cover (the --metrics "coverage" figure).
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/region.hpp>
#include <vector>

namespace acanthus::detail {

// Fraction of the region's area covered by the elements: circles and polygons filled, arcs,
// line segments and Béziers stroked `stroke_width` user units wide (points cover nothing).
// Measured by rasterizing with Cairo at 1024 pixels on the region's longer side, antialiased,
// clipped to the region, and dividing by the region rasterized the same way; so the figure is
// exact up to about one pixel along every edge.
double coverage(const Region& region, const std::vector<const Element*>& elements,
                double stroke_width);

// The width render_to_file gives outlines, in user units, for an output `output_width` wide; the
// natural stroke_width for coverage().
double rendered_line_width(const Region& region, double output_width);

}  // namespace acanthus::detail
