// Window-bottom rows in the layout: the course under each sill laid in headers across the sill
// and a header past each jamb, its joints set off those of the courses below and above. Made part
// of the face's one layout so that the closers see them and the bond runs on either side.
#pragma once

#include "brick_layout.hpp"

namespace acanthus::cells::detail {

// The row under a straight sill edge and its units [u0, u1] (the sill's width), or false.
bool sill_span(const Facade& facade, const Edge& sill, const BrickLayout& layout, int& row, int& u0,
               int& u1);

// Replaces the layout's pieces under every sill of `face` (an opening's bottom edge) with
// headers (Piece::sill) over the sill's units and about two more each side, as far past one
// jamb as past the other (layout.centred_sills; else two units past each), clipped to the run.
void set_sill_rows(const Facade& facade, int face, BrickLayout& layout);

}  // namespace acanthus::cells::detail
