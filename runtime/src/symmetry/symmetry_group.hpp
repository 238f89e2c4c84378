// The transformations of a rosette group about its centre, and its fundamental domain: the
// wedge the growth loop chooses its empty circles in (docs/symmetry.md).
#pragma once

#include <acanthus/symmetry.hpp>
#include <utility>
#include <vector>

#include "symmetry/isometry.hpp"

namespace acanthus::detail {

class SymmetryGroup {
  public:
    SymmetryGroup(const Symmetry& spec, Point center);

    const Symmetry& spec() const { return spec_; }
    Point center() const { return center_; }
    // Every transformation, the identity first, then the rotations by 2 pi k / N, then (dN)
    // the reflections.
    const std::vector<Isometry>& transforms() const { return transforms_; }
    std::size_t size() const { return transforms_.size(); }
    // The fundamental domain's angle: 2 pi / N (cN) or pi / N (dN).
    double wedge() const { return wedge_; }

    // True when p lies in the fundamental domain, a wedge of angle 2 pi / N (cN) or pi / N (dN)
    // whose first edge points up from the centre, widened by `tolerance` on each side.
    bool in_domain(Point p, double tolerance) const;
    // p moved onto the centre or (dN) onto the nearest mirror when it lies within `tolerance`
    // of it, so that its images coincide with it exactly; else p.
    Point snap(Point p, double tolerance) const;
    // Half the distance from c to its nearest image farther than `tolerance` (infinite when
    // every image coincides with c): a circle about c no larger stays clear of its images.
    double clearance(Point c, double tolerance) const;
    // The domain's two edges, from the centre out to `radius` (none for c1).
    std::vector<std::pair<Point, Point>> domain_edges(double radius) const;

  private:
    Symmetry spec_;
    Point center_;
    double wedge_;  // the domain's angle
    std::vector<Isometry> transforms_;
};

}  // namespace acanthus::detail
