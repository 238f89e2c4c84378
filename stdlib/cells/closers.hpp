// Closers at the ends of runs (quoins, jambs, reveals): the bond cut off at an opening leaves
// joints over joints near it; a mason breaks them with a queen closer or a bat there.
#pragma once

#include "brick_layout.hpp"

namespace acanthus::cells::detail {

// Moves each joint that falls on a joint of the course below (next to a run's end or a
// window-bottom row: the bond itself leaves none elsewhere), course by course from the bottom, off
// the joints of the course below (and, where it can, of the course above): the two pieces either
// side of such a joint become a closer and a bat, or two bats, of one to four quarter bricks.
void set_closers(BrickLayout& layout);

// What the closers and the quoins' piers left: each joint still over one of the course below (a
// quoin's, a lintel's or a window-bottom row's end met the bond's joint where no single joint could
// move) has the free pieces round it, in its course or else the one below, cut again into pieces
// of one to four quarters off the joints of both neighbouring courses.
void repair_straight_joints(BrickLayout& layout);

}  // namespace acanthus::cells::detail

namespace acanthus::cells::detail {

// King closers (Flemish bond): where a header would stand against a reveal (a jamb, the wall's
// end, a quoin) with a queen closer beside it, one brick with a corner cut off behind takes both
// places: its face three quarters of a brick, its back a whole header into the wall. So a header
// and queen closer at a run's end become one king closer, and a three-quarter piece at a reveal
// with a stretcher beside it (a header and closer the bond's sequence put there) is one.
void set_king_closers(BrickLayout& layout);

}  // namespace acanthus::cells::detail
