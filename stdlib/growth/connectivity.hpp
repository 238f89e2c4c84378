// Section 4 of the paper: the connectivity of a reference arrangement. Delaunay triangles with an
// angle of 2pi/3 or more are removed (cells of points on one circle split canonically and judged
// whole), the author's flips applied, and edges kept only on kept triangles.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace acanthus::growth::detail {

// Angles within this many radians of a threshold count as on it: 2pi/3 for a skewed triangle (a
// lattice's zigzag side makes exactly 2pi/3) and pi for the opposite angles of two triangles on
// one circle. Scale-free, and chosen for rounded files: coordinates rounded to 3 decimals of the
// spacing a move a point by at most 7.1e-4 a, which turns an angle between sides no shorter than a
// by at most 2.8e-3 rad and a sum of two such angles by 5.7e-3. 0.01 rad (0.57 degrees) covers
// that with room and is far below any difference an author draws on purpose.
inline constexpr double kAngleTolerance = 0.01;

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
