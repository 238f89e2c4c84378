// Head joints course by course, each against the course above (head_joints.hpp).
#include <acanthus/stdlib/cells/head_joints.hpp>
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace acanthus::cells {

bool is_rect(const std::vector<Point>& p, Rect& r) {
    if (p.size() != 4) return false;
    r = {1e300, 1e300, -1e300, -1e300};
    for (Point q : p)
        r = {std::min(r.x0, q.x), std::min(r.y0, q.y), std::max(r.x1, q.x), std::max(r.y1, q.y)};
    const double eps = 1e-6 * std::max(1.0, std::max(std::abs(r.x1), std::abs(r.y1)));
    for (Point q : p)
        if ((std::abs(q.x - r.x0) > eps && std::abs(q.x - r.x1) > eps) ||
            (std::abs(q.y - r.y0) > eps && std::abs(q.y - r.y1) > eps))
            return false;
    return true;
}

bool coursed(const Cell& c) {
    static const std::set<std::string> kinds{"bricks", "window_bottom", "quoins", "lintel"};
    return kinds.count(c.generator) > 0;
}

HeadJoints straight_joints(const std::vector<Cell>& cells, double brick_length, double mortar) {
    std::vector<Rect> bricks;
    for (const Cell& c : cells) {
        Rect b;
        if (coursed(c) && is_rect(c.polygon, b)) bricks.push_back(b);
    }
    const double same = 0.05 * mortar + 1e-9;
    auto row = [&](const Rect& b) { return std::llround(b.y1 / same); };
    std::sort(bricks.begin(), bricks.end(), [&](const Rect& a, const Rect& b) {
        return row(a) != row(b) ? row(a) < row(b) : a.x0 < b.x0;
    });
    std::vector<HeadJoint> joints;
    for (std::size_t i = 0; i + 1 < bricks.size(); ++i) {
        const Rect &a = bricks[i], &b = bricks[i + 1];
        if (row(a) != row(b) || std::abs(a.y0 - b.y0) > same) continue;
        double gap = b.x0 - a.x1;
        if (gap > 0 && gap <= 2 * mortar) joints.push_back({(a.x1 + b.x0) / 2, a.y0, a.y1});
    }
    // Each joint against those of the course right above it (its bottom a joint over our top).
    std::stable_sort(joints.begin(), joints.end(),
                     [](const HeadJoint& a, const HeadJoint& b) { return a.y1 < b.y1; });
    HeadJoints out;
    for (const HeadJoint& j : joints) {
        auto lo = std::lower_bound(joints.begin(), joints.end(), j.y0 - 2 * mortar,
                                   [](const HeadJoint& a, double y) { return a.y1 < y; });
        bool compared = false;
        const HeadJoint* nearest = nullptr;
        for (auto it = lo; it != joints.end() && it->y1 < j.y0; ++it) {
            compared = true;
            if (std::abs(it->x - j.x) < brick_length / 4 - 1e-6 &&
                (!nearest || std::abs(it->x - j.x) < std::abs(nearest->x - j.x)))
                nearest = &*it;
        }
        out.compared += compared;
        if (nearest) out.straight.push_back({j, *nearest});
    }
    return out;
}

}  // namespace acanthus::cells
