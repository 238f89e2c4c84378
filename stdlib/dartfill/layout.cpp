#include "layout.hpp"

#include <algorithm>

namespace acanthus::dartfill {

using acanthus::detail::SpatialIndex;

bool Layout::collides(const PlacedShape& candidate) const {
    return index_.any_of(candidate.bounds(), [&](SpatialIndex::Entry e) {
        return shapes_overlap(candidate, shapes_[e.element], tolerance_);
    });
}

bool Layout::circle_collides(Circle c) const {
    Rect box{c.center.x - c.radius, c.center.y - c.radius, c.center.x + c.radius,
             c.center.y + c.radius};
    return index_.any_of(box, [&](SpatialIndex::Entry e) {
        Circle o = shapes_[e.element].bounding_circle();
        Vector between = o.center - c.center;
        double reach = o.radius + c.radius;
        return between.dot(between) < reach * reach;
    });
}

void Layout::add(PlacedShape shape) {
    // Indexed by the box of the bounding circle so circle queries find every neighbour.
    Circle c = shape.bounding_circle();
    Rect b = shape.bounds();
    Rect box{std::min(b.x0, c.center.x - c.radius), std::min(b.y0, c.center.y - c.radius),
             std::max(b.x1, c.center.x + c.radius), std::max(b.y1, c.center.y + c.radius)};
    index_.insert(static_cast<int>(shapes_.size()), 0, box);
    shapes_.push_back(std::move(shape));
}

}  // namespace acanthus::dartfill
