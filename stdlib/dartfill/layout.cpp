#include "layout.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

namespace acanthus::dartfill {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using Box = bg::model::box<BoxPoint>;
using Entry = std::pair<Box, std::size_t>;

Box to_box(const Rect& r) { return Box(BoxPoint(r.x0, r.y0), BoxPoint(r.x1, r.y1)); }

}  // namespace

struct Layout::Index {
    bgi::rtree<Entry, bgi::rstar<16>> tree;
};

Layout::Layout(double tolerance) : tolerance_(tolerance), index_(std::make_unique<Index>()) {}
Layout::~Layout() = default;
Layout::Layout(Layout&&) noexcept = default;
Layout& Layout::operator=(Layout&&) noexcept = default;

bool Layout::collides(const PlacedShape& candidate) const {
    for (auto it = index_->tree.qbegin(bgi::intersects(to_box(candidate.bounds())));
         it != index_->tree.qend(); ++it)
        if (shapes_overlap(candidate, shapes_[it->second], tolerance_)) return true;
    return false;
}

bool Layout::circle_collides(Circle c) const {
    Rect box{c.center.x - c.radius, c.center.y - c.radius, c.center.x + c.radius,
             c.center.y + c.radius};
    for (auto it = index_->tree.qbegin(bgi::intersects(to_box(box))); it != index_->tree.qend();
         ++it) {
        Circle o = shapes_[it->second].bounding_circle();
        Vector between = o.center - c.center;
        double reach = o.radius + c.radius;
        if (between.dot(between) < reach * reach) return true;
    }
    return false;
}

void Layout::add(PlacedShape shape) {
    // Indexed by the box of the bounding circle so circle queries find every neighbour.
    Circle c = shape.bounding_circle();
    Rect b = shape.bounds();
    Rect box{std::min(b.x0, c.center.x - c.radius), std::min(b.y0, c.center.y - c.radius),
             std::max(b.x1, c.center.x + c.radius), std::max(b.y1, c.center.y + c.radius)};
    index_->tree.insert({to_box(box), shapes_.size()});
    shapes_.push_back(std::move(shape));
}

}  // namespace acanthus::dartfill
