// Lintels: one stone in the courses (or the ashlar rows of a stone wall) over an opening's
// straight head, bearing past each jamb. The head's corners lay it too (corners come first), so
// no corner brick notches it.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>

#include "ashlar_grid.hpp"
#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"
#include "head_edge.hpp"

namespace acanthus::cells {

Generator lintel() {
    return [](const FeatureRef& f, Context& c) {
        const int head = detail::head_edge(c.facade(), f);
        if (head < 0) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(head)];
        // On the grid the wall is laid on: the bricks' courses, or the ashlar's units in stone.
        const Options& o = c.options();
        const detail::CourseGrid& grid =
            c.data().stone ? detail::ashlar_grid(c, e.face) : detail::brick_layout(c, e.face).grid;
        const double unit = c.data().stone ? detail::ashlar_unit(o) : o.brick_height;
        Point above = e.at(e.length / 2) + e.inward(e.length / 2) * (0.25 * unit);
        int row = grid.row_at(above.y);
        double tiny = 1e-6 * e.bounds.width();
        int u0 = grid.unit_at(e.bounds.x0 + tiny), u1 = grid.unit_at(e.bounds.x1 - tiny);
        if (row < 0 || u0 < 0 || u1 < 0) return;
        // Bearing in quarter bricks; in stone, as many units as cover it.
        int b = o.lintel_bearing;
        if (c.data().stone)
            b = std::max(1,
                         static_cast<int>(std::ceil(
                             b * (o.brick_length + o.mortar) / 4 / detail::ashlar_unit(o) - 1e-9)));
        u0 = std::max(0, u0 - b);
        u1 = std::min(grid.units(), u1 + 1 + b);
        // As deep as lintel_courses courses (rows above have lower indices in SVG numbers).
        int top = std::max(0, row - std::max(1, o.lintel_courses) + 1);
        Rect r = grid.cell(row, u0, u1);
        r.y0 = grid.ys[static_cast<std::size_t>(top)];
        c.place(detail::polygon_of(r), grid.course(row));
    };
}

}  // namespace acanthus::cells
