// The bricks of a face before any is laid [5.2]: the brick grid (fixed quarter-brick units and
// courses, brick_grid.hpp), runs of units inside the face cut into the bond's pieces, with the
// phase that gives the fewest cut bricks ("fewest half bricks"; the corner flips follow from it).
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "bond.hpp"
#include "course_grid.hpp"
#include "framed_moves.hpp"

namespace acanthus::cells::detail {

struct BrickLayout {
    CourseGrid grid;
    BondPattern bond;
    int phase = 0;
    std::vector<std::vector<Piece>> rows;         // per grid row, left to right
    std::vector<std::vector<int>> piece_of_unit;  // per row: piece index or -1
    std::vector<std::vector<char>> taken;         // per row and piece: laid already
    long cut_pieces = 0;
    bool quoined = false;  // jamb quoins are pieces of the layout (quoin_rows.hpp)
    FramedMoves moves;     // fixed ends moved a quarter brick (framed_moves.hpp)
    // Per straight head edge with a lintel in the layout: its units [u0, u1) (lintel.hpp).
    std::map<int, std::pair<int, int>> lintel_units;
    // Window-bottom rows set out about their openings' middles, their ends kept by the closers
    // (sill_rows.hpp); `sill_rows`: the face has one.
    bool centred_sills = true, sill_rows = false;
    // The unit lines it was laid on: set out from the jambs, with bond breaks, arched jambs
    // among them (brick_grid.hpp).
    std::tuple<bool, bool, bool> laid_as{true, false, true};

    double unit = 0, gauge = 0, tolerance = 0, mortar = 0;  // nominal, from the options
    // Per row and piece: how far the drawn piece stands right of the centre of its claim
    // (set_joints: bricks flush at jambs, the difference in the head joints between).
    std::vector<std::vector<double>> shift;
    // Per row and piece: set out again from its run's jambs (relay_runs), the piece as laid and
    // its claim; empty where the piece lies on its units.
    std::vector<std::vector<std::pair<Rect, Rect>>> relaid;

    // The piece under point p: row and index, or false.
    bool find(Point p, int& row, int& piece) const;
    Rect rect(int row, int piece) const;
    // What a mason lays in units [u0, u1) of `row`: the nominal brick (or bat) centred in its
    // claim where the joints took up the difference, the claim less half a joint elsewhere.
    Rect drawn(int row, int u0, int u1) const;
    // The piece as laid: as above, moved by its shift, or as set out again from its jambs.
    Rect drawn(int row, int piece) const;
    // What the piece claims: its units, or where it was set out again, its part between them.
    Rect claim(int row, int piece) const;
    // Whether units [u0, u1) of `row` are drawn at the nominal length (the joints took up the
    // difference), not cut to their claim.
    bool nominal(int row, int u0, int u1) const;
};

// With `quoins`, jambs and the wall's vertical ends get quoins in the layout (quoin_rows.hpp);
// with `lintels`, every straight head's lintel is a fixed piece of the courses it fills
// (lintel.hpp). With both (the framed tree), where two fixed ends still stand over each other,
// the fixed ends round them are moved a quarter brick (framed_moves.hpp) while that leaves fewer.
BrickLayout make_brick_layout(const Facade& facade, int face, const Options& options,
                              bool quoins = false, bool lintels = false);
// Cut pieces the face would have with `phase` (for the fewest-half-bricks choice and its test).
long cut_pieces(const CourseGrid& grid, const BondPattern& bond, int phase);

// The layout of `face` shared by every generator that lays bricks in this context.
BrickLayout& brick_layout(Context& context, int face);

}  // namespace acanthus::cells::detail
