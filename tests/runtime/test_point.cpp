// Point, Vector, Direction, Circle and Rect: the value types rule bodies use.
#include <gtest/gtest.h>

#include <acanthus/point.hpp>
#include <cmath>

namespace acanthus {
namespace {

TEST(Vector, Arithmetic) {
    Vector v{3, 4};
    EXPECT_DOUBLE_EQ(v.length(), 5);
    EXPECT_DOUBLE_EQ(~v, 5);
    EXPECT_EQ(v + Vector(1, 1), Vector(4, 5));
    EXPECT_EQ(v - Vector(1, 1), Vector(2, 3));
    EXPECT_EQ(-v, Vector(-3, -4));
    EXPECT_EQ(v * 2, Vector(6, 8));
    EXPECT_EQ(2 * v, Vector(6, 8));
    EXPECT_EQ(v / 2, Vector(1.5, 2));
    EXPECT_DOUBLE_EQ(v.dot({1, 0}), 3);
    EXPECT_DOUBLE_EQ(Vector(1, 0).cross({0, 1}), 1);
    EXPECT_EQ(Vector(1, 0).perp(), Vector(0, 1));
    EXPECT_DOUBLE_EQ(v.normalized().length(), 1);
    EXPECT_EQ(Vector().normalized(), Vector());
    Vector r = Vector(1, 0).rotated(M_PI / 2);
    EXPECT_NEAR(r.x, 0, 1e-15);
    EXPECT_NEAR(r.y, 1, 1e-15);
    Vector w{1, 1};
    w += {1, 2};
    w *= 2;
    EXPECT_EQ(w, Vector(4, 6));
}

TEST(Direction, ConversionsAndTurns) {
    Direction d(Vector{0, 2});
    EXPECT_DOUBLE_EQ(d.angle, M_PI / 2);
    Direction e = d + M_PI / 2;
    EXPECT_DOUBLE_EQ(e.angle, M_PI);
    EXPECT_NEAR(e.unit().x, -1, 1e-15);
    double radians = Direction(0.25);
    EXPECT_DOUBLE_EQ(radians, 0.25);
    EXPECT_DOUBLE_EQ(Direction(0.5).opposite().angle, 0.5 + M_PI);
    Direction f(1.0);
    f -= 0.5;
    EXPECT_DOUBLE_EQ(f.angle, 0.5);
}

TEST(Point, OffsetDistanceAndOperators) {
    Point p{1, 2};
    Point q = p.offset(Direction(0.0), 3);
    EXPECT_EQ(q, Point(4, 2));
    Point r = p.offset(Direction(M_PI / 2), 2);
    EXPECT_NEAR(r.x, 1, 1e-15);
    EXPECT_NEAR(r.y, 4, 1e-15);
    EXPECT_DOUBLE_EQ(distance(p, {4, 6}), 5);
    EXPECT_DOUBLE_EQ(~(Point(4, 6) - p), 5);
    EXPECT_EQ(p + Vector(1, 1), Point(2, 3));
    EXPECT_EQ(midpoint({0, 0}, {2, 4}), Point(1, 2));
    EXPECT_EQ(lerp({0, 0}, {2, 4}, 0.25), Point(0.5, 1));
    EXPECT_TRUE(p.finite());
    EXPECT_FALSE(Point(NAN, 0).finite());
    EXPECT_FALSE(Point(0, INFINITY).finite());
}

TEST(Rect, Measures) {
    Rect r{1, 2, 5, 10};
    EXPECT_DOUBLE_EQ(r.width(), 4);
    EXPECT_DOUBLE_EQ(r.height(), 8);
    EXPECT_EQ(r.center(), Point(3, 6));
    EXPECT_TRUE(r.contains({1, 2}));
    EXPECT_TRUE(r.contains({5, 10}));
    EXPECT_FALSE(r.contains({5.0001, 3}));
    Circle c{{1, 1}, 2};
    EXPECT_DOUBLE_EQ(c.radius, 2);
}

}  // namespace
}  // namespace acanthus
