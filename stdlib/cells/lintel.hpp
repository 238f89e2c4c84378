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

}  // namespace acanthus::cells::detail
