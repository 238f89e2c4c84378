// The part of the region that a symmetry can fill: the points whose every image lies in the
// region (the whole region when the group maps it onto itself), and the fundamental domain on
// the render buffer.
#pragma once

#include <acanthus/region.hpp>
#include <cstdint>
#include <vector>

#include "field/raster_buffer.hpp"
#include "symmetry/symmetry_group.hpp"

namespace acanthus::detail {

// Free pixels of the buffer an image of which may leave the region: made boundary obstacles,
// the field keeps circles inside the core (conservatively, as the boundary's own pixels do).
std::vector<int> pixels_outside_core(const RasterBuffer& raster, const SymmetryGroup& group);
// One byte per pixel of the grid, non-zero where the pixel's centre lies in the fundamental
// domain (widened by a pixel): where C may be centred.
std::vector<std::uint8_t> domain_pixels(const GridFrame& grid, const SymmetryGroup& group);

// The cells of 8 x 8 pixels (the field's tiles) within `cells` cells of a pixel of `domain`
// (domain_pixels()), row by row, on the grid's cells widened by `cells` on every side (the
// first at the grid's corner less `cells` cells); empty without a domain.
std::vector<bool> near_zone(const GridFrame& grid, const std::vector<std::uint8_t>& domain,
                            int cells);
// A box (user units) whose every point is farther than this many pixels from the centre of
// every pixel of the domain misses the zone near_zone(..., cells) flags, as Ornament's zone
// tests a box (widened by a cell): a zone cell lies within `cells` cells of a domain cell on
// each axis, with one cell to spare.
inline double near_zone_reach(int cells) { return (cells + 2) * 8 * 1.4142135623730951; }

// p and its distinct images (within `tolerance`), p first, the others in the group's order;
// with translations only those inside `bounds` (the region's).
std::vector<Point> point_orbit(const SymmetryGroup& group, Point p, double tolerance,
                               const Rect& bounds);

// True when the group maps the region onto itself (its boundary onto its boundary, sampled,
// within `tolerance`): then the core is the whole region.
bool maps_onto_itself(const Region& region, const SymmetryGroup& group, double tolerance);

bool core_contains(const Region& region, const SymmetryGroup& group, Point p);
// Distance from p, inside the core, to the core's boundary.
double core_distance_to_boundary(const Region& region, const SymmetryGroup& group, Point p);

}  // namespace acanthus::detail
