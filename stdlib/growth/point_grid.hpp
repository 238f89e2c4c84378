// Points bucketed into square cells, for "which points lie near q" at a fixed reach: a query
// visits the 3 x 3 cells around q's. The cells are one array over the points' bounding box when
// it is dense enough, else hashed; either way each cell's points sit side by side, in index order.
#pragma once

#include <acanthus/point.hpp>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace acanthus::growth::detail {

class PointGrid {
  public:
    PointGrid(const std::vector<Point>& points, double cell);
    // f(i) for every point i in the cells around q's (a superset of those within one cell of
    // q), cell by cell, each cell's in index order.
    template <class F>
    void around(Point q, F&& f) const {
        if (order_.empty()) return;
        const long x = coordinate(q.x - origin_.x), y = coordinate(q.y - origin_.y);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                const int c = cell_of(x + dx, y + dy);
                if (c < 0) continue;
                for (int k = start_[static_cast<std::size_t>(c)];
                     k < start_[static_cast<std::size_t>(c) + 1]; ++k)
                    f(order_[static_cast<std::size_t>(k)]);
            }
    }

  private:
    long coordinate(double v) const;
    int cell_of(long x, long y) const;  // -1: no point there
    static std::int64_t key(long x, long y) {
        return static_cast<std::int64_t>((static_cast<std::uint64_t>(x) << 32) ^
                                         (static_cast<std::uint64_t>(y) & 0xffffffffU));
    }
    double cell_;
    Point origin_;
    long columns_ = 0, rows_ = 0;                 // the array's size; 0 when hashed
    std::unordered_map<std::int64_t, int> hash_;  // cell -> its number, when hashed
    std::vector<int> start_;                      // per cell number: its first place in order_
    std::vector<int> order_;                      // point indices, cell by cell
};

}  // namespace acanthus::growth::detail
