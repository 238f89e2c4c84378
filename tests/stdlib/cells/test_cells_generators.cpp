// Arch stones with radial joints, RGB blocks, author-written generators in a tree (ashlar:
// test_cells_ashlar.cpp).
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <set>

#include "cells_oracle.hpp"
#include "mason_check.hpp"

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

TEST(CellsGenerators, PointedArchGetsAKeystone) {
    // An equilateral pointed arch: arcs of radius 1200 struck from the opposite springings.
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 6000, 4000), {"wall"}, "gable"));
    s.push_back(
        shape("M 2400 3000 V 2000 A 1200 1200 0 0 1 3000 960.77 "
              "A 1200 1200 0 0 1 3600 2000 V 3000 Z",
              {"window", "arch"}, "lancet"));
    Facade f = Facade::from_shapes(std::move(s), "gable.svg");
    Texture t = texture(f, brick_tree(), Options{}, 2);
    const Point apex{3000, 960.77};
    const Point centers[2] = {{3600, 2000}, {2400, 2000}};
    int keystones = 0;
    for (const Cell& c : t.cells) {
        if (c.generator != "arch_stones" || c.feature != FeatureKind::corner) continue;
        ++keystones;
        // A key with real width at the intrados (not a wedge from the apex): points a little way
        // down each arc from the apex, just into the wall, are in it.
        for (int side = 0; side < 2; ++side) {
            const Point o = centers[side];
            const double r = 1200, a0 = std::atan2(apex.y - o.y, apex.x - o.x);
            const double a = a0 + (side == 0 ? -1 : 1) * 40.0 / r;
            const Point on{o.x + r * std::cos(a), o.y + r * std::sin(a)};
            const acanthus::Vector out = (on - o).normalized();
            EXPECT_TRUE(mason_detail::contains(c.polygon, on + out * 15)) << "side " << side;
        }
        EXPECT_TRUE(mason_detail::contains(c.polygon, apex + acanthus::Vector{0, -20}));
    }
    EXPECT_EQ(keystones, 1);
    Report r = check_texture(f, t, 10);
    EXPECT_LT(r.overlap, 1.0);
    EXPECT_LT(r.over_openings, 1.0);
    EXPECT_GE(r.coverage, 0.99);
}

TEST(CellsGenerators, AshlarSillStonesUnderWindows) {
    Facade f = row_house();
    Options o;
    o.bond = Bond::ashlar;
    o.ashlar_unit = 150;
    Texture t = texture(f, tree_for(o), o, 5);
    // w1 and w2: sills at y 2600 from x 600 to 1500 and 4500 to 5400.
    for (double x0 : {600.0, 4500.0}) {
        double covered = 0;
        int stones = 0;
        for (const Cell& c : t.cells) {
            if (c.generator != "window_bottom") continue;
            double a = 1e300, b = -1e300, top = 1e300;
            for (Point p : c.polygon)
                a = std::min(a, p.x), b = std::max(b, p.x), top = std::min(top, p.y);
            if (std::abs(top - 2605) > 1e-6) continue;  // the row under the sill, half a joint down
            covered += std::max(0.0, std::min(b + 5, x0 + 900) - std::max(a - 5, x0));
            ++stones;
            EXPECT_LE(b - a, 4 * 150 * 1.5);  // no longer than the ashlar maximum
        }
        EXPECT_GE(covered, 0.99 * 900) << "sill at x " << x0;
        EXPECT_GE(stones, 2);
    }
    Report r = check_texture(f, t, 10);
    EXPECT_LT(r.overlap, 1.0);
    EXPECT_GE(r.coverage, 0.99);
}
