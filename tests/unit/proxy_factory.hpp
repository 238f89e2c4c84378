// Shorthands that build set proxies for the geometry tests.
#pragma once

#include <acanthus/proxy.hpp>
#include <vector>

namespace acanthus::test {

inline PointProxy point_proxy(double x, double y) {
    PointProxy p;
    p.set({x, y});
    return p;
}
inline CircleProxy circle_proxy(double x, double y, double r) {
    CircleProxy c;
    c.set({x, y}, r);
    return c;
}
inline ArcProxy arc_proxy(double x, double y, double r, double start, double end) {
    ArcProxy a;
    a.set({x, y}, r, start, end);
    return a;
}
inline LineSegmentProxy segment_proxy(double x0, double y0, double x1, double y1) {
    LineSegmentProxy s;
    s.set({x0, y0}, {x1, y1});
    return s;
}
inline BezierProxy bezier_proxy(Point c0, Point c1, Point c2, Point c3) {
    BezierProxy b;
    b.set(c0, c1, c2, c3);
    return b;
}
inline PolygonProxy polygon_proxy(std::vector<Point> points) {
    PolygonProxy p;
    p.set(std::move(points));
    return p;
}
inline PolygonProxy rect_proxy(double x0, double y0, double x1, double y1) {
    return polygon_proxy({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

}  // namespace acanthus::test
