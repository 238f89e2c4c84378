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
        // Out to the quarter-brick lines round the jambs, so the bond beside it is cut in whole
        // quarters, never to a sliver.
        const double tiny = 1e-6 * e.bounds.width();
        const int u0 = grid.unit_at(e.bounds.x0 + tiny), u1 = grid.unit_at(e.bounds.x1 - tiny);
        if (u0 < 0 || u1 < 0) return;
        const double x0 = grid.xs[static_cast<std::size_t>(u0)],
                     x1 = grid.xs[static_cast<std::size_t>(u1) + 1];
        const double y0 = grid.ys[static_cast<std::size_t>(top)], y1 = e.bounds.y0;
        // Soldiers of the brick's height plus a joint each, the span shared out evenly.
        const double pitch = o.brick_height + o.mortar;
        const int n = std::max(1, static_cast<int>(std::lround((x1 - x0) / pitch)));
        for (int k = 0; k < n; ++k) {
            const Rect r{x0 + (x1 - x0) * k / n, y0, x0 + (x1 - x0) * (k + 1) / n, y1};
            c.place(detail::polygon_of(r), grid.course(row));
        }
        // A head within a course: under the soldiers' ends, beside the jambs, the course's strip
        // down to its bed is the soldiers' bedding (mortar: too small for a cell), so the bricks
        // beside stay whole rectangles on their course's beds.
        const double bed = grid.ys[static_cast<std::size_t>(row) + 1];
        const double jl = std::min(e.bounds.x0, e.bounds.x1),
                     jr = std::max(e.bounds.x0, e.bounds.x1);
        if (bed > y1) {
            if (jl > x0) c.place(detail::polygon_of({x0, y1, jl, bed}), grid.course(row));
            if (x1 > jr) c.place(detail::polygon_of({jr, y1, x1, bed}), grid.course(row));
        }
    };
}

}  // namespace acanthus::cells
