#include "symmetry/symmetric_core.hpp"

#include <algorithm>

namespace acanthus::detail {

std::vector<int> pixels_outside_core(const RasterBuffer& raster, const SymmetryGroup& group) {
    const GridFrame& grid = raster.grid();
    const auto& occ = raster.occupancy();
    const auto& g = group.transforms();
    const int w = grid.width, h = grid.height;
    // A pixel's square maps into the 3 x 3 pixels round the one holding its centre's image:
    // when all of those are free, the whole image is inside the region.
    auto clear_round = [&](int q) {
        if (q < 0) return false;
        const int i = q % w, j = q / w;
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                const int x = i + di, y = j + dj;
                if (x < 0 || y < 0 || x >= w || y >= h) return false;
                if (occ[static_cast<std::size_t>(y * w + x)] ==
                    static_cast<std::uint8_t>(ObstacleKind::boundary))
                    return false;
            }
        return true;
    };
    std::vector<int> out;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int p = j * w + i;
            if (occ[static_cast<std::size_t>(p)] != static_cast<std::uint8_t>(ObstacleKind::none))
                continue;
            const Point c = grid.center_of(i, j);
            for (std::size_t k = 1; k < g.size(); ++k)
                if (!clear_round(raster.pixel_of(g[k].apply(c)))) {
                    out.push_back(p);
                    break;
                }
        }
    return out;
}

std::vector<std::uint8_t> domain_pixels(const GridFrame& grid, const SymmetryGroup& group) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(grid.width) * grid.height, 0);
    for (int j = 0; j < grid.height; ++j)
        for (int i = 0; i < grid.width; ++i)
            out[static_cast<std::size_t>(j * grid.width + i)] =
                group.in_domain(grid.center_of(i, j), grid.pixel) ? 1 : 0;
    return out;
}

bool maps_onto_itself(const Region& region, const SymmetryGroup& group, double tolerance) {
    for (const auto& ring : region.rings(tolerance / 4))
        for (Point p : ring)
            for (std::size_t k = 1; k < group.size(); ++k)
                if (region.distance_to_boundary(group.transforms()[k].apply(p)) > tolerance)
                    return false;
    return true;
}

bool core_contains(const Region& region, const SymmetryGroup& group, Point p) {
    for (const Isometry& g : group.transforms())
        if (!region.contains(g.apply(p))) return false;
    return true;
}

double core_distance_to_boundary(const Region& region, const SymmetryGroup& group, Point p) {
    double d = region.distance_to_boundary(p);
    for (std::size_t k = 1; k < group.size(); ++k)
        d = std::min(d, region.distance_to_boundary(group.transforms()[k].apply(p)));
    return d;
}

}  // namespace acanthus::detail
