// The paper's random ashlar on a face [5.2]: a stone for every free unit of the grid, then
// stones picked at random merge with a neighbour sharing a whole side while the result stays
// within the maximum size, until no two stones can merge.
#pragma once

#include <acanthus/random.hpp>
#include <vector>

namespace acanthus::cells::detail {

struct Stone {
    int row, unit, h, w;  // top-left unit, height in rows, width in units
};

// `free`: rows x units, row-major, nonzero where a stone may go. Stones come back in reading
// order of their top-left units. Ends after fewer than 2 n (1 + max_w + max_h) picks for n
// free units: each pick takes one stone off the queue; n start on it, and each merge (at most
// n - 1) queues the merged stone and at most 2 (max_w + max_h) neighbours again.
std::vector<Stone> merge_ashlar(const std::vector<char>& free, int rows, int units, int max_w,
                                int max_h, Random& random);

}  // namespace acanthus::cells::detail
