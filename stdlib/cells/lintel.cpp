// Lintels: one stone in the courses over an opening's straight head, bearing past each jamb. The
// head's corners lay it too (corners come first), so no corner brick notches it.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

Generator lintel() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        if (f.kind == FeatureKind::face) return;
        int head = -1;
        if (f.kind == FeatureKind::edge) {
            head = f.index;
        } else {
            const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
            for (int e : {corner.edge_in, corner.edge_out})
                if (facade.edges()[static_cast<std::size_t>(e)].part == Part::top &&
                    !facade.edges()[static_cast<std::size_t>(e)].arc)
                    head = e;
        }
        if (head < 0) return;
        const Edge& e = facade.edges()[static_cast<std::size_t>(head)];
        if (e.arc || e.part != Part::top || !e.opening) return;
        detail::BrickLayout& layout = detail::brick_layout(c, e.face);
        Point above =
            e.at(e.length / 2) + e.inward(e.length / 2) * (0.25 * c.options().brick_height);
        int row = layout.grid.row_at(above.y);
        double tiny = 1e-6 * e.bounds.width();
        int u0 = layout.grid.unit_at(e.bounds.x0 + tiny),
            u1 = layout.grid.unit_at(e.bounds.x1 - tiny);
        if (row < 0 || u0 < 0 || u1 < 0) return;
        int b = c.options().lintel_bearing;
        u0 = std::max(0, u0 - b);
        u1 = std::min(layout.grid.units(), u1 + 1 + b);
        // As deep as lintel_courses courses (rows above have lower indices in SVG numbers).
        int top = std::max(0, row - std::max(1, c.options().lintel_courses) + 1);
        Rect r = layout.grid.cell(row, u0, u1);
        r.y0 = layout.grid.ys[static_cast<std::size_t>(top)];
        c.place(detail::polygon_of(r), layout.grid.course(row));
    };
}

}  // namespace acanthus::cells
