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

}  // namespace detail

Generator arch_stones() {
    return [](const FeatureRef& f, Context& c) {
        if (f.kind != FeatureKind::edge) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(f.index)];
        const Options& o = c.options();
        double width = o.voussoir_width > 0 ? o.voussoir_width : 2 * (o.brick_height + o.mortar);
        double depth = o.arch_depth > 0 ? o.arch_depth : o.brick_length + o.mortar;
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
