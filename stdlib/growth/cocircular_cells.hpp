// Delaunay leaves the split of four or more points on one empty circle (a square of a grid, a
// hexagon of a honeycomb) to chance: exact coordinates get one split, the same points rounded get
// another, square by square. These cells are found within an angle tolerance and split the same
// way every time, so that a lattice's connectivity does not depend on how its file was rounded.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <vector>

#include "common/triangulation.hpp"

namespace acanthus::growth::detail {

// A convex polygon of points on one empty circle, or a single Delaunay triangle.
struct Cell {
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise
    double largest_angle = 0;                   // its outline's largest interior angle
};

// The Delaunay triangles grouped into cells: two triangles across an edge whose opposite angles
// sum to pi within `tolerance` radians lie on one circle (chained). Each cell of more than three
// points is re-split as a fan from a canonical vertex: the first counter-clockwise, seen from the
// cell's centroid, from a fixed direction. A group that is not a convex polygon with all its
// points on its outline stays Delaunay's triangles, one cell each.
std::vector<Cell> cocircular_cells(const std::vector<Point>& points,
                                   const std::vector<common::DelaunayTriangle>& delaunay,
                                   double tolerance);

}  // namespace acanthus::growth::detail
