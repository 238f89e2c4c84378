// Soldier courses: bricks on end side by side over an opening's straight head, a brick's length
// high (the courses that make it up, from the head up), from jamb to jamb and out to the
// quarter-brick lines round them. The head's corners lay
// it too (corners come first), so no corner brick notches it.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"
#include "head_edge.hpp"

namespace acanthus::cells {

namespace {

// The soldiers' span: two quarter-brick lines round the jambs, and how many soldiers share it.
struct Span {
    int a = 0, b = 0, n = 0;
};

// Out to the quarter-brick lines round the jambs (the first or the next), so the bond beside it
// is cut in whole quarters: the span whose soldiers, each of nominal width, leave head joints
// within the tolerance, bearing as far past one jamb as past the other, then the narrowest.
Span soldier_span(const detail::CourseGrid& grid, double jl, double jr, int u0, int u1,
                  double pitch, double tol) {
    Span best{u0, u1 + 1, 0};
    double least = INFINITY;
    for (int a = u0; a >= std::max(0, u0 - 1); --a)
        for (int b = u1 + 1; b <= std::min(grid.units(), u1 + 2); ++b) {
            const double x0 = grid.xs[static_cast<std::size_t>(a)],
                         x1 = grid.xs[static_cast<std::size_t>(b)];
            const double s = x1 - x0;
            const int n = std::max(1, static_cast<int>(std::lround(s / pitch)));
            const double off = std::abs(s / n - pitch);  // each head joint's difference
            const double cost =
                (off > tol + 1e-9 ? 1000 * off : 0) + std::abs((jl - x0) - (x1 - jr)) + 0.01 * s;
            if (cost < least) least = cost, best = {a, b, n};
        }
    return best;
}

}  // namespace

Generator soldier_course() {
    return [](const FeatureRef& f, Context& c) {
        const int head = detail::head_edge(c.facade(), f);
        if (head < 0) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(head)];
        const Options& o = c.options();
        const detail::CourseGrid& grid = detail::brick_layout(c, e.face).grid;
        const Point above = e.at(e.length / 2) + e.inward(e.length / 2) * (0.25 * o.brick_height);
        const int row = grid.row_at(above.y);
        if (row < 0) return;
        // As many courses as a brick is long (three of 7.5 for a 21.5 brick).
        const int courses = std::max(1, static_cast<int>(std::lround((o.brick_length + o.mortar) /
                                                                     (o.brick_height + o.mortar))));
        const int top = std::max(0, row - courses + 1);
        const double tiny = 1e-6 * e.bounds.width();
        const int u0 = grid.unit_at(e.bounds.x0 + tiny), u1 = grid.unit_at(e.bounds.x1 - tiny);
        if (u0 < 0 || u1 < 0) return;
        const double jl = std::min(e.bounds.x0, e.bounds.x1),
                     jr = std::max(e.bounds.x0, e.bounds.x1);
        const double pitch = o.brick_height + o.mortar;
        const Span span = soldier_span(grid, jl, jr, u0, u1, pitch, o.joint_tolerance);
        const double x0 = grid.xs[static_cast<std::size_t>(span.a)],
                     x1 = grid.xs[static_cast<std::size_t>(span.b)];
        const double y0 = grid.ys[static_cast<std::size_t>(top)], y1 = e.bounds.y0;
        // Each soldier a whole brick on end, standing on the head, centred in its share of the
        // span: the head joints take up the difference, the bed joint over them the rest of
        // the courses' height.
        const int n = span.n;
        const double h = o.mortar / 2;
        for (int k = 0; k < n; ++k) {
            const Rect r{x0 + (x1 - x0) * k / n, y0, x0 + (x1 - x0) * (k + 1) / n, y1};
            const double mid = (r.x0 + r.x1) / 2;
            Rect drawn{mid - o.brick_height / 2, y1 - h - o.brick_length, mid + o.brick_height / 2,
                       y1 - h};
            // The bed joint over them at least half a joint (the courses were set out for
            // them); else the brick is cut to the courses' line.
            if (drawn.y0 - (y0 - h) < h - 1e-9) drawn.y0 = y0 + h;
            const bool fits = std::abs(r.width() - pitch) <= o.joint_tolerance + 1e-9;
            c.place(detail::polygon_of(r), grid.course(row), true, fits ? &drawn : nullptr);
        }
        // A head within a course: under the soldiers' ends, beside the jambs, the course's strip
        // down to its bed is the soldiers' bedding (mortar: too small for a cell), so the bricks
        // beside stay whole rectangles on their course's beds.
        const double bed = grid.ys[static_cast<std::size_t>(row) + 1];
        if (bed > y1) {
            if (jl > x0) c.place(detail::polygon_of({x0, y1, jl, bed}), grid.course(row));
            if (x1 > jr) c.place(detail::polygon_of({jr, y1, x1, bed}), grid.course(row));
        }
    };
}

}  // namespace acanthus::cells
