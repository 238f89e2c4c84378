// Constrained Delaunay triangulation of a simple polygon (CGAL), keeping the inside triangles.
#pragma once

#include <vector>

#include "shape.hpp"

namespace acanthus::dartfill {

// `outline` must be a simple polygon (validated by Shape). Returns n - 2 triangles.
std::vector<Triangle> triangulate_polygon(const std::vector<Point>& outline);

}  // namespace acanthus::dartfill
