// Arch stones [5.2]: voussoirs with radial joints along arc edges, in rows.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>

#include "voussoirs.hpp"

namespace acanthus::cells {

namespace detail {

void place_voussoirs(const Edge& edge, Context& c, double width, double depth, int rows) {
    if (!edge.arc) return;
    const Segment& first = edge.segments.front();
    const Point center = first.center;
    const double radius = first.radius;
    const double dir = first.sweep >= 0 ? 1 : -1;
    // Rows grow away from the opening: outwards when the wall lies outside the circle.
    const Vector out = edge.at(edge.length / 2) - center;
    const double grow = edge.inward(edge.length / 2).dot(out) > 0 ? 1 : -1;
    double tol = c.options().arc_tolerance > 0 ? c.options().arc_tolerance
                                               : std::max(1e-3, c.options().mortar / 20);
    auto arc_points = [&](double r, double a0, double a1, std::vector<Point>& pts) {
        double step = 2 * std::acos(std::max(-1.0, 1 - tol / std::max(r, 1e-300)));
        int n = std::clamp(static_cast<int>(std::ceil(std::abs(a1 - a0) / std::max(step, 1e-6))), 1,
                           1024);
        for (int i = 0; i <= n; ++i) {
            double a = a0 + (a1 - a0) * i / n;
            pts.push_back({center.x + r * std::cos(a), center.y + r * std::sin(a)});
        }
    };
    auto intervals =
        c.edge_occupancy(&edge - c.facade().edges().data()).free_intervals(1e-9 * edge.length);
    for (auto [s0, s1] : intervals) {
        Point p0 = edge.at(s0);
        double a0 = std::atan2(p0.y - center.y, p0.x - center.x);
        double sweep = dir * (s1 - s0) / radius;
        for (int row = 0; row < rows; ++row) {
            double r_in = radius + grow * depth * row, r_out = radius + grow * depth * (row + 1);
            if (r_in <= 0 || r_out <= 0) break;
            double mid = (r_in + r_out) / 2;
            int n = std::max(1, static_cast<int>(std::lround(std::abs(sweep) * mid / width)));
            for (int i = 0; i < n; ++i) {
                double t0 = a0 + sweep * i / n, t1 = a0 + sweep * (i + 1) / n;
                std::vector<Point> poly;
                arc_points(r_in, t0, t1, poly);
                arc_points(r_out, t1, t0, poly);
                c.place(poly, row);
            }
        }
    }
}

// Where two arcs meet at an angle (a pointed arch's apex) the voussoirs of each side end on a
// radial joint of their own arc, leaving a wedge: the keystone, whose two sides continue those
// joints, all rows deep.
void place_keystone(const Corner& k, Context& c, double depth) {
    const auto& edges = c.facade().edges();
    if (k.edge_in < 0 || k.edge_out < 0) return;
    const Edge& a = edges[static_cast<std::size_t>(k.edge_in)];
    const Edge& b = edges[static_cast<std::size_t>(k.edge_out)];
    if (!a.arc || !b.arc) return;
    auto away = [&](const Edge& e, const Segment& s, double at) {
        Vector u = (k.position - s.center).normalized();
        return u.dot(e.inward(at)) < 0 ? -u : u;  // into the wall, away from the opening
    };
    Vector ua = away(a, a.segments.back(), a.length), ub = away(b, b.segments.front(), 0);
    if (ua.dot(ub) > std::cos(1.0 * M_PI / 180)) return;  // no wedge: the arcs meet smoothly
    c.place({k.position, k.position + ua * depth, k.position + ub * depth});
}

}  // namespace detail

Generator arch_stones() {
    return [](const FeatureRef& f, Context& c) {
        const Options& o = c.options();
        double depth = o.arch_depth > 0 ? o.arch_depth : o.brick_length + o.mortar;
        if (f.kind == FeatureKind::corner) {
            const Corner& k = c.facade().corners()[static_cast<std::size_t>(f.index)];
            detail::place_keystone(k, c, depth * std::max(1, o.arch_rows));
            return;
        }
        if (f.kind != FeatureKind::edge) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(f.index)];
        double width = o.voussoir_width > 0 ? o.voussoir_width : 2 * (o.brick_height + o.mortar);
        detail::place_voussoirs(e, c, width, depth, o.arch_rows);
    };
}

Generator arch_bricks() {
    // Bricks on end round the arc (a rowlock arch): one course height wide, a brick deep.
    return [](const FeatureRef& f, Context& c) {
        if (f.kind != FeatureKind::edge) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(f.index)];
        const Options& o = c.options();
        detail::place_voussoirs(e, c, o.brick_height + o.mortar, o.brick_length + o.mortar, 1);
    };
}

}  // namespace acanthus::cells
