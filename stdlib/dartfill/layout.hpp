// The exclusive regions placed so far, in the runtime's spatial index (an R-tree over their
// boxes) for the broad phase of overlap queries.
#pragma once

#include <vector>

#include "geometry/spatial_index.hpp"
#include "placed_shape.hpp"

namespace acanthus::dartfill {

class Layout {
  public:
    explicit Layout(double tolerance) : tolerance_(tolerance) {}

    // True when `candidate` overlaps a placed shape deeper than the tolerance.
    bool collides(const PlacedShape& candidate) const;
    // True when the circle meets the bounding circle of a placed shape (Poisson-disk test).
    bool circle_collides(Circle c) const;
    void add(PlacedShape shape);
    const std::vector<PlacedShape>& shapes() const { return shapes_; }
    double tolerance() const { return tolerance_; }

  private:
    double tolerance_;
    std::vector<PlacedShape> shapes_;
    // Entry::element is the index in shapes_, indexed by the box of its bounding circle.
    acanthus::detail::SpatialIndex index_;
};

}  // namespace acanthus::dartfill
