// Window-bottom bricks [5.2]: a row of headers in the course under an opening's sill, one more
// header past each bottom corner. Faces are not its business: passing one is an error.
#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

namespace {

// The sill edge a bottom corner belongs to, or -1.
int sill_of(const Facade& facade, const Corner& c) {
    for (int e : {c.edge_in, c.edge_out}) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (edge.opening && edge.part == Part::bottom) return e;
    }
    return -1;
}

void headers(Context& c, const detail::BrickLayout& layout, int row, int u0, int u1) {
    for (int u = std::max(0, u0); u < std::min(u1, layout.grid.units()); u += 2) {
        const int end = std::min(u + 2, u1);
        const Rect drawn = layout.drawn(row, u, end);
        c.place(detail::polygon_of(layout.grid.cell(row, u, end)), layout.grid.course(row), true,
                &drawn);
    }
}

}  // namespace

Generator window_bottom() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        if (f.kind == FeatureKind::face)
            throw InputError(facade.name() +
                             ": cells: the tree passes a face to window_bottom, which textures "
                             "only corners and edges");
        int edge_index = f.index;
        if (f.kind == FeatureKind::corner)
            edge_index = sill_of(facade, facade.corners()[static_cast<std::size_t>(f.index)]);
        if (edge_index < 0) return;
        const Edge& sill = facade.edges()[static_cast<std::size_t>(edge_index)];
        detail::BrickLayout& layout = detail::brick_layout(c, sill.face);
        const double inset = 0.25 * c.options().brick_height;
        Point below = sill.at(sill.length / 2) + sill.inward(sill.length / 2) * inset;
        int row = layout.grid.row_at(below.y);
        double x0 = std::min(sill.bounds.x0, sill.bounds.x1), x1 = sill.bounds.x1;
        double tiny = 1e-6 * (x1 - x0);
        int u0 = layout.grid.unit_at(x0 + tiny), u1 = layout.grid.unit_at(x1 - tiny);
        if (row < 0 || u0 < 0 || u1 < 0) return;
        if (f.kind == FeatureKind::edge) {
            headers(c, layout, row, u0, u1 + 1);
            return;
        }
        const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
        if (corner.position.x <= (x0 + x1) / 2)
            headers(c, layout, row, u0 - 2, u0);
        else
            headers(c, layout, row, u1 + 1, u1 + 3);
    };
}

}  // namespace acanthus::cells
