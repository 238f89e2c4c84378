// Arch stones with radial joints, RGB blocks, author-written generators in a tree (ashlar:
// test_cells_ashlar.cpp).
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <set>

#include "cells_oracle.hpp"

using namespace cells_test;

TEST(CellsGenerators, ArchStonesHaveRadialJoints) {
    Facade f = row_house();
    Texture t = texture(f, brick_tree(), Options{}, 3);
    const Point center{3000, 1700};
    int stones = 0, joints = 0;
    for (const Cell& c : t.cells) {
        if (c.generator != "arch_stones") continue;
        ++stones;
        const auto& p = c.polygon;
        for (std::size_t k = 0; k < p.size(); ++k) {
            Point a = p[k], b = p[(k + 1) % p.size()];
            double ra = distance(a, center), rb = distance(b, center);
            if (std::abs(ra - rb) < 0.5 * distance(a, b)) continue;  // along an arc
            acanthus::Vector d = (b - a).normalized(), r = (midpoint(a, b) - center).normalized();
            EXPECT_LT(std::acos(std::min(1.0, std::abs(d.dot(r)))) * 180 / M_PI, 2.0);
            ++joints;
        }
    }
    EXPECT_GE(stones, 5);
    EXPECT_GE(joints, 2 * stones - 2);
    Report r = check_texture(f, t, 10);
    EXPECT_LT(r.overlap, 1.0);
}

TEST(CellsGenerators, RgbBlocksByFeature) {
    Facade f = row_house();
    Texture t = texture(f, rgb_tree(), Options{}, 1);
    std::set<FeatureKind> kinds;
    for (const Cell& c : t.cells) kinds.insert(c.feature);
    EXPECT_EQ(kinds.size(), 3u);
    Report r = check_texture(f, t, 10);
    EXPECT_LT(r.overlap, 1.0);
    EXPECT_GE(r.coverage, 0.99);
}

TEST(CellsGenerators, AuthorsWriteGeneratorsAndTrees) {
    Facade f = row_house();
    // A generator of one's own: a square stone at each convex corner, then bricks.
    Generator stone = [](const FeatureRef& ref, Context& c) {
        Point p = c.facade().corners()[static_cast<std::size_t>(ref.index)].position;
        double s = 300;
        c.place({{p.x - s, p.y - s}, {p.x + s, p.y - s}, {p.x + s, p.y + s}, {p.x - s, p.y + s}});
    };
    Node tree = by_kind(by_convexity(generator("stone", stone), generator("bricks", bricks())),
                        generator("bricks", bricks()), generator("bricks", bricks()));
    Texture t = texture(f, tree, Options{}, 1);
    int stones = 0;
    for (const Cell& c : t.cells) stones += c.generator == "stone";
    EXPECT_EQ(stones, 6);
    Report r = check_texture(f, t, 10);
    EXPECT_LT(r.overlap, 1.0);
    EXPECT_GE(r.coverage, 0.99);
}

TEST(CellsGenerators, WindowBottomRefusesFaces) {
    Facade f = row_house();
    EXPECT_THROW(texture(f, generator("window_bottom", window_bottom()), Options{}, 1),
                 acanthus::InputError);
}
