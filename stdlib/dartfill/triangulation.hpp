// Constrained Delaunay triangulation of a simple polygon (CGAL), keeping the inside triangles.
#pragma once

#include "shape.hpp"

#include <vector>

namespace acanthus::dartfill {

// `outline` must be a simple polygon (validated by Shape). Returns n - 2 triangles.
std::vector<Triangle> triangulate_polygon(const std::vector<Point>& outline);

}  // namespace acanthus::dartfill
