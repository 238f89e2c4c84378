// The room a growing ornament leaves, seen through the public Environment of the running body.
#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <utility>

#include "container.hpp"

namespace acanthus::dartfill {
namespace {

// Cells of side `cell` that meet the region, flood-filled from the cell holding `start`.
// Returns false when more than `limit` cells would be visited.
bool discover(const Environment& env, Point start, double cell, std::size_t limit, Rect& bounds) {
    std::set<std::pair<long, long>> seen;
    std::deque<std::pair<long, long>> queue;
    auto key = [&](Point p) {
        return std::pair<long, long>{static_cast<long>(std::floor(p.x / cell)),
                                     static_cast<long>(std::floor(p.y / cell))};
    };
    queue.push_back(key(start));
    seen.insert(queue.front());
    bool any = false;
    double reach = cell * std::sqrt(0.5);
    while (!queue.empty()) {
        auto [i, j] = queue.front();
        queue.pop_front();
        Point c{(i + 0.5) * cell, (j + 0.5) * cell};
        if (!env.inside(c) && env.distance_to_boundary(c) > reach) continue;
        Rect box{i * cell, j * cell, (i + 1) * cell, (j + 1) * cell};
        if (!any) {
            bounds = box;
            any = true;
        } else {
            bounds = {std::min(bounds.x0, box.x0), std::min(bounds.y0, box.y0),
                      std::max(bounds.x1, box.x1), std::max(bounds.y1, box.y1)};
        }
        for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            std::pair<long, long> n{i + di, j + dj};
            if (seen.insert(n).second) queue.push_back(n);
        }
        if (seen.size() > limit) return false;
    }
    return any;
}

}  // namespace

EnvironmentContainer::EnvironmentContainer(Environment& env, Point start, double cell) : env_(env) {
    if (!(cell > 0) || !start.finite())
        throw InputError("dartfill: cannot find the panel around a non-finite start point");
    while (!discover(env, start, cell, 1u << 20, bounds_)) cell *= 2;
}

double EnvironmentContainer::area() const { return std::max(area_, 0.0); }

bool EnvironmentContainer::admits(const PlacedShape& shape, double) const {
    PolygonProxy proxy;
    proxy.set(shape.outline());
    return !env_.intersects(proxy);
}

std::vector<std::uint8_t> EnvironmentContainer::rasterize(const GridFrame& grid) const {
    std::vector<std::uint8_t> occupancy(static_cast<std::size_t>(grid.width) * grid.height, 1);
    long free = 0;
    CircleProxy probe;
    for (int j = 0; j < grid.height; ++j) {
        for (int i = 0; i < grid.width; ++i) {
            Point c = grid.center_of(i, j);
            if (!env_.inside(c)) continue;
            // A pixel is free when a disc as wide as the pixel clears the region edge and elements.
            probe.set(c, grid.pixel / 2);
            if (env_.intersects(probe)) continue;
            occupancy[static_cast<std::size_t>(j) * grid.width + i] = 0;
            ++free;
        }
    }
    if (area_ < 0) area_ = static_cast<double>(free) * grid.pixel * grid.pixel;
    return occupancy;
}

}  // namespace acanthus::dartfill
