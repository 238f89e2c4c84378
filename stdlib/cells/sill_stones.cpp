// Sill stones: the window bottom of a stone wall. The row of the ashlar grid under an opening's
// sill, from one unit before it to one unit past it, in stones of at most the ashlar maximum
// width; on the ashlar's own grid, so the ashlar around them stays whole.
#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <string>

#include "ashlar_grid.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

Generator sill_stones() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        if (f.kind == FeatureKind::face)
            throw InputError(facade.name() +
                             ": cells: the tree passes a face to sill_stones, which textures "
                             "only corners and edges");
        int edge_index = f.index;
        if (f.kind == FeatureKind::corner) {
            // A bottom corner lays the whole sill, before corner stones can notch it.
            edge_index = -1;
            const Corner& k = facade.corners()[static_cast<std::size_t>(f.index)];
            for (int e : {k.edge_in, k.edge_out}) {
                const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
                if (edge.opening && edge.part == Part::bottom && !edge.arc) edge_index = e;
            }
        }
        if (edge_index < 0) return;
        const Edge& sill = facade.edges()[static_cast<std::size_t>(edge_index)];
        if (!sill.opening || sill.part != Part::bottom || sill.arc) return;
        const Options& o = c.options();
        const double unit = detail::ashlar_unit(o);
        detail::CourseGrid& grid = detail::ashlar_grid(c, sill.face);
        Point below = sill.at(sill.length / 2) + sill.inward(sill.length / 2) * (0.25 * unit);
        int row = grid.row_at(below.y);
        double tiny = 1e-6 * sill.bounds.width();
        int u0 = grid.unit_at(sill.bounds.x0 + tiny), u1 = grid.unit_at(sill.bounds.x1 - tiny);
        if (row < 0 || u0 < 0 || u1 < 0) return;
        u0 = std::max(0, u0 - 1);
        u1 = std::min(grid.units(), u1 + 2);
        // Stones as even as the maximum width allows.
        const int n = (u1 - u0 + o.ashlar_max_width - 1) / std::max(1, o.ashlar_max_width);
        for (int i = 0; i < n; ++i) {
            int a = u0 + (u1 - u0) * i / n, b = u0 + (u1 - u0) * (i + 1) / n;
            if (b > a) c.place(detail::polygon_of(grid.cell(row, a, b)), grid.course(row));
        }
    };
}

}  // namespace acanthus::cells
