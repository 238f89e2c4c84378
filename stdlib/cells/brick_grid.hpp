// The grid bricks are laid on: quarter bricks and courses of their nominal size, never stretched
// to fit as the paper's grid tool does. Differences go into the joints within the tolerance, and
// beyond it into one cut course at the wall's top (or closers, where the bond meets an opening
// or the wall's end).
#pragma once

#include <acanthus/stdlib/cells.hpp>

#include "course_grid.hpp"

namespace acanthus::cells::detail {

// Units of (length + joint) / 4 from the face's left side, the face's width taken up in the head
// joints when each joint moves by no more than the tolerance, else a cut unit at the right end.
// Courses of height + joint from the face's bottom; a level edge (sill, flat head, the wall's
// top) is a course line where the bed joints since the last reach it within the tolerance, else
// it falls within a course; a level top out of reach gets one cut course under it (two, each at
// least half a course, when one would be thinner).
// With `set_out`, the unit lines are set out from the jambs instead: through as many as the
// tolerance lets them reach, so that those jambs fall on joints. With `breaks` too, the jamb
// across an opening whose width is no whole number of quarters is reached with one odd unit
// within the opening (CourseGrid::breaks): the courses over and under it take the bond's break
// there, a cut piece under the opening, and the piers beside it are set out from their jambs.
// Without `arched`, the jambs of arched openings are left out of the set-out (the lines may then
// reach a flat-headed opening's jamb that an arched one's would have cost).
CourseGrid make_brick_grid(const Facade& facade, int face, const Options& options,
                           bool set_out = false, bool breaks = false, bool arched = true);

struct BondPattern;
// Moves each break's odd unit to the unit nearest the opening's middle where, narrower than a
// quarter brick, it has no joint on either side of it in consecutive courses of `bond` laid at
// `phase` (none in header bond: its odd unit is a quarter wider). False when there is none.
bool set_breaks(const Facade& facade, int face, const BondPattern& bond, int phase,
                CourseGrid& grid);

}  // namespace acanthus::cells::detail
