// stdlib/common's triangulations: Delaunay of point sets against a brute-force empty-circumcircle
// check, hull coverage and neighbour symmetry; polygon triangulation by area and count.
#include <gtest/gtest.h>

#include <acanthus/point.hpp>
#include <acanthus/random.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/triangulation.hpp"

namespace {

using acanthus::Point;
using acanthus::common::delaunay_triangulation;
using acanthus::common::DelaunayTriangle;

double orient(Point a, Point b, Point c) { return (b - a).cross(c - a); }

// > 0 when d lies strictly inside the circle through the counter-clockwise a, b, c; long double
// and a tolerance relative to the terms, so that cocircular points count as on the circle.
bool strictly_inside_circumcircle(Point a, Point b, Point c, Point d) {
    long double ax = a.x - d.x, ay = a.y - d.y, bx = b.x - d.x, by = b.y - d.y;
    long double cx = c.x - d.x, cy = c.y - d.y;
    long double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    long double det =
        ax * (by * c2 - b2 * cy) - ay * (bx * c2 - b2 * cx) + a2 * (bx * cy - by * cx);
    long double scale = (std::abs(ax) + std::abs(ay)) * (std::abs(bx) + std::abs(by)) *
                        (std::abs(cx) + std::abs(cy)) * (a2 + b2 + c2);
    return det > 1e-12L * scale;
}

// Area of the convex hull (Andrew's monotone chain).
double hull_area(std::vector<Point> p) {
    std::sort(p.begin(), p.end(),
              [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Point> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    double area = 0;
    for (std::size_t i = 0; i + 1 < k; ++i) area += (h[i] - h[0]).cross(h[i + 1] - h[0]);
    return area / 2;
}

// Every property the growth library relies on, checked by brute force.
void expect_delaunay(const std::vector<Point>& points, const std::vector<DelaunayTriangle>& tris) {
    ASSERT_FALSE(tris.empty());
    double area = 0;
    std::map<std::pair<int, int>, std::pair<int, int>> edges;  // directed edge -> (triangle, k)
    for (std::size_t t = 0; t < tris.size(); ++t) {
        const auto& v = tris[t].vertices;
        EXPECT_LT(v[0], v[1]);
        EXPECT_LT(v[0], v[2]);
        const Point a = points[v[0]], b = points[v[1]], c = points[v[2]];
        ASSERT_GT(orient(a, b, c), 0) << "triangle " << t << " is not counter-clockwise";
        area += orient(a, b, c) / 2;
        for (std::size_t q = 0; q < points.size(); ++q) {
            EXPECT_FALSE(strictly_inside_circumcircle(a, b, c, points[q]))
                << "point " << q << " inside the circumcircle of triangle " << t;
        }
        for (int k = 0; k < 3; ++k) edges[{v[(k + 1) % 3], v[(k + 2) % 3]}] = {int(t), k};
        if (t > 0) {
            EXPECT_LT(tris[t - 1].vertices, tris[t].vertices);
        }
    }
    EXPECT_NEAR(area, hull_area(points), 1e-9 * std::max(1.0, std::abs(area)));
    // neighbors[k] shares the edge opposite vertices[k], the other way round; -1 on the hull.
    for (std::size_t t = 0; t < tris.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const auto& v = tris[t].vertices;
            auto twin = edges.find({v[(k + 2) % 3], v[(k + 1) % 3]});
            int expected = twin == edges.end() ? -1 : twin->second.first;
            EXPECT_EQ(tris[t].neighbors[k], expected) << "triangle " << t << " edge " << k;
            if (expected >= 0) {
                EXPECT_EQ(tris[expected].neighbors[twin->second.second], int(t));
            }
        }
    }
}

TEST(Delaunay, RandomPointsHaveEmptyCircumcircles) {
    acanthus::Random rng(7);
    for (int n : {3, 4, 10, 60, 300}) {
        std::vector<Point> points;
        for (int i = 0; i < n; ++i) points.push_back({rng.uniform(-50, 50), rng.uniform(0, 20)});
        auto tris = delaunay_triangulation(points);
        SCOPED_TRACE(n);
        expect_delaunay(points, tris);
        std::set<int> used;
        for (const auto& t : tris) used.insert(t.vertices.begin(), t.vertices.end());
        EXPECT_EQ(static_cast<int>(used.size()), n) << "every point is a vertex";
    }
}

TEST(Delaunay, GridWithCocircularPointsAndCollinearHull) {
    std::vector<Point> points;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 7; ++i) points.push_back({i * 1.5, j * 1.5});
    auto tris = delaunay_triangulation(points);
    expect_delaunay(points, tris);
    EXPECT_EQ(tris.size(), std::size_t{2 * 6 * 5});  // two triangles per cell
    EXPECT_EQ(delaunay_triangulation(points).size(), tris.size());
}

TEST(Delaunay, RepeatedPointsUseTheirFirstIndex) {
    std::vector<Point> points{{0, 0}, {4, 0}, {0, 3}, {4, 0}, {1, 1}, {0, 0}};
    auto tris = delaunay_triangulation(points);
    std::set<int> used;
    for (const auto& t : tris) used.insert(t.vertices.begin(), t.vertices.end());
    EXPECT_EQ(used, (std::set<int>{0, 1, 2, 4}));
    std::vector<Point> distinct{points[0], points[1], points[2], points[4]};
    for (auto& t : tris)
        for (int& v : t.vertices) v = v == 4 ? 3 : v;
    expect_delaunay(distinct, tris);
}

TEST(Delaunay, DegenerateInputGivesNoTriangles) {
    EXPECT_TRUE(delaunay_triangulation({}).empty());
    EXPECT_TRUE(delaunay_triangulation({{1, 1}, {2, 2}}).empty());
    EXPECT_TRUE(delaunay_triangulation({{0, 0}, {1, 1}, {2, 2}, {3, 3}}).empty());
    EXPECT_TRUE(delaunay_triangulation({{5, 5}, {5, 5}, {5, 5}}).empty());
    EXPECT_THROW(delaunay_triangulation({{0, 0}, {1, 0}, {0, NAN}}), std::invalid_argument);
}

TEST(PolygonTriangulation, ConcavePolygonKeepsItsInside) {
    // An L with a notch: 8 vertices, so 6 triangles whose area is the polygon's.
    std::vector<Point> outline{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 3}, {4, 3}, {4, 5}, {0, 5}};
    auto tris = acanthus::common::triangulate_polygon(outline);
    ASSERT_EQ(tris.size(), outline.size() - 2);
    double area = 0;
    for (const auto& t : tris) area += std::abs(orient(t[0], t[1], t[2])) / 2;
    EXPECT_DOUBLE_EQ(area, 6 * 2 + 2 * 1 + 4 * 2 + 0.0);
    for (const auto& t : tris) {
        Point c{(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3};
        bool in_notch = c.x > 2 && c.y > 2 && c.y < 3;
        bool in_cut = c.x > 4 && c.y > 2;
        EXPECT_FALSE(in_notch || in_cut) << "triangle outside the outline at " << c.x << "," << c.y;
    }
}

}  // namespace
