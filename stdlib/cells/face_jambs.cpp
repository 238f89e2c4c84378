#include "face_jambs.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

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

JambIndex::JambIndex(std::vector<Jamb> jambs) : jambs_(std::move(jambs)), by_x_(jambs_.size()) {
    for (std::size_t i = 0; i < by_x_.size(); ++i) by_x_[i] = i;
    std::stable_sort(by_x_.begin(), by_x_.end(),
                     [&](std::size_t a, std::size_t b) { return jambs_[a].x < jambs_[b].x; });
}

bool JambIndex::jamb_at(const CourseGrid& g, double q, int r, int u, bool left, double& x) const {
    // A jamb's ends come from the outline's segments (an arc's springing a micrometre off the
    // course line it was drawn on): compared with the course lines at the outline's precision.
    const double eps = 1e-6 * std::max(1.0, std::abs(g.ys.back()));
    const double lo = g.xs[static_cast<std::size_t>(u)] - 1e-6 * q,
                 hi = g.xs[static_cast<std::size_t>(u) + 1] + 1e-6 * q;
    const double y0 = g.ys[static_cast<std::size_t>(r)], y1 = g.ys[static_cast<std::size_t>(r) + 1];
    auto it = std::lower_bound(by_x_.begin(), by_x_.end(), lo,
                               [&](std::size_t i, double v) { return jambs_[i].x < v; });
    std::size_t best = jambs_.size();
    for (; it != by_x_.end() && jambs_[*it].x <= hi; ++it) {
        const Jamb& j = jambs_[*it];
        if (j.left == left && j.y0 <= y0 + eps && j.y1 >= y1 - eps) best = std::min(best, *it);
    }
    if (best == jambs_.size()) return false;
    x = jambs_[best].x;
    return true;
}

}  // namespace acanthus::cells::detail
