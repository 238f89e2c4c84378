// Triangulations for the stdlib libraries, on CGAL (only stdlib/common includes it): the inside
// of a simple polygon (dartfill's shapes) and the Delaunay triangulation of a point set.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <vector>

namespace acanthus::common {

// Constrained Delaunay triangulation of a simple polygon (validated by the caller), keeping the
// triangles inside it: n - 2 of them for n vertices.
std::vector<std::array<Point, 3>> triangulate_polygon(const std::vector<Point>& outline);

struct DelaunayTriangle {
    // Indices into the input points, counter-clockwise in y-up terms, the smallest first.
    std::array<int, 3> vertices;
    // neighbors[k]: the triangle across the edge opposite vertices[k]; -1 on the convex hull.
    std::array<int, 3> neighbors;
};

// Delaunay triangulation of a point set, triangles sorted by their vertex indices. Of points that
// repeat, only the first index is used; fewer than three points, or all on one line, give none.
// Four or more points on one empty circle are split as CGAL's insertion order decides, which
// depends only on the input. Throws std::invalid_argument for a non-finite point.
std::vector<DelaunayTriangle> delaunay_triangulation(const std::vector<Point>& points);

}  // namespace acanthus::common
