#include <2geom/rect.h>

#include <acanthus/proxy.hpp>
#include <algorithm>
#include <cmath>

#include "proxy/proxy_path.hpp"

namespace acanthus {

std::string_view to_string(ProxyKind kind) {
    switch (kind) {
        case ProxyKind::point:
            return "point";
        case ProxyKind::circle:
            return "circle";
        case ProxyKind::arc:
            return "arc";
        case ProxyKind::linesegment:
            return "linesegment";
        case ProxyKind::bezier:
            return "bezier";
        case ProxyKind::polygon:
            return "polygon";
    }
    return "unknown";
}

namespace {

bool finite_value(double v) { return std::isfinite(v); }

// Every coordinate finite; a polygon also needs three points to enclose anything.
bool complete(const Proxy& proxy) {
    switch (proxy.kind()) {
        case ProxyKind::point:
            return static_cast<const PointProxy&>(proxy).point().finite();
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            return c.center.finite() && finite_value(c.radius);
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(proxy);
            return a.center.finite() && finite_value(a.radius) && finite_value(a.start) &&
                   finite_value(a.end);
        }
        case ProxyKind::linesegment: {
            const auto& s = static_cast<const LineSegmentProxy&>(proxy);
            return s.p0.finite() && s.p1.finite();
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(proxy);
            return std::all_of(b.c.begin(), b.c.end(), [](Point p) { return p.finite(); });
        }
        case ProxyKind::polygon: {
            const auto& g = static_cast<const PolygonProxy&>(proxy);
            return g.points.size() >= 3 && std::all_of(g.points.begin(), g.points.end(),
                                                       [](Point p) { return p.finite(); });
        }
    }
    return false;
}

Rect points_bounds(const std::vector<Point>& points) {
    Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (Point p : points) {
        r.x0 = std::min(r.x0, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x);
        r.y1 = std::max(r.y1, p.y);
    }
    return r;
}

// Bounds of a counter-clockwise arc: its end points plus every axis extreme (angles k*pi/2)
// that the sweep passes.
Rect arc_bounds(const ArcProxy& a) {
    double sweep = detail::arc_sweep(a.start, a.end);
    std::vector<Point> pts{a.start_point(), a.center.offset(Direction(a.start + sweep), a.radius)};
    double first = std::ceil(a.start / (M_PI / 2)) * (M_PI / 2);
    for (double angle = first; angle <= a.start + sweep; angle += M_PI / 2) {
        pts.push_back(a.center.offset(Direction(angle), a.radius));
    }
    return points_bounds(pts);
}

}  // namespace

bool Proxy::is_set() const {
    if (kind_ == ProxyKind::polygon) {
        // set() with fewer than three points still leaves no area to place.
        return complete(*this);
    }
    return set_ || complete(*this);
}

bool Proxy::finite() const { return complete(*this); }

Rect Proxy::bounds() const {
    switch (kind_) {
        case ProxyKind::point: {
            Point p = static_cast<const PointProxy&>(*this).point();
            return {p.x, p.y, p.x, p.y};
        }
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(*this);
            double r = std::abs(c.radius);
            return {c.center.x - r, c.center.y - r, c.center.x + r, c.center.y + r};
        }
        case ProxyKind::arc:
            return arc_bounds(static_cast<const ArcProxy&>(*this));
        case ProxyKind::linesegment: {
            const auto& s = static_cast<const LineSegmentProxy&>(*this);
            return points_bounds({s.p0, s.p1});
        }
        case ProxyKind::bezier: {
            Geom::OptRect r = detail::proxy_path(*this).boundsExact();
            if (!r) return {NAN, NAN, NAN, NAN};
            return {r->left(), r->top(), r->right(), r->bottom()};
        }
        case ProxyKind::polygon:
            return points_bounds(static_cast<const PolygonProxy&>(*this).points);
    }
    return {NAN, NAN, NAN, NAN};
}

}  // namespace acanthus
