// Built-in shapes, the default panel and the geometric queries (distance, rings, path data,
// largest inscribed circle) against known answers.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <cmath>

using acanthus::Circle;
using acanthus::Point;
using acanthus::Region;

namespace {

// Arcs become cubic Béziers within 6e-9 of the radius (lib2geom 1.2.2 mishandles arcs).
constexpr double kArcArea = 1e-3;

double ring_area(const std::vector<Point>& ring) {
    double a = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point& p = ring[i];
        const Point& q = ring[(i + 1) % ring.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a / 2;
}

}  // namespace

TEST(region_shapes, RectSpec) {
    Region r = Region::from_spec("rect:30,20");
    EXPECT_EQ(r.name(), "rect:30,20");
    EXPECT_DOUBLE_EQ(r.area(), 600);
    EXPECT_DOUBLE_EQ(r.bounds().x0, 0);
    EXPECT_DOUBLE_EQ(r.bounds().y0, 0);
    EXPECT_DOUBLE_EQ(r.bounds().x1, 30);
    EXPECT_DOUBLE_EQ(r.bounds().y1, 20);
    EXPECT_TRUE(r.contains({15, 10}));
    EXPECT_FALSE(r.contains({31, 10}));
    EXPECT_FALSE(r.evenodd());
}

TEST(region_shapes, CircleAndEllipseSpecs) {
    Region c = Region::from_spec("circle:5");
    EXPECT_NEAR(c.area(), M_PI * 25, kArcArea);
    EXPECT_NEAR(c.bounds().x0, 0, 1e-12);
    EXPECT_NEAR(c.bounds().y1, 10, 1e-12);
    EXPECT_TRUE(c.contains({5, 5}));
    EXPECT_FALSE(c.contains({0.5, 0.5}));
    Region e = Region::from_spec("ellipse:20, 10");
    EXPECT_NEAR(e.area(), M_PI * 200, kArcArea);
    EXPECT_NEAR(e.bounds().x1, 40, 1e-12);
    EXPECT_NEAR(e.bounds().y1, 20, 1e-12);
}

TEST(region_shapes, FromArgumentPicksSpec) {
    EXPECT_DOUBLE_EQ(Region::from_argument("rect:3,4").area(), 12);
    EXPECT_NEAR(Region::from_argument("circle:1").area(), M_PI, kArcArea);
}

TEST(region_shapes, DefaultPanelIsTheArch) {
    Region r = Region::default_panel();
    EXPECT_NEAR(r.bounds().x0, 0, 1e-9);
    EXPECT_NEAR(r.bounds().y0, 0, 1e-9);
    EXPECT_NEAR(r.bounds().x1, 120, 1e-9);
    EXPECT_NEAR(r.bounds().y1, 160, 1e-9);
    EXPECT_NEAR(r.area(), 12000 + 1800 * M_PI, kArcArea);
    EXPECT_TRUE(r.contains({60, 5}));
    EXPECT_FALSE(r.contains({5, 5}));  // outside the arch's shoulder
    EXPECT_TRUE(r.contains({5, 155}));
    Circle c = r.largest_inscribed_circle(0.01);
    EXPECT_NEAR(c.radius, 60, 0.011);
    EXPECT_NEAR(c.center.x, 60, 0.5);
    EXPECT_TRUE(r.contains(c.center));
}

TEST(region_shapes, DistanceToBoundary) {
    Region r = Region::from_spec("rect:100,60");
    EXPECT_NEAR(r.distance_to_boundary({50, 30}), 30, 1e-12);
    EXPECT_NEAR(r.distance_to_boundary({10, 30}), 10, 1e-12);
    EXPECT_NEAR(r.distance_to_boundary({110, 30}), 10, 1e-12);  // unsigned outside
    Region c = Region::from_spec("circle:10");
    EXPECT_NEAR(c.distance_to_boundary({10, 10}), 10, 1e-6);
    EXPECT_NEAR(c.distance_to_boundary({30, 10}), 10, 1e-6);
    EXPECT_NEAR(c.distance_to_boundary({13, 14}), 5, 1e-6);
}

TEST(region_shapes, RingsFollowTheCurveWithinTolerance) {
    Region c = Region::from_spec("circle:10");
    auto rings = c.rings(0.01);
    ASSERT_EQ(rings.size(), 1u);
    EXPECT_GT(rings[0].size(), 20u);
    for (const Point& p : rings[0]) EXPECT_NEAR(std::hypot(p.x - 10, p.y - 10), 10, 1e-6);
    EXPECT_NEAR(std::abs(ring_area(rings[0])), M_PI * 100, M_PI * 100 * 0.01);
    // A coarser tolerance gives fewer points.
    EXPECT_LT(c.rings(1.0)[0].size(), rings[0].size());
    Region r = Region::from_spec("rect:4,3");
    auto box = r.rings(0.1);
    ASSERT_EQ(box.size(), 1u);
    EXPECT_EQ(box[0].size(), 4u);
    EXPECT_DOUBLE_EQ(ring_area(box[0]), 12);  // outer rings keep positive orientation
}

TEST(region_shapes, RingsKeepHoles) {
    Region r = Region::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path fill-rule=\"evenodd\" "
        "d=\"M0,0 H10 V10 H0 Z M2,2 H8 V8 H2 Z\"/></svg>",
        "frame.svg");
    auto rings = r.rings(0.1);
    ASSERT_EQ(rings.size(), 2u);
    EXPECT_DOUBLE_EQ(ring_area(rings[0]) + ring_area(rings[1]), 64);
}

