// RGB blocks [5.2]: square blocks on the grid tool, coloured by feature kind when drawn; the
// debug view of which feature claimed what.
#include <acanthus/stdlib/cells.hpp>
#include <set>
#include <string>

#include "context_data.hpp"
#include "course_grid.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

Generator rgb_blocks() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        int face = detail::face_of(facade, f);
        double module = c.options().brick_height + c.options().mortar;
        auto& grid = c.data().layout<detail::CourseGrid>("rgb:" + std::to_string(face), [&] {
            return detail::make_grid(facade, face, module, module);
        });
        auto block = [&](int row, int u) {
            c.place(detail::polygon_of(grid.cell(row, u, u + 1)), grid.course(row));
        };
        const double inset = 0.25 * module;
        if (f.kind == FeatureKind::corner) {
            Point p =
                detail::inside_corner(facade.corners()[static_cast<std::size_t>(f.index)], inset);
            int row = grid.row_at(p.y), u = grid.unit_at(p.x);
            if (row >= 0 && u >= 0) block(row, u);
        } else if (f.kind == FeatureKind::edge) {
            std::set<std::pair<int, int>> seen;
            detail::walk_edge(facade.edges()[static_cast<std::size_t>(f.index)], inset, inset,
                              [&](Point p, double) {
                                  int row = grid.row_at(p.y), u = grid.unit_at(p.x);
                                  if (row >= 0 && u >= 0 && seen.insert({row, u}).second)
                                      block(row, u);
                              });
        } else {
            FaceOccupancy& occupancy = c.face_occupancy(face);
            for (int row = 0; row < grid.rows(); ++row)
                for (int u = 0; u < grid.units(); ++u) {
                    if (grid.at(row, u) == detail::kOutside) continue;
                    Rect r = grid.cell(row, u, u + 1);
                    if (grid.at(row, u) == detail::kFull && occupancy.rect_is_free(r))
                        c.place_free_rect(r, grid.course(row));
                    else
                        block(row, u);
                }
        }
    };
}

}  // namespace acanthus::cells
