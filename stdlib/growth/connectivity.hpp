// Section 4 of the paper: the connectivity of a reference arrangement. Delaunay triangles with an
// angle of 2pi/3 or more are removed, the author's flips applied, and edges kept only on kept
// triangles.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace acanthus::growth::detail {

struct Connectivity {
    std::vector<std::array<int, 3>> triangles;  // kept, counter-clockwise (y up)
    std::vector<std::pair<int, int>> edges;     // i < j, sorted
    // Neighbours of each point by angle, counter-clockwise from -pi.
    std::vector<std::vector<int>> rings;
    // closed[i][k]: rings[i][k], rings[i][k + 1 mod n] and i form a kept triangle.
    std::vector<std::vector<bool>> closed;
    // On the boundary of the kept triangles (an edge with one triangle), or with no triangle.
    std::vector<bool> boundary;
    int removed_triangles = 0;
};

// Throws InputError naming `source` for points all on one line, no triangle left after the skew
// removal, or a flip that names no flippable edge.
Connectivity analyse_connectivity(const std::vector<Point>& points,
                                  const std::vector<std::pair<int, int>>& flips,
                                  const std::string& source);

// Largest interior angle of the triangle (radians).
double largest_angle(Point a, Point b, Point c);

}  // namespace acanthus::growth::detail
