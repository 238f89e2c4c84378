#include "geometry/curve_intersection.hpp"

#include <2geom/elliptical-arc.h>

#include <algorithm>
#include <cmath>

namespace acanthus::detail {

namespace {

const Geom::EllipticalArc* circular_arc(const Geom::Curve& c) {
    const auto* arc = dynamic_cast<const Geom::EllipticalArc*>(&c);
    if (!arc || arc->isChord()) return nullptr;
    double rx = arc->ray(Geom::X), ry = arc->ray(Geom::Y);
    return std::abs(rx - ry) <= 1e-12 * std::max(rx, ry) ? arc : nullptr;
}

// Time of a point lying on the arc's circle, if it lies on the arc itself.
bool time_on_arc(const Geom::EllipticalArc& arc, Geom::Point p, double& t) {
    t = arc.nearestTime(p);
    double scale = 1 + arc.ray(Geom::X) + Geom::L2(arc.center());
    return Geom::distance(arc.pointAt(t), p) <= 1e-9 * scale;
}

std::vector<Geom::CurveIntersection> intersect_circular(const Geom::EllipticalArc& a,
                                                        const Geom::EllipticalArc& b) {
    Geom::Point c1 = a.center(), c2 = b.center();
    double r1 = a.ray(Geom::X), r2 = b.ray(Geom::X);
    Geom::Point d = c2 - c1;
    double dist = Geom::L2(d);
    double eps = 1e-12 * (1 + r1 + r2 + Geom::L2(c1));
    // Concentric circles are either apart or the same circle (no isolated crossings).
    if (dist <= eps || dist > r1 + r2 + eps || dist < std::abs(r1 - r2) - eps) return {};
    Geom::Point u = d / dist;
    double along = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist);
    double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
    std::vector<Geom::Point> points{c1 + u * along + Geom::rot90(u) * h};
    if (h > 0) points.push_back(c1 + u * along - Geom::rot90(u) * h);
    std::vector<Geom::CurveIntersection> out;
    for (Geom::Point p : points) {
        double ta = 0, tb = 0;
        if (time_on_arc(a, p, ta) && time_on_arc(b, p, tb)) out.emplace_back(a, b, ta, tb);
    }
    return out;
}

}  // namespace

std::vector<Geom::CurveIntersection> intersect_curves(const Geom::Curve& a, const Geom::Curve& b) {
    const Geom::EllipticalArc* ca = circular_arc(a);
    const Geom::EllipticalArc* cb = circular_arc(b);
    if (ca && cb) return intersect_circular(*ca, *cb);
    return a.intersect(b);
}

}  // namespace acanthus::detail
