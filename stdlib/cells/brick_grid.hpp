// The grid bricks are laid on: quarter bricks and courses of their nominal size, never stretched
// to fit as the paper's grid tool does. Differences go into the joints within the tolerance, and
// beyond it into one cut course (or closers, where the bond meets an opening or the wall's end).
#pragma once

#include <acanthus/stdlib/cells.hpp>

#include "course_grid.hpp"

namespace acanthus::cells::detail {

// Units of (length + joint) / 4 from the face's left side, the face's width taken up in the head
// joints when each joint moves by no more than the tolerance, else a cut unit at the right end.
// Courses of height + joint between the level edges (sills, heads, the wall's top and bottom),
// bed joints taking up what does not divide within the tolerance, else a cut course at the
// bottom of that storey (two, each at least half a course, when one would be thinner).
CourseGrid make_brick_grid(const Facade& facade, int face, const Options& options);

}  // namespace acanthus::cells::detail
