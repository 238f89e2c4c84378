#include "point_grid.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::growth::detail {

PointGrid::PointGrid(const std::vector<Point>& points, double cell) : cell_(cell) {
    if (points.empty() || !(cell > 0)) return;
    Point lo = points.front(), hi = points.front();
    for (const Point& p : points) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    origin_ = lo;
    const double n = static_cast<double>(points.size());
    const double columns = std::floor((hi.x - lo.x) / cell) + 1;
    const double rows = std::floor((hi.y - lo.y) / cell) + 1;
    // An array of cells costs its size: at most a few cells a point, else the cells are hashed.
    const bool dense = columns * rows <= 4 * n + 1024;
    std::vector<int> number(points.size());
    int cells = 0;
    if (dense) {
        columns_ = static_cast<long>(columns);
        rows_ = static_cast<long>(rows);
        cells = static_cast<int>(columns_ * rows_);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const long x = coordinate(points[i].x - lo.x), y = coordinate(points[i].y - lo.y);
        if (dense) {
            number[i] = static_cast<int>(std::clamp(y, 0L, rows_ - 1) * columns_ +
                                         std::clamp(x, 0L, columns_ - 1));
        } else {
            auto [it, added] = hash_.try_emplace(key(x, y), cells);
            if (added) ++cells;
            number[i] = it->second;
        }
    }
    // Counting sort by cell, stable: each cell's points in index order.
    start_.assign(static_cast<std::size_t>(cells) + 1, 0);
    for (int c : number) ++start_[static_cast<std::size_t>(c) + 1];
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(points.size());
    std::vector<int> next(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
        order_[static_cast<std::size_t>(next[static_cast<std::size_t>(number[i])]++)] =
            static_cast<int>(i);
}

long PointGrid::coordinate(double v) const {
    // Clamped so that a far query stays a valid integer (it then meets no cell).
    return static_cast<long>(std::clamp(std::floor(v / cell_), -4.0e15, 4.0e15));
}

int PointGrid::cell_of(long x, long y) const {
    if (columns_ > 0) {
        if (x < 0 || y < 0 || x >= columns_ || y >= rows_) return -1;
        return static_cast<int>(y * columns_ + x);
    }
    auto it = hash_.find(key(x, y));
    return it == hash_.end() ? -1 : it->second;
}

}  // namespace acanthus::growth::detail
