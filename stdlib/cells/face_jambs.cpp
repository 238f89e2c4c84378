#include "face_jambs.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::cells::detail {

bool plumb_edge(const Edge& e) {
    return !e.arc && !e.closed && e.bounds.width() <= 1e-9 * std::max(1.0, std::abs(e.bounds.x1)) &&
           e.bounds.height() > 0;
}

std::vector<Jamb> face_jambs(const Facade& facade, int face) {
    std::vector<Jamb> jambs;
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (plumb_edge(edge))
            jambs.push_back({edge.bounds.x0, edge.bounds.y0, edge.bounds.y1,
                             edge.inward(edge.length / 2).x > 0});
    }
    return jambs;
}

bool jamb_at(const std::vector<Jamb>& jambs, const CourseGrid& g, double q, int r, int u, bool left,
             double& x) {
    const double eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
    const double lo = g.xs[static_cast<std::size_t>(u)], hi = g.xs[static_cast<std::size_t>(u) + 1];
    for (const Jamb& j : jambs) {
        if (j.left != left || j.y0 > g.ys[static_cast<std::size_t>(r)] + eps ||
            j.y1 < g.ys[static_cast<std::size_t>(r) + 1] - eps)
            continue;
        if (j.x >= lo - 1e-6 * q && j.x <= hi + 1e-6 * q) {
            x = j.x;
            return true;
        }
    }
    return false;
}

}  // namespace acanthus::cells::detail
