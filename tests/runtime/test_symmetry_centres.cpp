// Rotation centres with mirrors (docs/symmetry.md, "Rules see smaller circles"): the circles
// inside an empty circle C there that stay clear of their own images, which let a rule place
// an element beside the centre when one on it would clash with its images; and the patterns
// that grew nothing under a group with translations.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "symmetry/symmetry_group.hpp"
#include "symmetry/translation_groups.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

constexpr double kTol = 1e-9;

// Every circle lies inside C and clears its own images (its radius at most its clearance).
void expect_clear_inside(const SymmetryGroup& g, const Circle& c, const std::vector<Circle>& got) {
    for (const Circle& k : got) {
        EXPECT_LE(distance(k.center, c.center) + k.radius, c.radius + 1e-9);
        EXPECT_LE(k.radius, g.clearance(k.center, kTol) + 1e-9);
        EXPECT_GT(k.radius, 0);
    }
}

// True when some transformation other than the identity fixes p (p on a mirror).
bool on_mirror(const SymmetryGroup& g, Point p) {
    for (std::size_t k = 1; k < g.size(); ++k)
        if (distance(g.transforms()[k].apply(p), p) <= 1e-6) return true;
    return false;
}

}  // namespace

// d4 about the centre of C: on a mirror the best circle has radius R / (1 + sqrt 2) (its image in
// the next mirror, 45 degrees away, is sqrt 2 times as far); off the mirrors R s / (1 + s),
// s = sin 22.5 degrees (the circle between two mirrors touching C). Sampled: within 3 %.
TEST(ClearCircles, BesideTheCentreOfADihedralRosette) {
    const Point o{50, 50};
    const SymmetryGroup d4(Symmetry{Symmetry::Kind::dihedral, 4, std::nullopt}, o);
    const Circle c{o, 10};
    const std::vector<Circle> got = d4.clear_circles_in(c, {50, 0}, kTol);
    ASSERT_EQ(got.size(), 3u);
    expect_clear_inside(d4, c, got);
    // First the one touching C straight up (towards `toward`), on the vertical mirror.
    EXPECT_NEAR(got[0].center.x, o.x, 1e-9);
    EXPECT_LT(got[0].center.y, o.y);
    EXPECT_NEAR(distance(got[0].center, o) + got[0].radius, 10, 1e-9);
    EXPECT_GT(got[0].radius, 0.9 * 10 / (1 + std::sqrt(2.0)));
    EXPECT_TRUE(on_mirror(d4, got[1].center));
    EXPECT_FALSE(on_mirror(d4, got[2].center));
    EXPECT_NEAR(got[1].radius, 10 / (1 + std::sqrt(2.0)), 0.03 * 10 / (1 + std::sqrt(2.0)));
    const double s = std::sin(M_PI / 8);
    EXPECT_NEAR(got[2].radius, 10 * s / (1 + s), 0.03 * 10 * s / (1 + s));
    // The one nearest `toward` (straight up) of the equivalent ones: above the centre.
    EXPECT_LT(got[1].center.y, o.y);
    EXPECT_LT(got[2].center.y, o.y);
    EXPECT_LT(std::abs(got[2].center.x - o.x), got[2].radius + 1e-9);
    // Towards the lower right instead: the circles follow.
    const std::vector<Circle> other = d4.clear_circles_in(c, {100, 100}, kTol);
    ASSERT_EQ(other.size(), 3u);
    EXPECT_GT(other[0].center.x, o.x);
    EXPECT_GT(other[0].center.y, o.y);
    EXPECT_GT(other[2].center.x, o.x);
    EXPECT_GT(other[2].center.y, o.y);
}

