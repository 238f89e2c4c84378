// Bricks [5.2]: one brick per corner, the bricks along each edge (alternating whole and cut at
// a jamb, as the bond gives them), then every brick of the face left free. All of them come
// from the face's one layout, so corners, edges and face agree on the bond.
#include <acanthus/stdlib/cells.hpp>
#include <cmath>
#include <set>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "face_occupancy.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

using detail::BrickLayout;

namespace {

// Four corners, sides plumb and level: the piece as laid out, not cut to a curve or a rake.
bool uncut(const std::vector<Point>& poly) {
    if (poly.size() != 4) return false;
    for (std::size_t i = 0; i < 4; ++i) {
        const Point a = poly[i], b = poly[(i + 1) % 4];
        if (std::abs(a.x - b.x) > 1e-9 && std::abs(a.y - b.y) > 1e-9) return false;
    }
    return true;
}

// A king closer looks like a three-quarter bat on the face: the cells say which it is. One cut
// to an arch's extrados or a rake is a cut brick like any other, named by its face alone.
void name(Context& c, const detail::Piece& p, int added) {
    if (!p.king || added != 1) return;
    Cell& cell = c.cells().back();
    if (!uncut(cell.polygon)) return;
    // Cut short at a jamb it is a bat, not a king closer: three quarters less a joint, to 1 mm.
    const Options& o = c.options();
    double x0 = cell.polygon[0].x, x1 = x0;
    for (Point q : cell.polygon) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
    const double king = 3 * (o.brick_length + o.mortar) / 4 - o.mortar;
    if (std::abs(x1 - x0 - king) <= o.joint_tolerance / 3) cell.piece = "king closer";
}

void lay(Context& c, BrickLayout& layout, int row, int piece) {
    char& taken = layout.taken[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
    if (taken) return;
    taken = 1;
    const detail::Piece& p =
        layout.rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
    if (p.head) return;  // the lintel's, laid by its generator
    const Rect drawn = layout.drawn(row, piece);
    const int added = c.place(detail::polygon_of(layout.claim(row, piece)), layout.grid.course(row),
                              true, &drawn);
    name(c, p, added);
}

}  // namespace

Generator bricks() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        int face = detail::face_of(facade, f);
        BrickLayout& layout = detail::brick_layout(c, face);
        const double inset =
            0.25 * std::min(c.options().brick_height, c.options().brick_length / 4);
        int row = 0, piece = 0;
        if (f.kind == FeatureKind::corner) {
            const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
            if (layout.find(detail::inside_corner(corner, inset), row, piece))
                lay(c, layout, row, piece);
            return;
        }
        if (f.kind == FeatureKind::edge) {
            const Edge& e = facade.edges()[static_cast<std::size_t>(f.index)];
            std::set<std::pair<int, int>> seen;
            std::vector<std::pair<int, int>> order;
            detail::walk_edge(e, inset, inset, [&](Point p, double) {
                if (layout.find(p, row, piece) && seen.insert({row, piece}).second)
                    order.emplace_back(row, piece);
            });
            for (auto [r, k] : order) lay(c, layout, r, k);
            return;
        }
        FaceOccupancy& occupancy = c.face_occupancy(face);
        for (int r = 0; r < layout.grid.rows(); ++r) {
            auto& pieces = layout.rows[static_cast<std::size_t>(r)];
            auto& taken = layout.taken[static_cast<std::size_t>(r)];
            for (std::size_t k = 0; k < pieces.size(); ++k) {
                if (taken[k]) continue;
                taken[k] = 1;
                if (pieces[k].head) continue;
                Rect rect = layout.claim(r, static_cast<int>(k));
                const Rect drawn = layout.drawn(r, static_cast<int>(k));
                const int added =
                    pieces[k].full && occupancy.rect_is_free(rect)
                        ? c.place_free_rect(rect, layout.grid.course(r), &drawn)
                        : c.place(detail::polygon_of(rect), layout.grid.course(r), true, &drawn);
                name(c, pieces[k], added);
            }
        }
    };
}

}  // namespace acanthus::cells
