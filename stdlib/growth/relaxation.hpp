// Section 5.5, eq. 5: least squares that pulls every link towards its desired offset,
// min sum |x_to - x_from - desired|^2, over a chosen set of free nodes; all other nodes hold still
// (the paper's fixed first element and boundary constraints, and the rest of the pattern when
// only a window around the newest element is re-solved).
#pragma once

#include <acanthus/point.hpp>
#include <vector>

namespace acanthus::growth::detail {

struct Spring {
    int from = -1;
    int to = -1;
    Vector desired;  // wanted x_to - x_from
};

// Solves for the nodes in `free_nodes` (distinct indices into `positions`) and writes them back.
// Springs between two held nodes are ignored. `stiffness` > 0 adds stiffness * |x - x_now|^2 per
// free node, so that a free group linked to nothing held stays put instead of being singular.
// The x and y systems share one sparse matrix (factored once, Cholesky).
void relax(std::vector<Point>& positions, const std::vector<Spring>& springs,
           const std::vector<int>& free_nodes, double stiffness = 1e-6);

}  // namespace acanthus::growth::detail