// A cyclic rosette has no mirror: only the circle off the centre, clear of its N - 1 images.
TEST(ClearCircles, CyclicRosetteHasNoMirrorCircle) {
    const SymmetryGroup c3(Symmetry{Symmetry::Kind::cyclic, 3, std::nullopt}, {0, 0});
    const Circle c{{0, 0}, 12};
    const std::vector<Circle> got = c3.clear_circles_in(c, {0, -20}, kTol);
    ASSERT_EQ(got.size(), 2u);  // touching C towards (0, -20), and the best one
    expect_clear_inside(c3, c, got);
    // Best: centre at d with d sqrt 3 / 2 = 12 - d, r = 12 - d; touching C the same here.
    const double d = 12 / (1 + std::sqrt(3.0) / 2);
    EXPECT_NEAR(got[0].radius, 12 - d, 0.03 * (12 - d));
    EXPECT_NEAR(got[1].radius, 12 - d, 0.03 * (12 - d));
    EXPECT_LT(got[0].center.y, 0);
}

// The corners and edge middles of a p4m tile (4-fold and 2-fold centres with mirrors) and the
// corner of a p6m tile (6-fold): circles beside them, inside C, clear of every image.
TEST(ClearCircles, AtTheCentresOnAWallpaperTilesEdges) {
    for (const Wallpaper& w : {Wallpaper{"p4m", 150, 150, 90}, Wallpaper{"p6m", 150, 150, 60}}) {
        const TranslationSetup s = wallpaper_setup(w);
        ASSERT_TRUE(s.box);
        const SymmetryGroup g(s.group, *s.box);
        for (Point centre : {Point{0, 0}, Point{75, 0}, Point{150, 0}}) {
            const Circle c{centre, 8};
            const std::vector<Circle> got = g.clear_circles_in(c, {centre.x, 40}, kTol);
            ASSERT_EQ(got.size(), 3u) << w.group << " at " << centre.x;
            expect_clear_inside(g, c, got);
            EXPECT_TRUE(on_mirror(g, got[1].center));
            EXPECT_FALSE(on_mirror(g, got[2].center));
            EXPECT_GT(got[2].radius, 0.15 * c.radius);  // a 30 degree wedge at the 6-fold centre
        }
    }
}

// The classes of rotation centre growth restarts on (docs/symmetry.md, "Restarts on the
// centres"): one point of each class, in the fundamental domain, no two carried onto each other;
// told apart by the rotations fixing them (p4m: two 4-fold classes and a 2-fold one; p6m: 6, 3
// and 2; p2: four 2-fold ones; p1: none).
TEST(CentreClasses, OneOfEachClassInTheDomain) {
    struct Case {
        Wallpaper tile;
        std::vector<int> orders;  // rotations fixing each class's point (the identity counted)
    };
    for (const Case& k :
         {Case{{"p4m", 150, 150, 90}, {2, 4, 4}}, Case{{"p6m", 150, 150, 60}, {2, 3, 6}},
          Case{{"p2", 150, 100, 90}, {2, 2, 2, 2}}, Case{{"p1", 150, 100, 90}, {}}}) {
        const TranslationSetup s = wallpaper_setup(k.tile);
        ASSERT_TRUE(s.box);
        const SymmetryGroup g(s.group, *s.box);
        const std::vector<Point> got = g.centre_classes(1e-6);
        std::vector<int> orders;
        for (Point p : got) {
            EXPECT_TRUE(g.in_domain(p, 1e-6)) << k.tile.group;
            int n = 0;
            for (const Isometry& t : g.transforms())
                if (!t.reverses() && distance(t.apply(p), p) <= 1e-6) ++n;
            orders.push_back(n);
            for (Point q : got) {
                if (distance(q, p) <= 1e-6) continue;  // p itself
                for (const Isometry& t : g.transforms())
                    EXPECT_GT(distance(t.apply(q), p), 1e-6) << k.tile.group;
            }
        }
        std::sort(orders.begin(), orders.end());
        EXPECT_EQ(orders, k.orders) << k.tile.group;
    }
}

// A rosette has one centre, its own.
TEST(CentreClasses, RosetteHasItsCentre) {
    const SymmetryGroup g(Symmetry::parse("d6"), {10, 20});
    const std::vector<Point> got = g.centre_classes(1e-6);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_LE(distance(got[0], {10, 20}), 1e-12);
}

