// Support library values: Point/Vector/Direction arithmetic, Random determinism, %param parsing.
#include <gtest/gtest.h>

#include <acanthus/body.hpp>
#include <acanthus/param.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/random.hpp>

namespace {
using namespace acanthus;

TEST(Point, OffsetAlongDirectionFromVector) {
    Point a{1, 1};
    Point goal{4, 5};
    Point p = a.offset(goal - a, 10);
    EXPECT_NEAR(p.x, 1 + 6, 1e-12);
    EXPECT_NEAR(p.y, 1 + 8, 1e-12);
    EXPECT_DOUBLE_EQ(~(goal - a), 5.0);
}

TEST(Direction, TurnsByRadians) {
    Direction d = Vector{1, 0};
    Direction t = d + M_PI / 2;
    EXPECT_NEAR(t.unit().x, 0, 1e-12);
    EXPECT_NEAR(t.unit().y, 1, 1e-12);
    EXPECT_NEAR((t - M_PI).unit().y, -1, 1e-12);
}

TEST(Bezier, DirectionFormLeavesAndArrivesAlongTangents) {
    BezierProxy b;
    b.set(Point{0, 0}, Direction(0.0), 0.5, Point{10, 0}, Direction(M_PI / 2), 0.25);
    EXPECT_TRUE(b.is_set());
    EXPECT_NEAR(b.c[1].x, 5, 1e-12);
    EXPECT_NEAR(b.c[2].y, -2.5, 1e-12);  // arrives moving along +y
    EXPECT_NEAR(b.at(1).x, 10, 1e-12);
}

TEST(Body, MixedMinMax) {
    EXPECT_DOUBLE_EQ(body::min(3, 2.5), 2.5);
    EXPECT_DOUBLE_EQ(body::max(3, 2.5), 3.0);
}

TEST(Random, SameSeedSameSequenceAndKnownValues) {
    Random a(42), b(42), c(43);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next_u64(), b.next_u64());
    EXPECT_NE(Random(42).next_u64(), c.next_u64());
    Random r(7);
    double sum = 0, sum2 = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        double u = r.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        double g = r.normal(2.0, 3.0);
        sum += g;
        sum2 += g * g;
    }
    double mean = sum / n, var = sum2 / n - mean * mean;
    EXPECT_NEAR(mean, 2.0, 0.1);
    EXPECT_NEAR(var, 9.0, 0.5);
    for (int i = 0; i < 1000; ++i) {
        auto k = r.uniform_int(-3, 3);
        ASSERT_GE(k, -3);
        ASSERT_LE(k, 3);
    }
}

TEST(Param, ParsesByTypeAndRefusesBadValues) {
    std::string err;
    int i = 0;
    EXPECT_TRUE(parse_param("42", i, err));
    EXPECT_EQ(i, 42);
    EXPECT_FALSE(parse_param("4.2", i, err));
    EXPECT_FALSE(parse_param("", i, err));
    double d = 0;
    EXPECT_TRUE(parse_param("2.5", d, err));
    EXPECT_EQ(d, 2.5);
    EXPECT_FALSE(parse_param("abc", d, err));
    EXPECT_FALSE(parse_param("nan", d, err));
    EXPECT_NE(err.find("nan"), std::string::npos);
    bool b = false;
    EXPECT_TRUE(parse_param("yes", b, err));
    EXPECT_TRUE(b);
    EXPECT_FALSE(parse_param("maybe", b, err));
    std::string s;
    EXPECT_TRUE(parse_param("hello world", s, err));
    EXPECT_EQ(format_param(2.5), "2.5");
    EXPECT_EQ(format_param(0.1), "0.1");
    EXPECT_EQ(format_param(true), "true");
}
}  // namespace
