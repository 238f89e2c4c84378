// Pairs of openings tested only where their bounding boxes meet: a sweep along x, so a facade
// of hundreds of windows costs about one test per window.
#include "opening_overlaps.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::cells::detail {

namespace {

struct Box {
    ClipperLib::cInt x0, y0, x1, y1;
};

Box box_of(const ClipperLib::Paths& paths) {
    Box b{0, 0, -1, -1};
    bool first = true;
    for (const ClipperLib::Path& r : paths)
        for (const ClipperLib::IntPoint& p : r) {
            if (first) b = {p.X, p.Y, p.X, p.Y};
            first = false;
            b = {std::min(b.x0, p.X), std::min(b.y0, p.Y), std::max(b.x1, p.X),
                 std::max(b.y1, p.Y)};
        }
    return b;
}

double area_of(const ClipperLib::Paths& paths) {
    double a = 0;
    for (const ClipperLib::Path& r : paths) a += ClipperLib::Area(r);
    return std::abs(a);
}

}  // namespace

std::pair<int, int> overlapping_openings(const std::vector<ClipperLib::Paths>& filled,
                                         const std::vector<bool>& opening) {
    std::vector<int> order;
    std::vector<Box> boxes(filled.size());
    for (std::size_t i = 0; i < filled.size(); ++i) {
        if (!opening[i]) continue;
        boxes[i] = box_of(filled[i]);
        order.push_back(static_cast<int>(i));
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return boxes[a].x0 < boxes[b].x0 || (boxes[a].x0 == boxes[b].x0 && a < b);
    });
    std::pair<int, int> first{-1, -1};
    for (std::size_t k = 0; k < order.size(); ++k) {
        const Box& a = boxes[order[k]];
        for (std::size_t m = k + 1; m < order.size() && boxes[order[m]].x0 < a.x1; ++m) {
            const Box& b = boxes[order[m]];
            if (b.y0 >= a.y1 || a.y0 >= b.y1) continue;
            ClipperLib::Clipper c;
            c.AddPaths(filled[order[k]], ClipperLib::ptSubject, true);
            c.AddPaths(filled[order[m]], ClipperLib::ptClip, true);
            ClipperLib::Paths common;
            c.Execute(ClipperLib::ctIntersection, common, ClipperLib::pftNonZero,
                      ClipperLib::pftNonZero);
            const double smaller = std::min(area_of(filled[order[k]]), area_of(filled[order[m]]));
            if (!(area_of(common) > 1e-4 * smaller)) continue;
            // The pair first in document order, whatever the sweep met first: one message per file.
            std::pair<int, int> pair{std::min(order[k], order[m]), std::max(order[k], order[m])};
            if (first.first < 0 || pair < first) first = pair;
        }
    }
    return first;
}

}  // namespace acanthus::cells::detail