// The fundamental domain's edges on a mirror, where growth also restarts (the largest hole on
// each): every point of each is fixed by a reflection, each is one of the domain's edges; p4m's
// and p6m's triangles are bounded by mirrors alone (the mirror edges make the whole perimeter);
// pm's domain has mirrors on two sides; p4, pg, p2 and a rosette have none.
TEST(MirrorEdges, TheDomainsEdgesOnMirrors) {
    struct Case {
        Wallpaper tile;
        double share;  // of the domain's perimeter on mirrors
    };
    for (const Case& k : {Case{{"p4m", 150, 150, 90}, 1}, Case{{"p6m", 150, 150, 60}, 1},
                          Case{{"p4", 150, 150, 90}, 0}, Case{{"pg", 150, 100, 90}, 0},
                          Case{{"p2", 150, 100, 90}, 0}}) {
        const TranslationSetup s = wallpaper_setup(k.tile);
        ASSERT_TRUE(s.box);
        const SymmetryGroup g(s.group, *s.box);
        const auto got = g.mirror_edges(1e-6);
        const auto all = g.domain_edges(0);
        double on = 0, perimeter = 0;
        for (const auto& [a, b] : got) on += distance(a, b);
        for (const auto& [a, b] : all) perimeter += distance(a, b);
        EXPECT_NEAR(on, k.share * perimeter, 1e-6 * perimeter) << k.tile.group;
        for (const auto& [a, b] : got) {
            for (double t : {0.0, 0.3, 0.5, 1.0})
                EXPECT_TRUE(on_mirror(g, a + (b - a) * t)) << k.tile.group;
            EXPECT_NE(std::find(all.begin(), all.end(), std::pair<Point, Point>{a, b}), all.end());
        }
    }
    EXPECT_TRUE(SymmetryGroup(Symmetry::parse("d6"), {10, 20}).mirror_edges(1e-6).empty());
}

// The part of a hole in the fundamental domain (what a fill is offered on a restart): inside the
// hole and the domain, its area the hole's over the transformations fixing the hole's centre (a
// rotation centre of each class, and a rosette's).
TEST(DomainPart, TheHolesShareInTheDomain) {
    const SymmetryGroup d6(Symmetry::parse("d6"), {10, 20});
    const SymmetryGroup c5(Symmetry::parse("c5"), {10, 20});
    const SymmetryGroup c1(Symmetry::parse("c1"), {10, 20});
    const TranslationSetup p4m = wallpaper_setup(Wallpaper{"p4m", 150, 150, 90});
    const TranslationSetup p6m = wallpaper_setup(Wallpaper{"p6m", 150, 150, 60});
    const TranslationSetup p4 = wallpaper_setup(Wallpaper{"p4", 150, 150, 90});
    ASSERT_TRUE(p4m.box && p6m.box && p4.box);
    const SymmetryGroup g4m(p4m.group, *p4m.box), g6m(p6m.group, *p6m.box), g4(p4.group, *p4.box);
    int holes = 0;
    for (const SymmetryGroup* g : {&d6, &c5, &c1, &g4m, &g6m, &g4})
        for (const Point centre : g->centre_classes(1e-6)) {
            const Circle hole{centre, 12};
            int fixing = 0;
            for (const Isometry& t : g->transforms())
                if (distance(t.apply(centre), centre) <= 1e-6) ++fixing;
            const std::vector<Point> part = g->domain_part(hole, 1e-9, 1e-3);
            ASSERT_GE(part.size(), 3u) << g->name();
            double area = 0;
            for (std::size_t i = 0; i < part.size(); ++i) {
                const Point a = part[i], b = part[(i + 1) % part.size()];
                area += a.x * b.y - a.y * b.x;
                EXPECT_TRUE(g->in_domain(a, 1e-6)) << g->name();
                EXPECT_LE(distance(a, hole.center), hole.radius + 1e-9) << g->name();
            }
            const double disc = M_PI * hole.radius * hole.radius;
            EXPECT_NEAR(std::abs(area) / 2, disc / fixing, 2e-3 * disc)
                << g->name() << " at " << centre.x << "," << centre.y;
            ++holes;
        }
    EXPECT_EQ(holes, 12);  // the rosettes one each; p4m, p6m and p4 three classes each
    // A disc that misses the domain has no part.
    EXPECT_TRUE(d6.domain_part({{10, 60}, 5}, 1e-9, 1e-3).empty());
}
