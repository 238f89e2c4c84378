// Overlap rules between every pair of proxy kinds: overlapping, touching within tolerance, apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "fixtures/proxy_factory.hpp"
#include "proxy/overlap.hpp"

namespace acanthus {
namespace {

using namespace detail;

using namespace test;

constexpr double tol = 1e-3;

// Both argument orders must agree.
bool overlap(const Proxy& a, const Proxy& b) {
    bool ab = overlaps(a, b, tol), ba = overlaps(b, a, tol);
    EXPECT_EQ(ab, ba) << "asymmetric overlap between " << to_string(a.kind()) << " and "
                      << to_string(b.kind());
    return ab;
}

// A C shape open to the right: outer 0..30 x 0..30, notch 10..30 x 10..20.
PolygonProxy c_shape() {
    return polygon_proxy(
        {{0, 0}, {30, 0}, {30, 10}, {10, 10}, {10, 20}, {30, 20}, {30, 30}, {0, 30}});
}

TEST(OverlapPoint, PointsAndCurvesNeverOverlapAPoint) {
    EXPECT_FALSE(overlap(point_proxy(1, 1), point_proxy(1, 1)));
    EXPECT_FALSE(overlap(point_proxy(5, 0), segment_proxy(0, 0, 10, 0)));
    EXPECT_FALSE(overlap(point_proxy(1, 0), arc_proxy(0, 0, 1, -1, 1)));
    EXPECT_FALSE(overlap(point_proxy(0, 0), bezier_proxy({0, 0}, {1, 1}, {2, 1}, {3, 0})));
}

TEST(OverlapPoint, PointInCircle) {
    auto c = circle_proxy(0, 0, 10);
    EXPECT_TRUE(overlap(point_proxy(3, 4), c));
    EXPECT_TRUE(overlap(point_proxy(10 - 2 * tol, 0), c));
    EXPECT_FALSE(overlap(point_proxy(10 - 0.5 * tol, 0), c));  // touching within tolerance
    EXPECT_FALSE(overlap(point_proxy(10, 0), c));
    EXPECT_FALSE(overlap(point_proxy(20, 0), c));
}

TEST(OverlapPoint, PointInConcavePolygon) {
    auto c = c_shape();
    EXPECT_TRUE(overlap(point_proxy(5, 15), c));
    EXPECT_TRUE(overlap(point_proxy(20, 5), c));
    EXPECT_FALSE(overlap(point_proxy(20, 15), c));  // in the notch
    EXPECT_FALSE(overlap(point_proxy(20, 10 + 0.5 * tol), c));
    EXPECT_FALSE(overlap(point_proxy(20, 10 - 0.5 * tol), c));
    EXPECT_TRUE(overlap(point_proxy(20, 10 - 2 * tol), c));
}

TEST(OverlapCircle, CircleCircle) {
    auto a = circle_proxy(0, 0, 5);
    EXPECT_TRUE(overlap(a, circle_proxy(8, 0, 5)));
    EXPECT_FALSE(overlap(a, circle_proxy(10, 0, 5)));              // tangent
    EXPECT_FALSE(overlap(a, circle_proxy(10 - 0.5 * tol, 0, 5)));  // within tolerance
    EXPECT_TRUE(overlap(a, circle_proxy(10 - 2 * tol, 0, 5)));
    EXPECT_FALSE(overlap(a, circle_proxy(30, 0, 5)));
    EXPECT_TRUE(overlap(a, circle_proxy(1, 0, 1)));   // contained
    EXPECT_TRUE(overlap(a, circle_proxy(4, 0, 1)));   // contained, internally tangent
    EXPECT_TRUE(overlap(a, circle_proxy(0, 0, 50)));  // containing
}

// Circles and points are decided on their centres and radii (no curves built): the same
// rules hold for a circle of radius 0 (a point deeper than the tolerance in the other) and
// for a circle not set (never overlapping).
TEST(OverlapCircle, DegenerateAndUnsetCircles) {
    auto a = circle_proxy(0, 0, 5);
    EXPECT_TRUE(overlap(a, circle_proxy(4, 0, 0)));
    EXPECT_FALSE(overlap(a, circle_proxy(5 - 0.5 * tol, 0, 0)));
    EXPECT_FALSE(overlap(circle_proxy(0, 0, 0), circle_proxy(0, 0, 0)));
    EXPECT_FALSE(overlap(a, CircleProxy()));
    EXPECT_FALSE(overlap(point_proxy(0, 0), CircleProxy()));
    EXPECT_FALSE(overlap(PointProxy(), a));
}

TEST(OverlapCircle, CirclePolygon) {
    auto square = rect_proxy(0, 0, 10, 10);
    EXPECT_FALSE(overlap(square, circle_proxy(15, 5, 5)));              // tangent to an edge
    EXPECT_FALSE(overlap(square, circle_proxy(15 - 0.5 * tol, 5, 5)));  // within tolerance
    EXPECT_TRUE(overlap(square, circle_proxy(15 - 2 * tol, 5, 5)));
    EXPECT_FALSE(overlap(square, circle_proxy(10 + 3, 10 + 4, 5)));  // touches the corner
    EXPECT_TRUE(overlap(square, circle_proxy(10 + 3, 10 + 4, 5.01)));
    EXPECT_TRUE(overlap(square, circle_proxy(5, 5, 1)));   // inside
    EXPECT_TRUE(overlap(square, circle_proxy(5, 5, 20)));  // contains the square
    EXPECT_FALSE(overlap(square, circle_proxy(30, 30, 5)));
}

TEST(OverlapCircle, CircleInTheNotchOfAConcavePolygon) {
    auto c = c_shape();
    EXPECT_FALSE(overlap(c, circle_proxy(20, 15, 4)));    // free in the notch
    EXPECT_FALSE(overlap(c, circle_proxy(20, 15, 5)));    // tangent to both walls
    EXPECT_FALSE(overlap(c, circle_proxy(15, 15, 5)));    // tangent to three walls
    EXPECT_TRUE(overlap(c, circle_proxy(20, 15, 5.01)));  // presses into the walls
    EXPECT_TRUE(overlap(c, circle_proxy(14.99, 15, 5)));  // presses into the back wall
    EXPECT_TRUE(overlap(c, circle_proxy(20, 15 + 0.01, 5)));
}

TEST(OverlapPolygon, PolygonPolygon) {
    auto a = rect_proxy(0, 0, 10, 10);
    EXPECT_FALSE(overlap(a, rect_proxy(10, 0, 20, 10)));              // shared edge
    EXPECT_FALSE(overlap(a, rect_proxy(10, 5, 20, 15)));              // partly shared edge
    EXPECT_FALSE(overlap(a, rect_proxy(10 - 0.5 * tol, 0, 20, 10)));  // within tolerance
    EXPECT_TRUE(overlap(a, rect_proxy(10 - 2 * tol, 0, 20, 10)));
    EXPECT_FALSE(overlap(a, rect_proxy(10, 10, 20, 20)));  // corner to corner
    EXPECT_TRUE(overlap(a, rect_proxy(9, 9, 20, 20)));
    EXPECT_TRUE(overlap(a, rect_proxy(0, 0, 10, 10)));    // identical
    EXPECT_TRUE(overlap(a, rect_proxy(2, 2, 4, 4)));      // contained
    EXPECT_TRUE(overlap(a, rect_proxy(-5, -5, 15, 15)));  // containing
    EXPECT_FALSE(overlap(a, rect_proxy(20, 20, 30, 30)));
    // A plus: no vertex of either lies in the other.
    EXPECT_TRUE(overlap(rect_proxy(-10, -1, 10, 1), rect_proxy(-1, -10, 1, 10)));
    // A triangle poking into the square.
    EXPECT_TRUE(overlap(a, polygon_proxy({{5, 9}, {8, 20}, {2, 20}})));
    EXPECT_FALSE(overlap(a, polygon_proxy({{5, 10 + 0.5 * tol}, {8, 20}, {2, 20}})));
    EXPECT_FALSE(overlap(a, polygon_proxy({{5, 10 - 0.5 * tol}, {8, 20}, {2, 20}})));
}

TEST(OverlapPolygon, SquareInTheNotch) {
    auto c = c_shape();
    EXPECT_FALSE(overlap(c, rect_proxy(10, 10, 30, 20)));  // fills the notch exactly
    EXPECT_FALSE(overlap(c, rect_proxy(12, 12, 18, 18)));
    EXPECT_TRUE(overlap(c, rect_proxy(12, 9, 18, 18)));
    EXPECT_TRUE(overlap(c, rect_proxy(5, 12, 18, 18)));
}

TEST(OverlapCurveArea, SegmentCircle) {
    auto c = circle_proxy(0, 0, 5);
    EXPECT_TRUE(overlap(c, segment_proxy(-10, 0, 10, 0)));   // through
    EXPECT_FALSE(overlap(c, segment_proxy(-10, 5, 10, 5)));  // tangent
    EXPECT_FALSE(overlap(c, segment_proxy(-10, 5 - 0.5 * tol, 10, 5 - 0.5 * tol)));
    EXPECT_TRUE(overlap(c, segment_proxy(-10, 5 - 2 * tol, 10, 5 - 2 * tol)));
    EXPECT_FALSE(overlap(c, segment_proxy(5, 0, 20, 0)));  // a stem ending on the rim
    EXPECT_TRUE(overlap(c, segment_proxy(0, 0, 20, 0)));   // a stem starting at the centre
    EXPECT_TRUE(overlap(c, segment_proxy(-1, 0, 1, 0)));   // entirely inside
    EXPECT_FALSE(overlap(c, segment_proxy(10, 10, 20, 20)));
}

TEST(OverlapCurveArea, ArcAndBezierCircle) {
    auto c = circle_proxy(0, 0, 5);
    EXPECT_FALSE(overlap(c, arc_proxy(0, 0, 5 + 0.5 * tol, 0, 3)));  // hugs the rim outside
    EXPECT_FALSE(overlap(c, arc_proxy(0, 0, 5 - 0.5 * tol, 0, 3)));  // hugs it inside
    EXPECT_TRUE(overlap(c, arc_proxy(0, 0, 4, 0, 1)));
    EXPECT_TRUE(overlap(c, arc_proxy(10, 0, 6, 2, 4)));   // crosses the rim
    EXPECT_FALSE(overlap(c, arc_proxy(10, 0, 5, 2, 4)));  // externally tangent at (5, 0)
    // A Bezier crossing the circle, one bulging just clear of it, one grazing it.
    EXPECT_TRUE(overlap(c, bezier_proxy({-10, 8}, {-3, -2}, {3, -2}, {10, 8})));
    EXPECT_FALSE(overlap(c, bezier_proxy({-10, -8}, {-4, -5}, {4, -5}, {10, -8})));
    // Symmetric cubic bulging down to y = -5 exactly at its middle: tangent to the circle.
    EXPECT_FALSE(overlap(c, bezier_proxy({-10, -5}, {-3, -5}, {3, -5}, {10, -5})));
}

TEST(OverlapCurveArea, CurvePolygon) {
    auto square = rect_proxy(0, 0, 10, 10);
    EXPECT_TRUE(overlap(square, segment_proxy(-5, 5, 15, 5)));
    EXPECT_FALSE(overlap(square, segment_proxy(-5, 10, 15, 10)));  // along an edge
    EXPECT_FALSE(overlap(square, segment_proxy(0, 10 - 0.5 * tol, 10, 10 - 0.5 * tol)));
    EXPECT_TRUE(overlap(square, segment_proxy(0, 10 - 2 * tol, 10, 10 - 2 * tol)));
    EXPECT_FALSE(overlap(square, segment_proxy(5, 10, 5, 20)));    // T-junction on an edge
    EXPECT_FALSE(overlap(square, segment_proxy(10, 10, 20, 20)));  // from the corner
    EXPECT_TRUE(overlap(square, segment_proxy(5, 5, 5, 20)));
    // Clipping a corner less deeply than the tolerance.
    EXPECT_FALSE(overlap(square, segment_proxy(8.9995, 11, 11, 8.9995)));
    EXPECT_FALSE(overlap(square, segment_proxy(9, 11, 11, 9)));  // through the corner
    EXPECT_TRUE(overlap(square, segment_proxy(8, 11, 11, 8)));
    EXPECT_TRUE(overlap(square, bezier_proxy({-5, 12}, {0, 0}, {10, 0}, {15, 12})));
    EXPECT_FALSE(overlap(square, bezier_proxy({-5, 12}, {0, 10}, {10, 10}, {15, 12})));
    EXPECT_TRUE(overlap(square, arc_proxy(5, 5, 3, 0, 1)));
    EXPECT_FALSE(overlap(square, arc_proxy(5, 5, 20, 0, 6)));  // encircles it
    auto c = c_shape();
    EXPECT_FALSE(overlap(c, segment_proxy(12, 15, 40, 15)));  // in the notch
    EXPECT_FALSE(overlap(c, arc_proxy(20, 15, 5, 0, 6)));     // tangent to the notch walls
    EXPECT_TRUE(overlap(c, segment_proxy(12, 15, 12, 35)));
}

TEST(OverlapCurveCurve, Segments) {
    EXPECT_TRUE(overlap(segment_proxy(0, 0, 10, 10), segment_proxy(0, 10, 10, 0)));
    EXPECT_FALSE(overlap(segment_proxy(0, 0, 10, 0), segment_proxy(10, 0, 20, 5)));  // chained
    EXPECT_FALSE(overlap(segment_proxy(0, 0, 10, 0), segment_proxy(5, 0, 5, 10)));   // T
    EXPECT_FALSE(overlap(segment_proxy(0, 0, 10, 0), segment_proxy(0, 1, 10, 1)));   // parallel
    EXPECT_FALSE(overlap(segment_proxy(0, 0, 10, 0), segment_proxy(20, 0, 30, 0)));
    // An end poking through by half the tolerance, and by five times it.
    EXPECT_FALSE(overlap(segment_proxy(0, 0, 10, 0), segment_proxy(5, 10, 5, -0.5 * tol)));
    EXPECT_TRUE(overlap(segment_proxy(0, 0, 10, 0), segment_proxy(5, 10, 5, -5 * tol)));
}

TEST(OverlapCurveCurve, ArcsIncludingWrapAround) {
    // Counter-clockwise from 3pi/2 to pi/2 wraps through angle 0 (the +x side).
    auto right = arc_proxy(0, 0, 5, 3 * M_PI / 2, M_PI / 2);
    EXPECT_TRUE(overlap(right, segment_proxy(0, 0, 10, 0)));
    EXPECT_FALSE(overlap(right, segment_proxy(0, 0, -10, 0)));   // the -x side is not on it
    EXPECT_FALSE(overlap(right, segment_proxy(5, -10, 5, 10)));  // tangent at (5, 0)
    EXPECT_TRUE(overlap(right, segment_proxy(4, -10, 4, 10)));
    EXPECT_TRUE(overlap(right, arc_proxy(5, 0, 5, 0, 2 * M_PI)));
    EXPECT_FALSE(overlap(right, arc_proxy(0, 0, 5, M_PI / 2, 3 * M_PI / 2)));   // its complement
    EXPECT_FALSE(overlap(right, arc_proxy(10, 0, 5, M_PI / 2, 3 * M_PI / 2)));  // tangent
}

TEST(OverlapCurveCurve, Beziers) {
    auto s = bezier_proxy({0, 0}, {3, 10}, {7, -10}, {10, 0});
    EXPECT_TRUE(overlap(s, segment_proxy(0, 1, 10, -1)));
    EXPECT_TRUE(overlap(s, bezier_proxy({0, 5}, {3, -5}, {7, 5}, {10, -5})));
    EXPECT_FALSE(overlap(s, bezier_proxy({10, 0}, {13, 10}, {17, -10}, {20, 0})));  // chained
    EXPECT_FALSE(overlap(s, segment_proxy(0, 10, 10, 10)));
}

TEST(OverlapTolerance, ZeroToleranceStillSeparatesTouching) {
    EXPECT_FALSE(overlaps(circle_proxy(0, 0, 1), circle_proxy(2, 0, 1), 0));
    EXPECT_TRUE(overlaps(circle_proxy(0, 0, 1), circle_proxy(1.999, 0, 1), 0));
    EXPECT_FALSE(overlaps(rect_proxy(0, 0, 1, 1), rect_proxy(1, 0, 2, 1), 0));
}

// --- randomized agreement with closed forms --------------------------------------------------

struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

double segment_point_distance(Point a, Point b, Point p) {
    Vector ab = b - a;
    double t = std::clamp((p - a).dot(ab) / ab.dot(ab), 0.0, 1.0);
    return distance(p, a + ab * t);
}

TEST(OverlapRandom, SegmentCircleMatchesClosedForm) {
    Lcg rng{42};
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
        Point a{rng.in(-20, 20), rng.in(-20, 20)}, b{rng.in(-20, 20), rng.in(-20, 20)};
        Point c{rng.in(-10, 10), rng.in(-10, 10)};
        double r = rng.in(0.5, 10);
        double margin = r - tol - segment_point_distance(a, b, c);
        if (std::abs(margin) < 1e-7) continue;
        EXPECT_EQ(overlap(segment_proxy(a.x, a.y, b.x, b.y), circle_proxy(c.x, c.y, r)),
                  margin > 0);
        ++checked;
    }
    EXPECT_GT(checked, 350);
}

TEST(OverlapRandom, TriangleCircleMatchesClosedForm) {
    Lcg rng{7};
    for (int i = 0; i < 300; ++i) {
        std::vector<Point> tri{{rng.in(-10, 10), rng.in(-10, 10)},
                               {rng.in(-10, 10), rng.in(-10, 10)},
                               {rng.in(-10, 10), rng.in(-10, 10)}};
        Point c{rng.in(-15, 15), rng.in(-15, 15)};
        double r = rng.in(0.5, 6);
        double d = INFINITY;
        for (int k = 0; k < 3; ++k)
            d = std::min(d, segment_point_distance(tri[k], tri[(k + 1) % 3], c));
        // Inside: same sign of all edge cross products.
        double s0 = (tri[1] - tri[0]).cross(c - tri[0]), s1 = (tri[2] - tri[1]).cross(c - tri[1]),
               s2 = (tri[0] - tri[2]).cross(c - tri[2]);
        bool inside = (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
        if (std::abs(d - (r - tol)) < 1e-7) continue;
        bool expected = d < r - tol || (inside && std::max(d, r) > tol);
        EXPECT_EQ(overlap(polygon_proxy(tri), circle_proxy(c.x, c.y, r)), expected) << i;
    }
}

TEST(OverlapRandom, SegmentSegmentMatchesProperCrossing) {
    Lcg rng{99};
    for (int i = 0; i < 400; ++i) {
        Point a{rng.in(0, 10), rng.in(0, 10)}, b{rng.in(0, 10), rng.in(0, 10)};
        Point c{rng.in(0, 10), rng.in(0, 10)}, d{rng.in(0, 10), rng.in(0, 10)};
        // Proper crossing with every end farther than the tolerance from the other segment.
        double o1 = (b - a).cross(c - a), o2 = (b - a).cross(d - a);
        double o3 = (d - c).cross(a - c), o4 = (d - c).cross(b - c);
        bool crossing = (o1 > 0) != (o2 > 0) && (o3 > 0) != (o4 > 0);
        double m = std::min({segment_point_distance(a, b, c), segment_point_distance(a, b, d),
                             segment_point_distance(c, d, a), segment_point_distance(c, d, b)});
        if (std::abs(m - tol) < 1e-7) continue;
        bool expected = crossing && m > tol;
        EXPECT_EQ(overlap(segment_proxy(a.x, a.y, b.x, b.y), segment_proxy(c.x, c.y, d.x, d.y)),
                  expected)
            << i;
    }
}

}  // namespace
}  // namespace acanthus
