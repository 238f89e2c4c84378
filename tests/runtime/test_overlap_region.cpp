// leaves_region against a rectangle, a region with a hole and curved regions; distance_to
// against brute-force sampling.
#include <2geom/bezier-curve.h>
#include <2geom/circle.h>
#include <2geom/path.h>
#include <2geom/rect.h>
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <cmath>
#include <cstdint>

#include "fixtures/proxy_factory.hpp"
#include "proxy/overlap.hpp"
#include "region/region_data.hpp"

namespace acanthus {
namespace {

using namespace detail;

using namespace test;

constexpr double tol = 1e-3;

detail::RegionData make_region(Geom::PathVector paths, bool evenodd) {
    detail::RegionData r;
    r.name = "test";
    r.paths = std::move(paths);
    r.evenodd = evenodd;
    Geom::OptRect box = r.paths.boundsExact();
    r.bounds = {box->left(), box->top(), box->right(), box->bottom()};
    detail::set_boundary(r);
    return r;
}

detail::RegionData rect_region() {
    return make_region(Geom::PathVector(Geom::Path(Geom::Rect(0, 0, 100, 80))), false);
}

// 100 x 80 with a 20 x 20 hole at (40..60, 30..50).
detail::RegionData holed_region(bool evenodd) {
    Geom::PathVector pv;
    pv.push_back(Geom::Path(Geom::Rect(0, 0, 100, 80)));
    Geom::Path hole(Geom::Rect(40, 30, 60, 50));
    // Under the nonzero rule a hole must wind the other way.
    pv.push_back(evenodd ? hole : hole.reversed());
    return make_region(pv, evenodd);
}

TEST(LeavesRegion, PointInRectangle) {
    auto r = rect_region();
    EXPECT_FALSE(leaves_region(point_proxy(50, 40), r, tol));
    EXPECT_FALSE(leaves_region(point_proxy(100, 40), r, tol));
    EXPECT_FALSE(leaves_region(point_proxy(100 + 0.5 * tol, 40), r, tol));
    EXPECT_TRUE(leaves_region(point_proxy(100 + 2 * tol, 40), r, tol));
    EXPECT_TRUE(leaves_region(point_proxy(-5, -5), r, tol));
}

TEST(LeavesRegion, CircleInRectangle) {
    auto r = rect_region();
    EXPECT_FALSE(leaves_region(circle_proxy(50, 40, 10), r, tol));
    EXPECT_FALSE(leaves_region(circle_proxy(90, 40, 10), r, tol));  // tangent inside
    EXPECT_FALSE(leaves_region(circle_proxy(90 + 0.5 * tol, 40, 10), r, tol));
    EXPECT_TRUE(leaves_region(circle_proxy(90 + 2 * tol, 40, 10), r, tol));
    EXPECT_FALSE(leaves_region(circle_proxy(10, 10, 10), r, tol));  // in the corner
    EXPECT_TRUE(leaves_region(circle_proxy(50, 40, 100), r, tol));  // covers the region
    EXPECT_TRUE(leaves_region(circle_proxy(200, 200, 5), r, tol));
}

TEST(LeavesRegion, CurvesInRectangle) {
    auto r = rect_region();
    EXPECT_FALSE(leaves_region(segment_proxy(10, 10, 90, 70), r, tol));
    EXPECT_FALSE(leaves_region(segment_proxy(0, 0, 100, 0), r, tol));  // along the boundary
    EXPECT_TRUE(leaves_region(segment_proxy(50, 40, 150, 40), r, tol));
    EXPECT_TRUE(leaves_region(segment_proxy(150, 40, 160, 40), r, tol));
    EXPECT_FALSE(leaves_region(segment_proxy(50, 40, 100 + 0.5 * tol, 40), r, tol));
    EXPECT_TRUE(leaves_region(segment_proxy(50, 40, 100 + 2 * tol, 40), r, tol));
    EXPECT_FALSE(leaves_region(arc_proxy(50, 40, 20, 5, 1), r, tol));  // wraps, stays inside
    EXPECT_TRUE(leaves_region(arc_proxy(50, 40, 55, -0.5, 0.5), r, tol));
    EXPECT_FALSE(leaves_region(arc_proxy(50, 40, 40, 1, 2), r, tol));  // tangent to y = 80
    EXPECT_FALSE(leaves_region(bezier_proxy({10, 70}, {30, 80}, {70, 80}, {90, 70}), r, tol));
    EXPECT_TRUE(leaves_region(bezier_proxy({10, 70}, {30, 100}, {70, 100}, {90, 70}), r, tol));
}

TEST(LeavesRegion, PolygonInRectangle) {
    auto r = rect_region();
    EXPECT_FALSE(leaves_region(rect_proxy(10, 10, 20, 20), r, tol));
    EXPECT_FALSE(leaves_region(rect_proxy(0, 0, 100, 80), r, tol));  // the region itself
    EXPECT_FALSE(leaves_region(rect_proxy(90, 0, 100 + 0.5 * tol, 10), r, tol));
    EXPECT_TRUE(leaves_region(rect_proxy(90, 0, 100 + 2 * tol, 10), r, tol));
    EXPECT_TRUE(leaves_region(rect_proxy(-10, -10, 110, 90), r, tol));
    EXPECT_TRUE(leaves_region(polygon_proxy({{50, 40}, {120, 50}, {50, 60}}), r, tol));
}

class LeavesHoledRegion : public ::testing::TestWithParam<bool> {};

TEST_P(LeavesHoledRegion, EveryKind) {
    auto r = holed_region(GetParam());
    EXPECT_TRUE(leaves_region(point_proxy(50, 40), r, tol));  // in the hole
    EXPECT_FALSE(leaves_region(point_proxy(20, 40), r, tol));
    EXPECT_TRUE(leaves_region(circle_proxy(50, 40, 20), r, tol));  // swallows the hole
    EXPECT_TRUE(leaves_region(circle_proxy(50, 40, 5), r, tol));   // inside the hole
    EXPECT_FALSE(leaves_region(circle_proxy(20, 40, 10), r, tol));
    EXPECT_FALSE(leaves_region(circle_proxy(50, 20, 10), r, tol));  // tangent to the hole
    EXPECT_TRUE(leaves_region(circle_proxy(50, 20 + 2 * tol, 10), r, tol));
    EXPECT_TRUE(leaves_region(segment_proxy(20, 40, 80, 40), r, tol));   // across the hole
    EXPECT_FALSE(leaves_region(segment_proxy(20, 40, 40, 40), r, tol));  // ends on its edge
    EXPECT_TRUE(leaves_region(arc_proxy(50, 40, 5, 0, 3), r, tol));
    EXPECT_FALSE(leaves_region(arc_proxy(50, 40, 25, 0, 3), r, tol));  // circles around it
    EXPECT_TRUE(leaves_region(bezier_proxy({20, 40}, {40, 30}, {60, 50}, {80, 40}), r, tol));
    EXPECT_TRUE(leaves_region(rect_proxy(35, 25, 65, 55), r, tol));   // frames the hole
    EXPECT_FALSE(leaves_region(rect_proxy(10, 10, 40, 70), r, tol));  // shares its left edge
}

INSTANTIATE_TEST_SUITE_P(FillRules, LeavesHoledRegion, ::testing::Values(true, false));

TEST(LeavesRegion, CircularRegionIsExact) {
    auto r = make_region(Geom::PathVector(Geom::Path(Geom::Circle(50, 50, 40))), false);
    for (double angle : {0.0, 0.7, 2.0, 4.0}) {
        Point dir = Point{0, 0}.offset(Direction(angle), 1);
        auto at = [&](double d, double rad) {
            return circle_proxy(50 + dir.x * d, 50 + dir.y * d, rad);
        };
        EXPECT_FALSE(leaves_region(at(30, 10), r, tol)) << angle;  // internally tangent
        EXPECT_FALSE(leaves_region(at(30 + 0.5 * tol, 10), r, tol)) << angle;
        EXPECT_TRUE(leaves_region(at(30 + 2 * tol, 10), r, tol)) << angle;
        Point p = Point{50, 50}.offset(Direction(angle), 40 + 2 * tol);
        EXPECT_TRUE(leaves_region(segment_proxy(50, 50, p.x, p.y), r, tol)) << angle;
        p = Point{50, 50}.offset(Direction(angle), 40 + 0.5 * tol);
        EXPECT_FALSE(leaves_region(segment_proxy(50, 50, p.x, p.y), r, tol)) << angle;
    }
}

TEST(LeavesRegion, ArcLeavingBetweenItsSamplePoints) {
    // The arc's ends and middle lie inside the disc; only |angle| < 0.23 pokes out (by 0.05).
    auto r = make_region(Geom::PathVector(Geom::Path(Geom::Circle(0, 0, 10))), false);
    EXPECT_TRUE(leaves_region(arc_proxy(2.5, 0, 7.55, -0.3, 1.2), r, tol));
    EXPECT_FALSE(leaves_region(arc_proxy(2.5, 0, 7.5, -0.3, 1.2), r, tol));  // tangent
    EXPECT_FALSE(leaves_region(arc_proxy(2.5, 0, 7.5 + 0.5 * tol, -0.3, 1.2), r, tol));
}

TEST(LeavesRegion, BezierBoundedRegion) {
    // A rounded blob of four cubics around (50, 50).
    Geom::Path blob(Geom::Point(90, 50));
    blob.append(Geom::CubicBezier({90, 50}, {90, 80}, {80, 90}, {50, 90}));
    blob.append(Geom::CubicBezier({50, 90}, {20, 90}, {10, 80}, {10, 50}));
    blob.append(Geom::CubicBezier({10, 50}, {10, 20}, {20, 10}, {50, 10}));
    blob.append(Geom::CubicBezier({50, 10}, {80, 10}, {90, 20}, {90, 50}));
    blob.close(true);
    auto r = make_region(Geom::PathVector(blob), false);
    EXPECT_FALSE(leaves_region(circle_proxy(50, 50, 30), r, tol));
    EXPECT_TRUE(leaves_region(circle_proxy(50, 50, 45), r, tol));
    EXPECT_FALSE(leaves_region(circle_proxy(80, 50, 10), r, tol));  // tangent at (90, 50)
    EXPECT_TRUE(leaves_region(circle_proxy(80 + 2 * tol, 50, 10), r, tol));
    EXPECT_FALSE(leaves_region(segment_proxy(50, 50, 90, 50), r, tol));  // ends on it
    EXPECT_TRUE(leaves_region(segment_proxy(50, 50, 90 + 2 * tol, 50), r, tol));
    EXPECT_FALSE(leaves_region(polygon_proxy({{50, 50}, {90, 50}, {50, 90}}), r, tol));
}

TEST(LeavesRegion, CircleHoldingAHoleOfCubics) {
    // A lens-shaped hole of two cubics, 7.5 from (50, 50) at its nearest: a circle holding it
    // leaves the region though its outline stays inside; one short of it does not.
    Geom::PathVector pv;
    pv.push_back(Geom::Path(Geom::Rect(0, 0, 100, 100)));
    Geom::Path hole(Geom::Point(40, 50));
    hole.append(Geom::CubicBezier({40, 50}, {40, 60}, {60, 60}, {60, 50}));
    hole.append(Geom::CubicBezier({60, 50}, {60, 40}, {40, 40}, {40, 50}));
    hole.close(true);
    pv.push_back(hole);
    auto r = make_region(pv, true);
    EXPECT_TRUE(leaves_region(circle_proxy(50, 50, 20), r, tol));
    EXPECT_FALSE(leaves_region(circle_proxy(50, 20, 12), r, tol));
}

TEST(LeavesRegion, RegionFromSpec) {
    Region region = Region::from_spec("rect:100,80");
    EXPECT_FALSE(leaves_region(circle_proxy(50, 40, 10), region, tol));
    EXPECT_TRUE(leaves_region(circle_proxy(95, 40, 10), region, tol));
}

// --- distance_to against sampling ------------------------------------------------------------

struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

constexpr int samples = 20000;

template <class F>
double sampled_distance(Point q, F point_at) {
    double best = INFINITY;
    for (int i = 0; i <= samples; ++i)
        best = std::min(best, distance(q, point_at(double(i) / samples)));
    return best;
}

bool inside_polygon(const std::vector<Point>& pts, Point q) {
    bool in = false;
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
        if ((pts[i].y > q.y) != (pts[j].y > q.y) &&
            q.x < (pts[j].x - pts[i].x) * (q.y - pts[i].y) / (pts[j].y - pts[i].y) + pts[i].x) {
            in = !in;
        }
    }
    return in;
}

// Exact distance never exceeds the sampled one and is within the sample spacing of it.
void expect_distance(const Proxy& p, Point q, double sampled, double spacing) {
    double exact = distance_to(p, q);
    EXPECT_LE(exact, sampled + 1e-9) << to_string(p.kind());
    EXPECT_GE(exact, sampled - spacing) << to_string(p.kind());
}

// Shapes whose bounds no boundary curve meets are answered without the exact tests (inside:
// no); the answer is the exact tests' one. A tolerance just below 0 takes the exact tests for
// every shape: the same answers for shapes inside, near the edge, across it and outside, in a
// disc and in the holed rectangle (both fill rules).
TEST(LeavesRegion, ShapesFarFromTheBoundaryAnsweredAsByTheExactTests) {
    const double exact = -1e-300;
    std::vector<detail::RegionData> regions;
    regions.push_back(make_region(Geom::PathVector(Geom::Path(Geom::Circle(50, 50, 40))), false));
    regions.push_back(holed_region(true));
    regions.push_back(holed_region(false));
    Lcg rng{29};
    int inside = 0, leaving = 0;
    for (const detail::RegionData& r : regions) {
        for (int i = 0; i < 400; ++i) {
            const Point c{rng.in(-5, 105), rng.in(-5, 105)};
            const double size = rng.in(0.5, 12);
            auto near = [&] { return Point{c.x + rng.in(-size, size), c.y + rng.in(-size, size)}; };
            const CircleProxy circle = circle_proxy(c.x, c.y, size / 2);
            const Point a = near(), b = near();
            const LineSegmentProxy segment = segment_proxy(a, b);
            const BezierProxy bezier = bezier_proxy(a, near(), near(), b);
            const PolygonProxy polygon = polygon_proxy({a, near(), b});
            for (const Proxy* p :
                 std::initializer_list<const Proxy*>{&circle, &segment, &bezier, &polygon}) {
                const bool answer = leaves_region(*p, r, 0.0);
                EXPECT_EQ(answer, leaves_region(*p, r, exact)) << i;
                (answer ? leaving : inside) += 1;
            }
        }
    }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(leaving, 1000);
}

TEST(DistanceTo, MatchesSamplingOnRandomShapes) {
    Lcg rng{2024};
    for (int i = 0; i < 25; ++i) {
        Point q{rng.in(-20, 20), rng.in(-20, 20)};
        Point c{rng.in(-10, 10), rng.in(-10, 10)};
        double r = rng.in(1, 8);

        auto circle = circle_proxy(c.x, c.y, r);
        double dc = distance(q, c) <= r ? 0 : sampled_distance(q, [&](double t) {
            return c.offset(Direction(2 * M_PI * t), r);
        });
        expect_distance(circle, q, dc, 2 * M_PI * r / samples);

        double start = rng.in(-7, 7), end = rng.in(-7, 7);
        double sweep = end >= start ? std::min(end - start, 2 * M_PI)
                                    : std::fmod(end - start, 2 * M_PI) + 2 * M_PI;
        auto arc = arc_proxy(c.x, c.y, r, start, end);
        expect_distance(arc, q,
                        sampled_distance(
                            q, [&](double t) { return c.offset(Direction(start + sweep * t), r); }),
                        2 * M_PI * r / samples);

        Point a{rng.in(-10, 10), rng.in(-10, 10)}, b{rng.in(-10, 10), rng.in(-10, 10)};
        auto seg = segment_proxy(a.x, a.y, b.x, b.y);
        expect_distance(seg, q, sampled_distance(q, [&](double t) { return lerp(a, b, t); }),
                        40.0 / samples);

        auto bez =
            bezier_proxy({rng.in(-10, 10), rng.in(-10, 10)}, {rng.in(-10, 10), rng.in(-10, 10)},
                         {rng.in(-10, 10), rng.in(-10, 10)}, {rng.in(-10, 10), rng.in(-10, 10)});
        expect_distance(bez, q, sampled_distance(q, [&](double t) { return bez.at(t); }),
                        100.0 / samples);

        std::vector<Point> pts;
        for (int k = 0; k < 6; ++k) {
            // A star-shaped (possibly concave) hexagon around c.
            pts.push_back(c.offset(Direction(k * M_PI / 3 + rng.in(0, 0.5)), rng.in(2, 9)));
        }
        auto poly = polygon_proxy(pts);
        double dp = inside_polygon(pts, q) ? 0 : sampled_distance(q, [&](double t) {
            double s = t * pts.size();
            std::size_t k = std::min(pts.size() - 1, static_cast<std::size_t>(s));
            return lerp(pts[k], pts[(k + 1) % pts.size()], s - k);
        });
        expect_distance(poly, q, dp, 120.0 / samples);

        auto pt = point_proxy(a.x, a.y);
        EXPECT_DOUBLE_EQ(distance_to(pt, q), distance(a, q));
    }
}

TEST(DistanceTo, BezierWithinLimitFromInsideItsControlHull) {
    // An arch whose top is at y = 7.5, its control hull the square 0..10: from inside the hull a
    // bound taken from the segments between control points alone could skip the curve.
    auto arch = bezier_proxy({0, 0}, {0, 10}, {10, 10}, {10, 0});
    EXPECT_NEAR(distance_to(arch, {5, 5}, 3), 2.5, 1e-9);
    // (5, 8) is 0.5 from the top and 2 or more from every segment between control points.
    EXPECT_LE(distance_to(arch, {5, 8}, 1), 0.5 + 1e-9);
    EXPECT_NEAR(distance_to(arch, {5, 5}, 2.5), 2.5, 1e-9);
    EXPECT_GT(distance_to(arch, {5, 5}, 2), 2.0);
    // Outside the hull: the bound is the nearest edge's distance (here 2), below the curve's.
    EXPECT_NEAR(distance_to(arch, {5, 12}, 4.6), 4.5, 1e-9);
    EXPECT_GT(distance_to(arch, {5, 12}, 1.9), 1.9);
    // Degenerate hulls: control points on a line, all in one point.
    EXPECT_NEAR(distance_to(bezier_proxy({0, 0}, {2, 0}, {8, 0}, {10, 0}), {5, 1}, 1.5), 1.0, 1e-9);
    EXPECT_NEAR(distance_to(bezier_proxy({1, 1}, {1, 1}, {1, 1}, {1, 1}), {1, 4}, 3.5), 3.0, 1e-9);
}

TEST(DistanceTo, ZeroInsideAreas) {
    EXPECT_EQ(distance_to(circle_proxy(0, 0, 5), {1, 1}), 0.0);
    EXPECT_EQ(distance_to(rect_proxy(0, 0, 10, 10), {5, 5}), 0.0);
    EXPECT_DOUBLE_EQ(distance_to(rect_proxy(0, 0, 10, 10), {13, 14}), 5.0);
    EXPECT_DOUBLE_EQ(distance_to(circle_proxy(0, 0, 5), {0, 8}), 3.0);
    EXPECT_NEAR(distance_to(segment_proxy(0, 0, 10, 0), {5, 3}), 3.0, 1e-12);
    EXPECT_NEAR(distance_to(arc_proxy(0, 0, 5, 3 * M_PI / 2, M_PI / 2), {-8, 0}), std::hypot(8, 5),
                1e-9);
}

}  // namespace
}  // namespace acanthus
