// A region's boundary made ready for queries: closed copies of its loops, their curves behind
// one BoundaryDistance (positive outside the region, indexed when there are many) and the
// winding number through the same index.
#pragma once

#include <2geom/pathvector.h>

#include <memory>

#include "geometry/boundary_distance.hpp"

namespace acanthus::detail {

class RegionBoundary {
  public:
    RegionBoundary(const Geom::PathVector& paths, bool evenodd);
    RegionBoundary(const RegionBoundary&) = delete;
    RegionBoundary& operator=(const RegionBoundary&) = delete;

    const Geom::PathVector& loops() const { return loops_; }
    // Signed distance positive outside; curves() are the loops' curves.
    const BoundaryDistance& outside() const { return *outside_; }
    int winding(Geom::Point p) const;
    bool contains(Geom::Point p) const;

  private:
    Geom::PathVector loops_;
    bool evenodd_;
    double right_ = 0;  // right edge of the loops' bounds, where winding rays end
    std::unique_ptr<BoundaryDistance> outside_;
};

}  // namespace acanthus::detail
