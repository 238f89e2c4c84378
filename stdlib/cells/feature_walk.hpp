// Small helpers the generators share: a rectangle as a polygon, its area, points just inside
// an edge.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

namespace acanthus::cells::detail {

inline std::vector<Point> polygon_of(Rect r) {
    return {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
}

// Unsigned area of a simple polygon (shoelace).
inline double area_of(const std::vector<Point>& p) {
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Point& q = p[i];
        const Point& r = p[(i + 1) % p.size()];
        a += q.x * r.y - r.x * q.y;
    }
    return std::abs(a) / 2;
}

// Calls f(point, s) at points `inset` inside the wall from the edge, every `step` or closer.
template <class F>
void walk_edge(const Edge& e, double step, double inset, F&& f) {
    int n = std::max(1, static_cast<int>(std::ceil(e.length / step)));
    for (int i = 0; i <= n; ++i) {
        // Stay off the very ends, which belong to the corners' cells as much as the edge's.
        double s = std::clamp(e.length * i / n, inset, std::max(inset, e.length - inset));
        f(e.at(s) + e.inward(s) * inset, s);
    }
}

}  // namespace acanthus::cells::detail
