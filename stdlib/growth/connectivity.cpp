#include "connectivity.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "cocircular_cells.hpp"
#include "common/triangulation.hpp"

namespace acanthus::growth::detail {
namespace {

using Edge = std::pair<int, int>;

Edge edge(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

double cross(Point o, Point a, Point b) { return (a - o).cross(b - o); }

// Edge -> indices of the kept triangles on it.
std::map<Edge, std::vector<int>> edge_map(const std::vector<std::array<int, 3>>& triangles) {
    std::map<Edge, std::vector<int>> map;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
        for (int k = 0; k < 3; ++k)
            map[edge(triangles[t][k], triangles[t][(k + 1) % 3])].push_back(t);
    return map;
}

int opposite(const std::array<int, 3>& t, Edge e) {
    for (int v : t)
        if (v != e.first && v != e.second) return v;
    return -1;
}

// Replaces the two triangles on edge {i, j} by the two on the other diagonal of their quad.
void flip(std::vector<std::array<int, 3>>& triangles, const std::vector<Point>& points, Edge e,
          std::size_t index, const std::string& source) {
    auto map = edge_map(triangles);
    std::string name = source + ": flip " + std::to_string(index) + " [" + std::to_string(e.first) +
                       ", " + std::to_string(e.second) + "]";
    auto it = map.find(e);
    if (it == map.end()) throw InputError(name + " names no edge of the connectivity");
    if (it->second.size() != 2)
        throw InputError(name + " names a boundary edge (one triangle), which cannot be flipped");
    int t1 = it->second[0], t2 = it->second[1];
    int a = opposite(triangles[t1], e), b = opposite(triangles[t2], e);
    const Point& pa = points[a];
    const Point& pb = points[b];
    // The new diagonal a-b must cross i-j strictly, else the quad is not convex.
    double s1 = cross(pa, pb, points[e.first]), s2 = cross(pa, pb, points[e.second]);
    if (!(s1 * s2 < 0)) throw InputError(name + ": its quad is not convex, the flip would fold");
    auto ccw = [&](int p, int q, int r) {
        return cross(points[p], points[q], points[r]) > 0 ? std::array<int, 3>{p, q, r}
                                                          : std::array<int, 3>{p, r, q};
    };
    triangles[t1] = ccw(a, b, e.first);
    triangles[t2] = ccw(a, b, e.second);
}

}  // namespace

double largest_angle(Point a, Point b, Point c) {
    auto angle = [](Point o, Point p, Point q) {
        Vector u = p - o, v = q - o;
        return std::atan2(std::abs(u.cross(v)), u.dot(v));
    };
    return std::max({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

Connectivity analyse_connectivity(const std::vector<Point>& points,
                                  const std::vector<std::pair<int, int>>& flips,
                                  const std::string& source) {
    Connectivity c;
    std::vector<std::array<int, 3>> triangles;
    for (const Cell& cell :
         cocircular_cells(points, common::delaunay_triangulation(points), kAngleTolerance)) {
        // A lone triangle near 2pi/3 counts as skewed, so that a lattice's zigzag side goes
        // however it rounds. A polygon of points on one circle is a cell of the pattern itself (a
        // honeycomb's hexagon has angles of exactly 2pi/3) and goes only when clearly flatter.
        const bool lone = cell.triangles.size() == 1;
        const double limit = 2 * M_PI / 3 + (lone ? -kAngleTolerance : kAngleTolerance);
        if (cell.largest_angle > limit) {
            c.removed_triangles += static_cast<int>(cell.triangles.size());
            continue;
        }
        triangles.insert(triangles.end(), cell.triangles.begin(), cell.triangles.end());
    }
    if (triangles.empty() && c.removed_triangles == 0)
        throw InputError(source + ": all elements lie on one line; no connectivity");
    if (triangles.empty())
        throw InputError(source + ": every Delaunay triangle has an angle over 120 degrees");
    for (std::size_t k = 0; k < flips.size(); ++k) {
        auto [i, j] = flips[k];
        int n = static_cast<int>(points.size());
        if (i < 0 || j < 0 || i >= n || j >= n || i == j)
            throw InputError(source + ": flip " + std::to_string(k) + " [" + std::to_string(i) +
                             ", " + std::to_string(j) + "] names no edge (no such elements)");
        flip(triangles, points, edge(i, j), k, source);
    }
    std::sort(triangles.begin(), triangles.end());
    auto map = edge_map(triangles);
    const std::size_t n = points.size();
    c.rings.assign(n, {});
    c.closed.assign(n, {});
    c.boundary.assign(n, false);
    std::set<std::array<int, 3>> sorted_triangles;
    for (auto t : triangles) {
        std::sort(t.begin(), t.end());
        sorted_triangles.insert(t);
    }
    for (const auto& [e, on] : map) {
        c.edges.push_back(e);
        c.rings[e.first].push_back(e.second);
        c.rings[e.second].push_back(e.first);
        if (on.size() < 2) c.boundary[e.first] = c.boundary[e.second] = true;
    }
    for (std::size_t i = 0; i < n; ++i) {
        auto& ring = c.rings[i];
        if (ring.empty()) c.boundary[i] = true;
        auto angle = [&](int j) {
            Vector d = points[j] - points[i];
            return std::atan2(d.y, d.x);
        };
        std::sort(ring.begin(), ring.end(), [&](int a, int b) {
            double ta = angle(a), tb = angle(b);
            return ta != tb ? ta < tb : a < b;
        });
        for (std::size_t k = 0; k < ring.size(); ++k) {
            std::array<int, 3> t{static_cast<int>(i), ring[k], ring[(k + 1) % ring.size()]};
            std::sort(t.begin(), t.end());
            // The triangle lies CCW of ring[k] only when the turn to the next is under pi.
            bool ccw = cross(points[i], points[ring[k]], points[ring[(k + 1) % ring.size()]]) > 0;
            c.closed[i].push_back(ccw && sorted_triangles.count(t) > 0);
        }
    }
    c.triangles = std::move(triangles);
    return c;
}

}  // namespace acanthus::growth::detail
