// Largest inscribed circle by the pole-of-inaccessibility quadtree search (as in Mapbox's
// polylabel), with the exact signed distance to the lib2geom boundary: a cell whose centre
// is at signed distance d can hold no better centre than d + half its diagonal, so cells are
// split best-bound first until none can beat the best centre by more than the tolerance.
#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <vector>

#include "region/region_data.hpp"

namespace acanthus {
namespace {

struct Cell {
    Point center;
    double half = 0;      // half the side
    double distance = 0;  // signed distance of the centre to the boundary, > 0 inside
    double bound = 0;     // the best any point of the cell can do

    // Deterministic order: best bound first, ties broken by position.
    bool operator<(const Cell& o) const {
        return std::tie(bound, center.y, center.x) < std::tie(o.bound, o.center.y, o.center.x);
    }
};

}  // namespace

Circle Region::largest_inscribed_circle(double tolerance) const {
    const Rect b = bounds();
    const double longest = std::max(b.width(), b.height());
    const double tol = std::max(tolerance > 0 ? tolerance : 1e-3 * longest, 1e-9 * longest);

    auto make_cell = [this](Point c, double half) {
        double d = distance_to_boundary(c);
        if (!contains(c)) d = -d;
        return Cell{c, half, d, d + half * M_SQRT2};
    };

    // Square cells covering the bounds; never more than ~1024 of them for thin regions.
    double side = std::min(b.width(), b.height());
    side = std::max(side, longest / 1024);
    const int nx = std::max(1, static_cast<int>(std::ceil(b.width() / side)));
    const int ny = std::max(1, static_cast<int>(std::ceil(b.height() / side)));
    std::priority_queue<Cell> queue;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            queue.push(make_cell({b.x0 + (i + 0.5) * side, b.y0 + (j + 0.5) * side}, side / 2));

    Cell best = make_cell(b.center(), 0);
    // Each split quarters the cell; the budget only matters for pathological inputs.
    for (int budget = 200000; !queue.empty() && budget > 0; --budget) {
        Cell cell = queue.top();
        queue.pop();
        if (cell.distance > best.distance) best = cell;
        if (cell.bound - best.distance <= tol) break;  // nothing left can do better
        double h = cell.half / 2;
        for (auto [dx, dy] : {std::pair{-1, -1}, {1, -1}, {-1, 1}, {1, 1}})
            queue.push(make_cell({cell.center.x + dx * h, cell.center.y + dy * h}, h));
    }
    return Circle{best.center, std::max(best.distance, 0.0)};
}

}  // namespace acanthus
