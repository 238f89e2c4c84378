#include "placed_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace acanthus::dartfill {
namespace {

Rect triangle_box(const Triangle& t) {
    return {std::min({t[0].x, t[1].x, t[2].x}), std::min({t[0].y, t[1].y, t[2].y}),
            std::max({t[0].x, t[1].x, t[2].x}), std::max({t[0].y, t[1].y, t[2].y})};
}

// True when the edges of `a` give an axis on which a and b are apart (or only touch).
bool separated_by_edges_of(const Triangle& a, const Triangle& b, double tolerance) {
    for (int i = 0; i < 3; ++i) {
        Vector edge = a[(i + 1) % 3] - a[i];
        double len = edge.length();
        if (len == 0) continue;
        Vector axis = edge.perp() / len;
        double amin = std::numeric_limits<double>::infinity(), amax = -amin;
        double bmin = amin, bmax = -amin;
        for (int k = 0; k < 3; ++k) {
            double pa = axis.dot(a[k] - Point{});
            double pb = axis.dot(b[k] - Point{});
            amin = std::min(amin, pa);
            amax = std::max(amax, pa);
            bmin = std::min(bmin, pb);
            bmax = std::max(bmax, pb);
        }
        if (amax <= bmin + tolerance || bmax <= amin + tolerance) return true;
    }
    return false;
}

}  // namespace

PlacedShape::PlacedShape(const Shape& shape, int shape_index, Pose pose)
    : shape_index_(shape_index), pose_(pose), area_(shape.area() * pose.scale * pose.scale) {
    double c = std::cos(pose.rotation) * pose.scale, s = std::sin(pose.rotation) * pose.scale;
    Point origin = shape.center();
    auto map = [&](Point p) {
        Vector v = p - origin;
        return Point{pose.position.x + c * v.x - s * v.y, pose.position.y + s * v.x + c * v.y};
    };
    outline_.reserve(shape.outline().size());
    for (Point p : shape.outline()) outline_.push_back(map(p));
    triangles_.reserve(shape.triangles().size());
    triangle_bounds_.reserve(shape.triangles().size());
    bounds_ = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
               -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const Triangle& t : shape.triangles()) {
        Triangle m{map(t[0]), map(t[1]), map(t[2])};
        Rect box = triangle_box(m);
        bounds_ = {std::min(bounds_.x0, box.x0), std::min(bounds_.y0, box.y0),
                   std::max(bounds_.x1, box.x1), std::max(bounds_.y1, box.y1)};
        triangles_.push_back(m);
        triangle_bounds_.push_back(box);
    }
    circle_ = {pose.position, shape.radius() * std::abs(pose.scale)};
}

bool PlacedShape::contains(Point p) const {
    if (!bounds_.contains(p)) return false;
    for (std::size_t i = 0; i < triangles_.size(); ++i)
        if (triangle_bounds_[i].contains(p) && point_in_triangle(triangles_[i], p)) return true;
    return false;
}

bool point_in_triangle(const Triangle& t, Point p) {
    double d0 = (t[1] - t[0]).cross(p - t[0]);
    double d1 = (t[2] - t[1]).cross(p - t[1]);
    double d2 = (t[0] - t[2]).cross(p - t[2]);
    bool has_neg = d0 < 0 || d1 < 0 || d2 < 0;
    bool has_pos = d0 > 0 || d1 > 0 || d2 > 0;
    return !(has_neg && has_pos);
}

bool boxes_meet(const Rect& a, const Rect& b) {
    return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

bool triangles_overlap(const Triangle& a, const Triangle& b, double tolerance) {
    return !separated_by_edges_of(a, b, tolerance) && !separated_by_edges_of(b, a, tolerance);
}

bool shapes_overlap(const PlacedShape& a, const PlacedShape& b, double tolerance) {
    Circle ca = a.bounding_circle(), cb = b.bounding_circle();
    Vector between = cb.center - ca.center;
    double reach = ca.radius + cb.radius;
    if (between.dot(between) >= reach * reach) return false;
    if (!boxes_meet(a.bounds(), b.bounds())) return false;
    const auto& ta = a.triangles();
    const auto& tb = b.triangles();
    for (std::size_t i = 0; i < ta.size(); ++i) {
        const Rect& ba = a.triangle_bounds()[i];
        if (!boxes_meet(ba, b.bounds())) continue;
        for (std::size_t j = 0; j < tb.size(); ++j)
            if (boxes_meet(ba, b.triangle_bounds()[j]) &&
                triangles_overlap(ta[i], tb[j], tolerance))
                return true;
    }
    return false;
}

}  // namespace acanthus::dartfill
