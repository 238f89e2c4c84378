// Lintels over straight heads, where they stand in the courses: shared by the lintel generator and
// the brick layout, which keeps a lintel's stretch of each course it fills as a fixed piece so
// that the bond beside it is closed against its ends (closers.hpp) instead of cut by it.
#pragma once

#include <acanthus/stdlib/cells.hpp>

#include "course_grid.hpp"

namespace acanthus::cells::detail {

// Rows [top, bottom] and units [u0, u1) of the lintel over head edge `e` on `grid` (`unit`: the
// grid's row height, `bearing`: units past each jamb), or false.
bool lintel_span(const Edge& e, const CourseGrid& grid, double unit, int bearing, int courses,
                 int& top, int& bottom, int& u0, int& u1);

struct BrickLayout;
// Puts a fixed piece (Piece::head) over every straight head's lintel in each row of `face`.
void set_lintel_rows(const Facade& facade, int face, const Options& options, BrickLayout& layout);

// The rectangle the lintel over straight head `e` is laid as (and its course), as the lintel
// generator lays it: on the brick layout's courses with its bearings (the framed tree's moves
// too), or on the ashlar grid in stone; false where none fits.
bool laid_lintel(Context& c, const Edge& e, Rect& r, int* course = nullptr);

}  // namespace acanthus::cells::detail
