#include "cocircular_cells.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace acanthus::growth::detail {
namespace {

// The angle at o in triangle o, a, b.
double angle_at(Point o, Point a, Point b) {
    Vector u = a - o, v = b - o;
    return std::atan2(std::abs(u.cross(v)), u.dot(v));
}

int find(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Where the fan of a cell starts: the first vertex counter-clockwise from this direction, seen
// from the centroid. Authored lattices put cell vertices at multiples of 15 degrees from the
// axes; -97.5 degrees lies halfway between two of them, so rounding never changes the choice.
constexpr double kFanStart = -97.5 * M_PI / 180;

// The group's triangles as a fan, or an empty cell when the group is not a convex polygon whose
// vertices are all on its outline.
Cell fan(const std::vector<Point>& points, const std::vector<std::array<int, 3>>& cell) {
    std::set<int> vertices;
    std::set<std::pair<int, int>> directed;
    for (const auto& t : cell)
        for (int k = 0; k < 3; ++k) {
            vertices.insert(t[k]);
            directed.insert({t[k], t[(k + 1) % 3]});
        }
    if (cell.size() + 2 != vertices.size()) return {};  // an interior point, or a hole
    std::map<int, int> next;
    for (auto [a, b] : directed)
        if (!directed.count({b, a}) && !next.emplace(a, b).second) return {};
    if (next.size() != vertices.size()) return {};
    std::vector<int> cycle{next.begin()->first};
    while (cycle.size() <= vertices.size()) {
        int n = next[cycle.back()];
        if (n == cycle.front()) break;
        cycle.push_back(n);
    }
    if (cycle.size() != vertices.size()) return {};
    Vector sum{0, 0};
    for (int v : cycle) sum += points[v] - Point{0, 0};
    const Point centre = Point{0, 0} + sum / static_cast<double>(cycle.size());
    auto turn = [&](int v) {
        Vector d = points[v] - centre;
        double a = std::atan2(d.y, d.x) - kFanStart;
        return a < 0 ? a + 2 * M_PI : a;
    };
    auto apex = std::min_element(cycle.begin(), cycle.end(),
                                 [&](int a, int b) { return turn(a) < turn(b); });
    std::rotate(cycle.begin(), apex, cycle.end());
    Cell out;
    const std::size_t m = cycle.size();
    for (std::size_t i = 0; i < m; ++i) {
        Point prev = points[cycle[(i + m - 1) % m]], at = points[cycle[i]],
              next = points[cycle[(i + 1) % m]];
        if (!((at - prev).cross(next - at) > 0)) return {};  // not strictly convex
        out.largest_angle = std::max(out.largest_angle, angle_at(at, prev, next));
        if (i >= 1 && i + 1 < m) out.triangles.push_back({cycle[0], cycle[i], cycle[i + 1]});
    }
    return out;
}

Cell single(const std::vector<Point>& points, const std::array<int, 3>& t) {
    double largest = 0;
    for (int k = 0; k < 3; ++k)
        largest = std::max(largest,
                           angle_at(points[t[k]], points[t[(k + 1) % 3]], points[t[(k + 2) % 3]]));
    return {{t}, largest};
}

}  // namespace

std::vector<Cell> cocircular_cells(const std::vector<Point>& points,
                                   const std::vector<common::DelaunayTriangle>& delaunay,
                                   double tolerance) {
    const int n = static_cast<int>(delaunay.size());
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    for (int t = 0; t < n; ++t)
        for (int k = 0; k < 3; ++k) {
            int u = delaunay[t].neighbors[k];
            if (u <= t) continue;
            const auto& v = delaunay[t].vertices;
            int a = v[(k + 1) % 3], b = v[(k + 2) % 3];
            int far = -1;
            for (int w : delaunay[u].vertices)
                if (w != a && w != b) far = w;
            double sum = angle_at(points[v[k]], points[a], points[b]) +
                         angle_at(points[far], points[a], points[b]);
            if (std::abs(sum - M_PI) < tolerance) parent[find(parent, t)] = find(parent, u);
        }
    std::map<int, std::vector<std::array<int, 3>>> cells;  // by root, in triangle order
    for (int t = 0; t < n; ++t) cells[find(parent, t)].push_back(delaunay[t].vertices);
    std::vector<Cell> out;
    for (auto& [root, group] : cells) {
        Cell whole = group.size() > 1 ? fan(points, group) : Cell{};
        if (!whole.triangles.empty()) {
            out.push_back(std::move(whole));
            continue;
        }
        for (const auto& t : group) out.push_back(single(points, t));
    }
    return out;
}

}  // namespace acanthus::growth::detail
