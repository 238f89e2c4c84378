// The exclusive regions placed so far, with a Boost.Geometry R-tree over their boxes for the
// broad phase of overlap queries.
#pragma once

#include <memory>
#include <vector>

#include "placed_shape.hpp"

namespace acanthus::dartfill {

class Layout {
  public:
    explicit Layout(double tolerance);
    ~Layout();
    Layout(Layout&&) noexcept;
    Layout& operator=(Layout&&) noexcept;

    // True when `candidate` overlaps a placed shape deeper than the tolerance.
    bool collides(const PlacedShape& candidate) const;
    // True when the circle meets the bounding circle of a placed shape (Poisson-disk test).
    bool circle_collides(Circle c) const;
    void add(PlacedShape shape);
    const std::vector<PlacedShape>& shapes() const { return shapes_; }
    double tolerance() const { return tolerance_; }

  private:
    struct Index;
    double tolerance_;
    std::vector<PlacedShape> shapes_;
    std::unique_ptr<Index> index_;
};

}  // namespace acanthus::dartfill
