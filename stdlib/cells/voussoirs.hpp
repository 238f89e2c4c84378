// Stones in rows along an arc edge [5.2]: in each free stretch of the edge, as many as the
// length asks for, cut by radial joints.
#pragma once

#include <acanthus/stdlib/cells.hpp>

namespace acanthus::cells::detail {

// `width` along the arc (the count is the stretch's length over it, rounded), `depth` per row.
void place_voussoirs(const Edge& edge, Context& c, double width, double depth, int rows);
// The wedge between two arcs of an arch meeting at corner `k` (a pointed apex), if any.
void place_keystone(const Corner& k, Context& c, double depth);

}  // namespace acanthus::cells::detail
