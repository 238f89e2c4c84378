// Jamb quoins: up each plumb side of an opening (and of the wall), stones one course high, long
// and short by turns, reaching into the wall from the edge.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"
#include "quoin_rows.hpp"

namespace acanthus::cells {

namespace {

// Quoins go up plumb sides only: a raking edge (a gable's) is cut to, not quoined.
bool plumb(const Edge& e) {
    return !e.arc && !e.closed && e.bounds.width() <= 1e-6 * std::max(1.0, e.bounds.height());
}

void quoin(Context& c, detail::BrickLayout& layout, const Edge& e, Point inside) {
    int row = 0;
    // Bonded in by the layout (plumb jambs and wall ends in a framed tree): lay that piece.
    if (const int k = detail::quoin_piece(layout, e, inside, row); k >= 0) {
        char& taken = layout.taken[static_cast<std::size_t>(row)][static_cast<std::size_t>(k)];
        if (taken) return;
        taken = 1;
        const Rect drawn = layout.drawn(row, k);
        c.place(detail::polygon_of(layout.claim(row, k)), layout.grid.course(row), true, &drawn);
        return;
    }
    // A bonded-in layout has no quoin in this course (a head or sill falls within it): the
    // layout's bricks fill it, closed against the quoins above and below.
    if (layout.quoined) return;
    row = layout.grid.row_at(inside.y);
    if (row < 0) return;
    double s = e.project(inside);
    Point on = e.at(s);
    double tiny = 1e-6 * (layout.grid.xs.back() - layout.grid.xs.front());
    bool right = e.inward(s).x > 0;
    int u = layout.grid.unit_at(right ? on.x + tiny : on.x - tiny);
    if (u < 0) return;
    int course = layout.grid.course(row);
    int len = course % 2 == 0 ? c.options().quoin_long : c.options().quoin_short;
    int u0 = right ? u : u - len + 1, u1 = right ? u + len : u + 1;
    u0 = std::max(0, u0);
    u1 = std::min(layout.grid.units(), u1);
    const Rect drawn = layout.drawn(row, u0, u1);
    c.place(detail::polygon_of(layout.grid.cell(row, u0, u1)), course, true, &drawn);
}

}  // namespace

Generator quoins() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        if (f.kind == FeatureKind::face) return;
        c.data().quoined = true;  // layouts made from here on bond the quoins in
        const double inset = 0.25 * c.options().brick_height;
        if (f.kind == FeatureKind::corner) {
            const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
            for (int e : {corner.edge_in, corner.edge_out}) {
                const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
                if (!plumb(edge)) continue;
                detail::BrickLayout& layout = detail::brick_layout(c, edge.face);
                quoin(c, layout, edge, detail::inside_corner(corner, inset));
                return;
            }
            return;
        }
        const Edge& e = facade.edges()[static_cast<std::size_t>(f.index)];
        if (!plumb(e)) return;
        detail::BrickLayout& layout = detail::brick_layout(c, e.face);
        std::set<int> rows;
        detail::walk_edge(e, inset, inset, [&](Point p, double) {
            int row = layout.grid.row_at(p.y);
            if (row >= 0 && rows.insert(row).second) quoin(c, layout, e, p);
        });
    };
}

}  // namespace acanthus::cells
