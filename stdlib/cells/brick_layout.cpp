#include "brick_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "brick_grid.hpp"
#include "closers.hpp"
#include "context_data.hpp"
#include "lintel.hpp"
#include "quoin_rows.hpp"
#include "sill_rows.hpp"

namespace acanthus::cells::detail {

namespace {

// Runs of units in a row that touch the face, cut into pieces.
void row_pieces(const CourseGrid& g, const BondPattern& bond, int phase, int row,
                std::vector<Piece>& out) {
    out.clear();
    const int n = g.units();
    for (int u = 0; u < n;) {
        if (g.at(row, u) == kOutside) {
            ++u;
            continue;
        }
        int a = u;
        while (u < n && g.at(row, u) != kOutside) ++u;
        pieces_of_run(bond, g.course(row), phase, a, u, out);
    }
    for (Piece& p : out) {
        p.full = true;
        for (int k = p.start; k < p.start + p.length; ++k)
            if (g.at(row, k) != kFull) p.full = false;
    }
}

}  // namespace

long cut_pieces(const CourseGrid& grid, const BondPattern& bond, int phase) {
    long cut = 0;
    std::vector<Piece> pieces;
    for (int r = 0; r < grid.rows(); ++r) {
        row_pieces(grid, bond, phase, r, pieces);
        for (const Piece& p : pieces) cut += p.cut;
    }
    return cut;
}

bool BrickLayout::find(Point p, int& row, int& piece) const {
    row = grid.row_at(p.y);
    int u = grid.unit_at(p.x);
    if (row < 0 || u < 0) return false;
    piece = piece_of_unit[static_cast<std::size_t>(row)][static_cast<std::size_t>(u)];
    return piece >= 0;
}

Rect BrickLayout::rect(int row, int piece) const {
    const Piece& p = rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
    return grid.cell(row, p.start, p.start + p.length);
}

Rect BrickLayout::drawn(int row, int u0, int u1) const {
    const Rect claim = grid.cell(row, u0, u1);
    const double slack = 1e-9 * std::max(1.0, std::abs(claim.x1) + std::abs(claim.y1));
    auto size = [&](double claimed, double nominal, double per_joint) {
        return std::abs(claimed - nominal) <= per_joint + slack ? nominal - mortar
                                                                : claimed - mortar;
    };
    // Head joints: the stretch of a whole unit run; bed joints: the course's height.
    const int n = u1 - u0;
    const double w = size(claim.width(), n * unit, tolerance * n / 4);
    const double h = size(claim.height(), gauge, tolerance);
    const Point c = claim.center();
    return {c.x - w / 2, c.y - h / 2, c.x + w / 2, c.y + h / 2};
}

Rect BrickLayout::drawn(int row, int piece) const {
    const Piece& p = rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
    return drawn(row, p.start, p.start + p.length);
}

BrickLayout make_brick_layout(const Facade& facade, int face, const Options& o, bool quoins,
                              bool lintels) {
    BrickLayout layout;
    layout.grid = make_brick_grid(facade, face, o);
    layout.unit = (o.brick_length + o.mortar) / 4;
    layout.gauge = o.brick_height + o.mortar;
    layout.tolerance = o.joint_tolerance;
    layout.mortar = o.mortar;
    layout.quoined = quoins;
    layout.bond.bond = o.bond == Bond::ashlar ? Bond::running : o.bond;
    // English bond at a building corner: the corner brick is a stretcher in this face's stretcher
    // courses and the other face's stretcher's end in its header courses, so a face whose
    // corner is at its right end (stretchers there in odd courses, quoin_rows.hpp) takes its
    // stretcher courses odd, and the phase puts a stretcher joint at the corner.
    int corner_unit = -1;
    const int corner = layout.bond.bond == Bond::english
                           ? building_corner_end(facade, face, layout.grid, corner_unit)
                           : 0;
    if (corner == 1) layout.bond.course_shift = 1;
    long best = -1;
    for (int phase = 0; phase < layout.bond.period(); ++phase) {
        if ((corner == -1 && (phase - corner_unit) % 4 != 0) ||
            (corner == 1 && (((phase - corner_unit - 1) % 4) + 4) % 4 != 0))
            continue;
        long cut = cut_pieces(layout.grid, layout.bond, phase);
        if (best < 0 || cut < best) best = cut, layout.phase = phase;
    }
    layout.cut_pieces = best;
    const int rows = layout.grid.rows();
    layout.rows.resize(static_cast<std::size_t>(rows));
    layout.piece_of_unit.resize(static_cast<std::size_t>(rows));
    layout.taken.resize(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r)
        row_pieces(layout.grid, layout.bond, layout.phase, r,
                   layout.rows[static_cast<std::size_t>(r)]);
    set_sill_rows(facade, face, layout);
    if (quoins) set_quoin_rows(facade, face, o, layout);
    if (lintels) set_lintel_rows(facade, face, o, layout);
    set_corner_rows(facade, face, layout);
    set_closers(layout);
    if (quoins) set_piers(o, layout);
    repair_straight_joints(layout);
    set_king_closers(layout);
    for (int r = 0; r < rows; ++r) {
        auto& pieces = layout.rows[static_cast<std::size_t>(r)];
        for (Piece& p : pieces) {  // closers moved some ends
            p.full = true;
            for (int u = p.start; u < p.start + p.length; ++u)
                if (layout.grid.at(r, u) != kFull) p.full = false;
        }
        auto& index = layout.piece_of_unit[static_cast<std::size_t>(r)];
        index.assign(static_cast<std::size_t>(layout.grid.units()), -1);
        for (std::size_t k = 0; k < pieces.size(); ++k)
            for (int u = pieces[k].start; u < pieces[k].start + pieces[k].length; ++u)
                index[static_cast<std::size_t>(u)] = static_cast<int>(k);
        layout.taken[static_cast<std::size_t>(r)].assign(pieces.size(), 0);
    }
    return layout;
}

BrickLayout& brick_layout(Context& context, int face) {
    return context.data().layout<BrickLayout>("bricks:" + std::to_string(face), [&] {
        return make_brick_layout(context.facade(), face, context.options(), context.data().quoined,
                                 context.data().lintels);
    });
}

}  // namespace acanthus::cells::detail
