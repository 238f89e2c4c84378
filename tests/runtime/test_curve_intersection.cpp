// intersect_curves: a circular arc against a Bezier curve skips lib2geom's solver only when the
// curve surely misses the circle, so it finds exactly what lib2geom finds; BoundaryDistance's
// nearest curve is the nearest one, the lowest index among equals, in whatever order it looks.
#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "geometry/boundary_distance.hpp"
#include "geometry/curve_intersection.hpp"

namespace acanthus::detail {
namespace {

// A circular arc of radius r round c, from angle a0 to a1 (counter-clockwise, under a turn).
Geom::EllipticalArc arc(Geom::Point c, double r, double a0, double a1) {
    const Geom::Point from = c + r * Geom::Point(std::cos(a0), std::sin(a0));
    const Geom::Point to = c + r * Geom::Point(std::cos(a1), std::sin(a1));
    return Geom::EllipticalArc(from, Geom::Point(r, r), 0, a1 - a0 > M_PI, true, to);
}

std::unique_ptr<Geom::BezierCurve> bezier(std::mt19937& rng, int order, Geom::Point near,
                                          double spread) {
    std::uniform_real_distribution<double> u(-spread, spread);
    std::vector<Geom::Point> points;
    for (int i = 0; i <= order; ++i) points.push_back(near + Geom::Point(u(rng), u(rng)));
    return std::unique_ptr<Geom::BezierCurve>(Geom::BezierCurve::create(points));
}

void expect_same(const std::vector<Geom::CurveIntersection>& got,
                 const std::vector<Geom::CurveIntersection>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].first, want[i].first);
        EXPECT_EQ(got[i].second, want[i].second);
    }
}

TEST(CurveIntersection, ArcAndBezierFindWhatLib2geomFinds) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), offset(-30, 30);
    int crossing = 0, missing = 0;
    for (int k = 0; k < 600; ++k) {
        const Geom::Point c(offset(rng), offset(rng));
        const double r = 2 + 8 * std::uniform_real_distribution<double>(0, 1)(rng);
        const double a0 = angle(rng);
        const Geom::EllipticalArc a = arc(c, r, a0, a0 + 0.3 + 2.5 * (k % 3));
        // Curves inside the circle, across it, round it and anywhere.
        const double spread = std::array<double, 4>{0.4 * r, r, 3 * r, 10}[k % 4];
        const double t = angle(rng);
        const Geom::Point near =
            std::array<Geom::Point, 4>{c, c + r * Geom::Point(std::cos(t), std::sin(t)), c,
                                       Geom::Point(offset(rng), offset(rng))}[k % 4];
        const auto b = bezier(rng, 1 + k % 3, near, spread);
        const auto want = a.intersect(*b);
        (want.empty() ? missing : crossing) += 1;
        expect_same(intersect_curves(a, *b), want);
        expect_same(intersect_curves(*b, a), b->intersect(a));
    }
    EXPECT_GT(crossing, 50);
    EXPECT_GT(missing, 50);
}

TEST(CurveIntersection, CurveTouchingTheCircleIsLeftToLib2geom) {
    // A line tangent to the circle and one a hair inside it: not "surely missing".
    const Geom::EllipticalArc a = arc(Geom::Point(0, 0), 5, 0, M_PI);
    const Geom::LineSegment tangent(Geom::Point(-10, 5), Geom::Point(10, 5));
    const Geom::LineSegment inside(Geom::Point(-10, 5 - 1e-9), Geom::Point(10, 5 - 1e-9));
    expect_same(intersect_curves(a, tangent), a.intersect(tangent));
    expect_same(intersect_curves(a, inside), a.intersect(inside));
    EXPECT_FALSE(intersect_curves(a, inside).empty());
}

// Few curves are scanned, many go through the spatial index: both skip curves by bounds and
// control hulls, and must still find what solving every curve finds.
void expect_nearest_of_all(int count) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-50, 50);
    std::vector<std::unique_ptr<Geom::BezierCurve>> owned;
    std::vector<const Geom::Curve*> curves;
    for (int i = 0; i < count; ++i) {
        owned.push_back(bezier(rng, 1 + i % 3, Geom::Point(u(rng), u(rng)), 15));
        curves.push_back(owned.back().get());
    }
    // The same curve twice: equal distances, the first wins.
    curves.push_back(curves[3]);
    const BoundaryDistance target(curves);
    for (int k = 0; k < 300; ++k) {
        const Geom::Point p(u(rng), u(rng));
        double best = INFINITY;
        std::size_t index = 0;
        for (std::size_t i = 0; i < curves.size(); ++i) {
            const double d = Geom::distance(p, curves[i]->pointAt(curves[i]->nearestTime(p)));
            if (d < best) best = d, index = i;
        }
        const BoundaryDistance::Nearest n = target.nearest(p);
        EXPECT_EQ(n.distance, best);
        EXPECT_EQ(n.curve, index);
    }
}

TEST(BoundaryDistance, NearestIsTheNearestCurveLowestIndexFirst) {
    expect_nearest_of_all(12);
    expect_nearest_of_all(80);  // past the 64 curves where the R-tree takes over
}

TEST(BoundaryDistance, LowerBoundNeverAboveTheCurvesDistance) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-30, 30);
    for (int k = 0; k < 400; ++k) {
        const auto c = bezier(rng, 1 + k % 3, Geom::Point(0, 0), 20);
        const Geom::Point p(u(rng), u(rng));
        double sampled = INFINITY;
        for (int i = 0; i <= 2000; ++i)
            sampled = std::min(sampled, Geom::distance(p, c->pointAt(i / 2000.0)));
        EXPECT_LE(curve_distance_lower_bound(*c, p), sampled) << k;
    }
    // Inside the hull of an arch, away from every segment between its control points.
    const Geom::CubicBezier arch({0, 0}, {0, 10}, {10, 10}, {10, 0});
    EXPECT_EQ(curve_distance_lower_bound(arch, {5, 8}), 0.0);
    EXPECT_NEAR(curve_distance_lower_bound(arch, {5, 13}), 3.0, 1e-9);
}

}  // namespace
}  // namespace acanthus::detail
