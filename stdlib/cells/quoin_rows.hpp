// Quoins bonded in: up each jamb and each vertical end of the wall, the piece against the edge is
// a quoin of quoin_long or quoin_short quarter bricks by course, in the face's one layout, so the
// closers set the bond beside it off its joints instead of the wall bricks being cut round it.
#pragma once

#include "brick_layout.hpp"

namespace acanthus::cells::detail {

void set_quoin_rows(const Facade& facade, int face, const Options& options, BrickLayout& layout);

// A pier between two quoins, eight quarters or less, is set out as a column: its joints a quarter
// brick or more off those of the courses above and below wherever some way allows. Run by
// set_quoin_rows, and again once the closers have moved the joints round it.
void set_piers(const Options& options, BrickLayout& layout);

// Building corners: a vertical end of the wall labelled `corner-left` or `corner-right` (the wall
// shape's class) meets another elevation. Each course's piece against it is a brick turning the
// corner: a stretcher (four quarters) on this face, or the end of the other face's stretcher
// (two), by turns; left ends and right ends take opposite turns, so the right end of one
// elevation and the left end of the next bond into each other. True when the face has one.
bool has_building_corner(const Facade& facade, int face);
// The face's building corners: -1 at the left end only, 1 at the right end only, 2 at both, 0
// none; `unit` the unit against the corner (the first or the last of its course).
int building_corner_end(const Facade& facade, int face, const CourseGrid& grid, int& unit);
void set_corner_rows(const Facade& facade, int face, BrickLayout& layout);

// The row's quoin piece at a vertical edge through point `inside` (just inside the wall), or -1.
int quoin_piece(const BrickLayout& layout, const Edge& edge, Point inside, int& row);

}  // namespace acanthus::cells::detail
