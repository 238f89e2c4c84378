#include "gap_field.hpp"

#include <algorithm>

namespace acanthus::dartfill {

GapField::GapField(const Container& container, const Layout& layout, int resolution)
    : grid_(make_grid(container.bounds(), resolution)),
      field_(grid_.width, grid_.height),
      stamp_(static_cast<std::size_t>(grid_.width) * grid_.height, 0) {
    std::vector<std::uint8_t> occupancy = container.rasterize(grid_);
    for (auto& o : occupancy)
        o = static_cast<std::uint8_t>(o ? acanthus::detail::ObstacleKind::boundary
                                        : acanthus::detail::ObstacleKind::none);
    for (const PlacedShape& s : layout.shapes()) {
        pixels_.clear();
        shape_pixels(grid_, s, pixels_);
        for (int p : pixels_)
            if (occupancy[p] == static_cast<std::uint8_t>(acanthus::detail::ObstacleKind::none))
                occupancy[p] = static_cast<std::uint8_t>(acanthus::detail::ObstacleKind::element);
    }
    field_.compute(occupancy);
}

std::int64_t GapField::max_squared_distance() const {
    std::int64_t best = 0;
    for (int i = 0, n = size(); i < n; ++i) {
        std::int64_t d2 = field_.squared_distance(i);
        if (d2 != acanthus::detail::DistanceField::infinite) best = std::max(best, d2);
    }
    return best;
}

void GapField::add(const PlacedShape& shape, std::vector<int>* changed) {
    pixels_.clear();
    shape_pixels(grid_, shape, pixels_);
    // add_sites wants each free pixel once.
    ++generation_;
    std::vector<int> sites;
    sites.reserve(pixels_.size());
    for (int p : pixels_) {
        if (stamp_[p] == generation_ || !free(p)) continue;
        stamp_[p] = generation_;
        sites.push_back(p);
    }
    if (sites.empty()) return;
    field_.add_sites(sites, acanthus::detail::ObstacleKind::element, changed);
    if (changed) changed->insert(changed->end(), sites.begin(), sites.end());
}

Point GapField::point_in(int index, double u, double v) const {
    int i = index % grid_.width, j = index / grid_.width;
    return {grid_.x0 + (i + u) * grid_.pixel, grid_.y0 + (j + v) * grid_.pixel};
}

}  // namespace acanthus::dartfill
