// Proxy basics: kind names, is_set / finite, exact bounds, conversion to lib2geom curves.
#include <gtest/gtest.h>

#include <acanthus/proxy.hpp>
#include <cmath>

#include "proxy/proxy_path.hpp"
#include "fixtures/proxy_factory.hpp"

namespace acanthus {
namespace {

using namespace detail;

using namespace test;

TEST(Proxy, KindNames) {
    EXPECT_EQ(to_string(ProxyKind::point), "point");
    EXPECT_EQ(to_string(ProxyKind::circle), "circle");
    EXPECT_EQ(to_string(ProxyKind::arc), "arc");
    EXPECT_EQ(to_string(ProxyKind::linesegment), "linesegment");
    EXPECT_EQ(to_string(ProxyKind::bezier), "bezier");
    EXPECT_EQ(to_string(ProxyKind::polygon), "polygon");
    EXPECT_TRUE(is_area(ProxyKind::circle));
    EXPECT_TRUE(is_area(ProxyKind::polygon));
    EXPECT_FALSE(is_area(ProxyKind::arc));
}

TEST(Proxy, FreshProxiesAreUnset) {
    EXPECT_FALSE(PointProxy().is_set());
    EXPECT_FALSE(CircleProxy().is_set());
    EXPECT_FALSE(ArcProxy().is_set());
    EXPECT_FALSE(LineSegmentProxy().is_set());
    EXPECT_FALSE(BezierProxy().is_set());
    EXPECT_FALSE(PolygonProxy().is_set());
    EXPECT_FALSE(CircleProxy().finite());
}

TEST(Proxy, SetMarksSet) {
    EXPECT_TRUE(point_proxy(1, 2).is_set());
    EXPECT_TRUE(circle_proxy(0, 0, 1).is_set());
    EXPECT_TRUE(arc_proxy(0, 0, 1, 0, 1).is_set());
    EXPECT_TRUE(segment_proxy(0, 0, 1, 1).is_set());
    EXPECT_TRUE(bezier_proxy({0, 0}, {1, 0}, {1, 1}, {2, 1}).is_set());
    EXPECT_TRUE(rect_proxy(0, 0, 1, 1).is_set());
    // set() with a non-finite value still counts as set, but is not finite.
    CircleProxy c;
    c.set({0, 0}, NAN);
    EXPECT_TRUE(c.is_set());
    EXPECT_FALSE(c.finite());
}

TEST(Proxy, DirectAssignmentCountsWhenComplete) {
    CircleProxy c;
    c.center = {1, 2};
    EXPECT_FALSE(c.is_set());
    c.radius = 3;
    EXPECT_TRUE(c.is_set());

    ArcProxy a;
    a.center = {0, 0};
    a.radius = 1;
    a.start = 0;
    EXPECT_FALSE(a.is_set());
    a.end = 1;
    EXPECT_TRUE(a.is_set());

    BezierProxy b;
    b.c[0] = {0, 0};
    b.c[1] = {1, 0};
    b.c[2] = {2, 0};
    EXPECT_FALSE(b.is_set());
    b.c[3] = {3, 0};
    EXPECT_TRUE(b.is_set());

    PointProxy p;
    p.x = 1;
    EXPECT_FALSE(p.is_set());
    p.y = 2;
    EXPECT_TRUE(p.is_set());

    LineSegmentProxy s;
    s.p0 = {0, 0};
    EXPECT_FALSE(s.is_set());
    s.p1 = {1, 0};
    EXPECT_TRUE(s.is_set());
}

TEST(Proxy, PolygonNeedsThreePoints) {
    PolygonProxy p;
    p.set({{0, 0}, {1, 1}});
    EXPECT_FALSE(p.is_set());
    p.points.push_back({0, 1});
    EXPECT_TRUE(p.is_set());
    p.points.push_back({NAN, 1});
    EXPECT_FALSE(p.is_set());
}

void expect_rect(Rect r, double x0, double y0, double x1, double y1) {
    EXPECT_NEAR(r.x0, x0, 1e-9);
    EXPECT_NEAR(r.y0, y0, 1e-9);
    EXPECT_NEAR(r.x1, x1, 1e-9);
    EXPECT_NEAR(r.y1, y1, 1e-9);
}

TEST(ProxyBounds, SimpleKinds) {
    expect_rect(point_proxy(3, 4).bounds(), 3, 4, 3, 4);
    expect_rect(circle_proxy(1, 2, 3).bounds(), -2, -1, 4, 5);
    expect_rect(segment_proxy(5, -1, 2, 7).bounds(), 2, -1, 5, 7);
    expect_rect(polygon_proxy({{0, 0}, {4, 1}, {2, 5}, {1, 2}}).bounds(), 0, 0, 4, 5);
}

TEST(ProxyBounds, ArcsByExtremeAngles) {
    // First quadrant (towards +y): from (1, 0) to (0, 1).
    expect_rect(arc_proxy(0, 0, 1, 0, M_PI / 2).bounds(), 0, 0, 1, 1);
    // Wraps through angle 0: the rightmost point (1, 0) is inside the sweep.
    double s = std::sqrt(0.5);
    expect_rect(arc_proxy(0, 0, 1, -M_PI / 4, M_PI / 4).bounds(), s, -s, 1, s);
    expect_rect(arc_proxy(0, 0, 1, 7 * M_PI / 4, M_PI / 4).bounds(), s, -s, 1, s);
    // The complementary arc covers the other three extremes.
    expect_rect(arc_proxy(0, 0, 1, M_PI / 4, -M_PI / 4).bounds(), -1, -1, s, 1);
    expect_rect(arc_proxy(2, 3, 2, 0, 2 * M_PI).bounds(), 0, 1, 4, 5);
}

TEST(ProxyBounds, BezierIsTightAgainstSampling) {
    auto b = bezier_proxy({0, 0}, {10, 20}, {20, -20}, {30, 0});
    Rect r = b.bounds();
    Rect s{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i <= 100000; ++i) {
        Point p = b.at(i / 100000.0);
        s = {std::min(s.x0, p.x), std::min(s.y0, p.y), std::max(s.x1, p.x), std::max(s.y1, p.y)};
    }
    EXPECT_LE(r.x0, s.x0);
    EXPECT_LE(r.y0, s.y0);
    EXPECT_GE(r.x1, s.x1);
    EXPECT_GE(r.y1, s.y1);
    EXPECT_NEAR(r.y0, s.y0, 1e-6);
    EXPECT_NEAR(r.y1, s.y1, 1e-6);
    EXPECT_GT(r.y1, 5.0);  // the control points reach 20, the curve does not
    EXPECT_LT(r.y1, 20.0);
}

TEST(ProxyPath, ArcRunsTowardsIncreasingAngle) {
    // From angle 0 to pi/2 with y down still means from (+x) towards (+y).
    Geom::Path p = detail::proxy_path(arc_proxy(0, 0, 2, 0, M_PI / 2));
    EXPECT_NEAR(p.initialPoint().x(), 2, 1e-12);
    EXPECT_NEAR(p.finalPoint().y(), 2, 1e-12);
    Geom::Point mid = p.pointAt(p.size() / 2.0);
    EXPECT_NEAR(mid.x(), std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(mid.y(), std::sqrt(2.0), 1e-9);
}

TEST(ProxyPath, ArcWrapAround) {
    EXPECT_NEAR(detail::arc_sweep(3 * M_PI / 2, M_PI / 2), M_PI, 1e-12);
    EXPECT_NEAR(detail::arc_sweep(0, 2 * M_PI), 2 * M_PI, 1e-12);
    EXPECT_NEAR(detail::arc_sweep(1, 0.5), 2 * M_PI - 0.5, 1e-12);
    Geom::Path p = detail::proxy_path(arc_proxy(0, 0, 1, 3 * M_PI / 2, M_PI / 2));
    // Passes through (1, 0), never through (-1, 0).
    EXPECT_NEAR(Geom::distance(p.pointAt(p.nearestTime(Geom::Point(2, 0))), Geom::Point(1, 0)), 0,
                1e-9);
    EXPECT_NEAR(Geom::distance(p.pointAt(p.nearestTime(Geom::Point(-2, 0))), Geom::Point(-1, 0)),
                std::sqrt(2.0), 1e-9);
}

TEST(ProxyPath, ClosedAreasAndOpenCurves) {
    Geom::Path circle = detail::proxy_path(circle_proxy(0, 0, 3));
    EXPECT_TRUE(circle.closed());
    EXPECT_EQ(circle.winding(Geom::Point(0, 0)) != 0, true);
    EXPECT_EQ(circle.winding(Geom::Point(4, 0)), 0);
    Geom::Path poly = detail::proxy_path(polygon_proxy({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}));
    EXPECT_TRUE(poly.closed());
    EXPECT_EQ(poly.size_closed(), 5u);
    EXPECT_NE(poly.winding(Geom::Point(1, 0.5)), 0);
    EXPECT_EQ(poly.winding(Geom::Point(2, 3)), 0);  // in the notch
    EXPECT_FALSE(detail::proxy_path(segment_proxy(0, 0, 1, 1)).closed());
    Geom::Path bez = detail::proxy_path(bezier_proxy({0, 0}, {1, 2}, {3, 2}, {4, 0}));
    EXPECT_NEAR(bez.pointAt(0.5).y(), 1.5, 1e-12);
}

}  // namespace
}  // namespace acanthus
