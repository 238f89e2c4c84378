// Openings that overlap are refused: merged, two windows would become one opening the author
// never drew, with jambs and sills nobody placed.
#pragma once

#include <polyclipping/clipper.hpp>
#include <vector>

namespace acanthus::cells::detail {

// The first pair (i, j), i < j, of shapes marked in `opening` whose fills share area (more than
// a ten-thousandth of the smaller one: shapes that only touch pass); {-1, -1} when none.
std::pair<int, int> overlapping_openings(const std::vector<ClipperLib::Paths>& filled,
                                         const std::vector<bool>& opening);

}  // namespace acanthus::cells::detail