TEST(region_shapes, PathDataRoundTrips) {
    Region d = Region::default_panel();
    std::string data = d.path_data();
    EXPECT_NE(data.find('M'), std::string::npos);
    EXPECT_NE(data.find('C'), std::string::npos);  // the arch, as cubic Béziers
    Region again = Region::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"" + data + "\"/></svg>", "again.svg");
    EXPECT_NEAR(again.area(), d.area(), 1e-6);
}

TEST(region_shapes, CopyAndMove) {
    Region a = Region::from_spec("rect:2,3");
    Region b = a;
    EXPECT_DOUBLE_EQ(b.area(), 6);
    Region c = std::move(a);
    EXPECT_DOUBLE_EQ(c.area(), 6);
    b = Region::from_spec("circle:1");
    EXPECT_NEAR(b.area(), M_PI, kArcArea);
    c = b;
    EXPECT_NEAR(c.area(), M_PI, kArcArea);
}

TEST(region_inscribed_circle, Rectangle) {
    Region r = Region::from_spec("rect:100,60");
    Circle c = r.largest_inscribed_circle(0.01);
    EXPECT_NEAR(c.radius, 30, 0.011);
    EXPECT_LE(c.radius, 30 + 1e-9);
    EXPECT_NEAR(c.center.y, 30, 0.5);
    EXPECT_GE(c.center.x, 30 - 0.01);
    EXPECT_LE(c.center.x, 70 + 0.01);
}

TEST(region_inscribed_circle, Circle) {
    Region r = Region::from_spec("circle:25");
    Circle c = r.largest_inscribed_circle(0.001);
    EXPECT_NEAR(c.radius, 25, 0.0011);
    EXPECT_NEAR(c.center.x, 25, 0.05);
    EXPECT_NEAR(c.center.y, 25, 0.05);
}

TEST(region_inscribed_circle, LShape) {
    // Arms 40 wide: the best circle touches both outer walls and the inner corner (40, 40):
    // sqrt(2) (40 - r) = r.
    Region r = Region::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"M0,0 H100 V40 H40 V100 H0 Z\"/></svg>",
        "L.svg");
    double expected = 40 * M_SQRT2 / (1 + M_SQRT2);
    Circle c = r.largest_inscribed_circle(0.01);
    EXPECT_NEAR(c.radius, expected, 0.011);
    EXPECT_NEAR(c.center.x, expected, 0.2);
    EXPECT_NEAR(c.center.y, expected, 0.2);
}

TEST(region_inscribed_circle, AvoidsHoles) {
    // A 100 x 100 square with a 20 x 20 hole in the middle: the best circle sits in a corner
    // quadrant, touching two sides and the hole's corner.
    Region r = Region::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path fill-rule=\"evenodd\" "
        "d=\"M0,0 H100 V100 H0 Z M40,40 H60 V60 H40 Z\"/></svg>",
        "holed.svg");
    Circle c = r.largest_inscribed_circle(0.01);
    double expected = 40 * M_SQRT2 / (1 + M_SQRT2);
    EXPECT_NEAR(c.radius, expected, 0.011);
    EXPECT_FALSE(c.center.x > 40 && c.center.x < 60 && c.center.y > 40 && c.center.y < 60);
}

TEST(region_inscribed_circle, Deterministic) {
    Region r = Region::default_panel();
    Circle a = r.largest_inscribed_circle(0.05);
    Circle b = r.largest_inscribed_circle(0.05);
    EXPECT_EQ(a.center, b.center);
    EXPECT_EQ(a.radius, b.radius);
}
