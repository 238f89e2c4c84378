// The gaps between placed shapes as a distance field over a pixel grid of the space: the
// runtime's exact EDT (DistanceField), updated incrementally as shapes are placed.
#pragma once

#include <cstdint>
#include <vector>

#include "container.hpp"
#include "field/distance_field.hpp"
#include "layout.hpp"

namespace acanthus::dartfill {

class GapField {
  public:
    // Rasterizes the space (blocked pixels are boundary sites) and every shape in `layout`.
    GapField(const Container& container, const Layout& layout, int resolution);

    const GridFrame& grid() const { return grid_; }
    const acanthus::detail::DistanceField& field() const { return field_; }
    int size() const { return grid_.width * grid_.height; }
    bool free(int index) const {
        return field_.occupancy(index) == acanthus::detail::ObstacleKind::none;
    }
    std::int64_t squared_distance(int index) const { return field_.squared_distance(index); }
    // Largest squared distance over the grid (0 when nothing is free).
    std::int64_t max_squared_distance() const;
    // Marks the shape's pixels as element sites and updates the field incrementally; appends the
    // new sites and every pixel whose distance changed to `changed` when it is not null.
    void add(const PlacedShape& shape, std::vector<int>* changed = nullptr);
    // A uniformly jittered point inside pixel `index`.
    Point point_in(int index, double u, double v) const;

  private:
    GridFrame grid_;
    acanthus::detail::DistanceField field_;
    std::vector<int> pixels_;
    std::vector<std::uint32_t> stamp_;
    std::uint32_t generation_ = 0;
};

}  // namespace acanthus::dartfill
