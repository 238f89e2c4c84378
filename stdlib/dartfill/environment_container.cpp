// The room a growing ornament leaves, seen through the public Environment of the running body.
#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <set>
#include <utility>

#include "container.hpp"
#include "proxy/overlap.hpp"

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
    if (const Region* region = env.region()) {
        panel_ = RingContainer::from_region(*region);
        bounds_ = panel_->bounds();
        return;
    }
    if (!(cell > 0) || !start.finite())
        throw InputError("dartfill: cannot find the panel around a non-finite start point");
    while (!discover(env, start, cell, 1u << 20, bounds_)) cell *= 2;
}

EnvironmentContainer::~EnvironmentContainer() = default;

double EnvironmentContainer::area() const { return std::max(area_, 0.0); }

bool EnvironmentContainer::admits(const PlacedShape& shape, double tolerance) const {
    // The region's flattened rings reject most candidates cheaply; the engine's exact test (the
    // region's curves and the placed elements) has the last word.
    if (panel_ && !panel_->admits(shape, tolerance)) return false;
    PolygonProxy proxy;
    proxy.set(shape.outline());
    return !env_.intersects(proxy);
}

long EnvironmentContainer::block_elements(const GridFrame& grid,
                                          std::vector<std::uint8_t>& occupancy) const {
    const double half = grid.pixel / 2;
    long free = 0;
    for (int j = 0; j < grid.height; ++j) {
        int clear_until = -1;
        for (int i = 0; i < grid.width; ++i) {
            std::size_t index = static_cast<std::size_t>(j) * grid.width + i;
            if (occupancy[index]) continue;
            if (i <= clear_until) {
                ++free;
                continue;
            }
            Point c = grid.center_of(i, j);
            double d = std::numeric_limits<double>::infinity();
            if (const Element* e = env_.nearest_element(c))
                for (std::size_t k = 0; k < e->proxy_count(); ++k)
                    if (e->proxy(k).is_set())
                        d = std::min(d, acanthus::detail::distance_to(e->proxy(k), c));
            if (d < half) {  // a disc as wide as the pixel meets an element
                occupancy[index] = 1;
                continue;
            }
            ++free;
            // Distances change by at most the step: the next pixels of the row are clear too.
            clear_until = std::isfinite(d)
                              ? i + static_cast<int>(std::floor((d - half) / grid.pixel))
                              : grid.width;
        }
    }
    return free;
}

std::vector<std::uint8_t> EnvironmentContainer::rasterize(const GridFrame& grid) const {
    std::vector<std::uint8_t> occupancy;
    long free = 0;
    if (panel_) {
        occupancy = panel_->rasterize(grid);
        free = block_elements(grid, occupancy);
    } else {
        occupancy.assign(static_cast<std::size_t>(grid.width) * grid.height, 1);
        CircleProxy probe;
        for (int j = 0; j < grid.height; ++j) {
            for (int i = 0; i < grid.width; ++i) {
                Point c = grid.center_of(i, j);
                if (!env_.inside(c)) continue;
                // Free when a disc as wide as the pixel clears the region edge and the elements.
                probe.set(c, grid.pixel / 2);
                if (env_.intersects(probe)) continue;
                occupancy[static_cast<std::size_t>(j) * grid.width + i] = 0;
                ++free;
            }
        }
    }
    if (area_ < 0) area_ = static_cast<double>(free) * grid.pixel * grid.pixel;
    return occupancy;
}

}  // namespace acanthus::dartfill
