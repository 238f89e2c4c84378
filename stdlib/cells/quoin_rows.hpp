// Quoins bonded in: up each jamb and each vertical end of the wall, the piece against the edge is
// a quoin of quoin_long or quoin_short quarter bricks by course, in the face's one layout, so the
// closers set the bond beside it off its joints instead of the wall bricks being cut round it.
#pragma once

#include "brick_layout.hpp"

namespace acanthus::cells::detail {

void set_quoin_rows(const Facade& facade, int face, const Options& options, BrickLayout& layout);

// The row's quoin piece at a vertical edge through point `inside` (just inside the wall), or -1.
int quoin_piece(const BrickLayout& layout, const Edge& edge, Point inside, int& row);

}  // namespace acanthus::cells::detail
