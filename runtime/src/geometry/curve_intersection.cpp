#include "geometry/curve_intersection.hpp"

#include <2geom/bezier-curve.h>
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

double segment_distance(Geom::Point p, Geom::Point a, Geom::Point b) {
    const Geom::Point d = b - a;
    const double len2 = Geom::dot(d, d);
    const double t = len2 > 0 ? std::clamp(Geom::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return Geom::distance(p, a + d * t);
}

bool in_triangle(Geom::Point p, Geom::Point a, Geom::Point b, Geom::Point c) {
    const double s1 = Geom::cross(b - a, p - a), s2 = Geom::cross(c - b, p - b),
                 s3 = Geom::cross(a - c, p - c);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

// Whether the Bezier curve surely misses the arc's whole circle: its control points' hull (which
// holds the curve) lies inside the disc, or away from it, by a margin. lib2geom's ellipse-Bezier
// solver (a polynomial of degree 2n) is most of the growth's time where element circles meet a
// region's sides; most such pairs do not cross.
bool misses_circle(const Geom::EllipticalArc& arc, const Geom::BezierCurve& bezier) {
    const Geom::Point c = arc.center();
    const double r = arc.ray(Geom::X);
    const std::size_t n = bezier.size();
    if (n < 2 || n > 4) return false;
    Geom::Point p[4];
    for (std::size_t i = 0; i < n; ++i) p[i] = bezier.controlPoint(i);
    double scale = 1 + r + Geom::L2(c);
    for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, Geom::L2(p[i]));
    const double margin = 1e-6 * scale;
    double farthest = 0;
    for (std::size_t i = 0; i < n; ++i) farthest = std::max(farthest, Geom::distance(c, p[i]));
    if (farthest < r - margin) return true;
    // The hull's edges are among the segments between control points; the hull is the union
    // of the triangles of three of them.
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (segment_distance(c, p[i], p[j]) <= r + margin) return false;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (std::size_t k = j + 1; k < n; ++k)
                if (in_triangle(c, p[i], p[j], p[k])) return false;
    return true;
}

// Whether two curves' bounds (which hold the curves) are apart by more than the solvers'
// resolution: then they cannot meet. lib2geom's solvers do not test this first, and most pairs
// the growth asks about (a proxy against the region's sides) are far apart.
bool apart(const Geom::Rect& a, const Geom::Rect& b) {
    const double scale =
        1 + std::max({std::abs(a.left()), std::abs(a.right()), std::abs(a.top()),
                      std::abs(a.bottom()), std::abs(b.left()), std::abs(b.right()),
                      std::abs(b.top()), std::abs(b.bottom())});
    const double margin = 1e-4 * scale;
    return a.left() > b.right() + margin || b.left() > a.right() + margin ||
           a.top() > b.bottom() + margin || b.top() > a.bottom() + margin;
}

}  // namespace

std::vector<Geom::CurveIntersection> intersect_curves(const Geom::Curve& a, const Geom::Curve& b) {
    if (apart(a.boundsFast(), b.boundsFast())) return {};
    const Geom::EllipticalArc* ca = circular_arc(a);
    const Geom::EllipticalArc* cb = circular_arc(b);
    if (ca && cb) return intersect_circular(*ca, *cb);
    if (ca) {
        const auto* bezier = dynamic_cast<const Geom::BezierCurve*>(&b);
        if (bezier && misses_circle(*ca, *bezier)) return {};
    } else if (cb) {
        const auto* bezier = dynamic_cast<const Geom::BezierCurve*>(&a);
        if (bezier && misses_circle(*cb, *bezier)) return {};
    }
    return a.intersect(b);
}

}  // namespace acanthus::detail
