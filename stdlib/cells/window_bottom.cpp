// Window-bottom bricks [5.2]: the headers of the course under an opening's sill, across it and
// one past each bottom corner. The row is part of the face's brick layout (sill_rows.hpp), set off
// the joints of the courses below and above, so the bond either side is closed against it. Faces
// are not its business: passing one is an error.
#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <vector>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"
#include "sill_rows.hpp"

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

// Lays the row's headers that overlap units [lo, hi), each once.
void headers(Context& c, detail::BrickLayout& layout, int row, int lo, int hi) {
    auto& pieces = layout.rows[static_cast<std::size_t>(row)];
    auto& taken = layout.taken[static_cast<std::size_t>(row)];
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const detail::Piece& p = pieces[k];
        if (!p.sill || taken[k] || p.start + p.length <= lo || p.start >= hi) continue;
        taken[k] = 1;
        const Rect drawn = layout.drawn(row, static_cast<int>(k));
        c.place(detail::polygon_of(layout.rect(row, static_cast<int>(k))), layout.grid.course(row),
                true, &drawn);
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
        int row = 0, u0 = 0, u1 = 0;
        if (!detail::sill_span(facade, sill, layout, row, u0, u1)) return;
        if (f.kind == FeatureKind::edge) {
            headers(c, layout, row, u0, u1 + 1);
            return;
        }
        const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
        const double mid = (sill.bounds.x0 + sill.bounds.x1) / 2;
        if (corner.position.x <= mid)
            headers(c, layout, row, u0 - 3, u0);
        else
            headers(c, layout, row, u1 + 1, u1 + 4);
    };
}

}  // namespace acanthus::cells
