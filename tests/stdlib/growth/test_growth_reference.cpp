// Reference analysis (section 4): skewed Delaunay triangles removed, edges only on kept
// triangles, the author's flips, counter-clockwise rings and boundary elements.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "common/triangulation.hpp"
#include "connectivity.hpp"
#include "growth_fixtures.hpp"
#include "growth_lattices.hpp"
#include "reference.hpp"

using namespace acanthus;
using namespace acanthus::growth;
using acanthus::growth::detail::analyse_connectivity;
using acanthus::growth::detail::largest_angle;

namespace {

bool has_edge(const std::vector<std::pair<int, int>>& edges, int a, int b) {
    return std::find(edges.begin(), edges.end(), std::pair{std::min(a, b), std::max(a, b)}) !=
           edges.end();
}

TEST(GrowthReference, SkewedHullTriangleIsRemovedWithItsEdges) {
    // B sits just below A-C: Delaunay makes the sliver A-B-C (174 degrees at B) and A-C-E.
    std::vector<Point> points{{0, 0}, {1, -0.05}, {2, 0}, {1, 30}};
    auto c = analyse_connectivity(points, {}, "test");
    EXPECT_EQ(c.removed_triangles, 1);
    ASSERT_EQ(c.triangles.size(), 1u);
    EXPECT_TRUE(has_edge(c.edges, 0, 2));
    EXPECT_FALSE(has_edge(c.edges, 0, 1));
    EXPECT_FALSE(has_edge(c.edges, 1, 2));
    EXPECT_TRUE(c.rings[1].empty());
    EXPECT_TRUE(c.boundary[1]);
}

TEST(GrowthReference, KeepsExactlyTheDelaunayTrianglesUnder120Degrees) {
    // Random points with no four nearly on one circle (those cells are split canonically; see
    // RoundedLatticesHaveTheExactConnectivity): the first such set from the seed.
    auto angle_at = [](Point o, Point a, Point b) {
        return std::atan2(std::abs((a - o).cross(b - o)), (a - o).dot(b - o));
    };
    Random random(7);
    std::vector<Point> points;
    std::vector<common::DelaunayTriangle> all;
    for (bool cocircular = true; cocircular;) {
        points.clear();
        for (int i = 0; i < 60; ++i)
            points.push_back({random.uniform(0, 10), random.uniform(0, 3)});
        all = common::delaunay_triangulation(points);
        cocircular = false;
        for (const auto& t : all)
            for (int k = 0; k < 3; ++k) {
                if (t.neighbors[k] < 0) continue;
                int a = t.vertices[(k + 1) % 3], b = t.vertices[(k + 2) % 3], far = -1;
                for (int w : all[t.neighbors[k]].vertices)
                    if (w != a && w != b) far = w;
                double sum = angle_at(points[t.vertices[k]], points[a], points[b]) +
                             angle_at(points[far], points[a], points[b]);
                cocircular = cocircular || std::abs(sum - M_PI) < growth::detail::kAngleTolerance;
            }
    }
    std::set<std::array<int, 3>> expected;
    int skewed = 0;
    for (const auto& t : all) {
        auto v = t.vertices;
        if (largest_angle(points[v[0]], points[v[1]], points[v[2]]) >
            2 * M_PI / 3 - growth::detail::kAngleTolerance) {
            ++skewed;
            continue;
        }
        std::sort(v.begin(), v.end());
        expected.insert(v);
    }
    ASSERT_GT(skewed, 0) << "the random set should have slivers on its hull";
    auto c = analyse_connectivity(points, {}, "test");
    EXPECT_EQ(c.removed_triangles, skewed);
    std::set<std::array<int, 3>> kept;
    for (auto t : c.triangles) {
        std::sort(t.begin(), t.end());
        kept.insert(t);
    }
    EXPECT_EQ(kept, expected);
    // Every kept edge borders a kept triangle.
    for (auto [i, j] : c.edges) {
        bool on = false;
        for (const auto& t : kept)
            on = on || (std::count(t.begin(), t.end(), i) && std::count(t.begin(), t.end(), j));
        EXPECT_TRUE(on) << i << "-" << j;
    }
}

// Issue 27: a lattice whose file was rounded to 3 decimals of its spacing has the connectivity of
// the exact one (skewed zigzag sides and cocircular cells decided within an angle tolerance), at
// any spacing and origin, turned or not.
TEST(GrowthReference, RoundedLatticesHaveTheExactConnectivity) {
    using growth_lattices::Kind;
    struct Placement {
        double spacing;
        Point origin;
        double turn;  // radians
    };
    for (Placement at : {Placement{10, {0, 0}, 0}, Placement{0.37, {123.4567, -89.01}, 0},
                         Placement{2500, {-1e5, 3e4}, 0}, Placement{10, {5, 5}, 0.35}})
        for (Kind kind : growth_lattices::all_kinds()) {
            auto exact = growth_lattices::lattice(kind, 9, at.spacing);
            for (auto& e : exact)
                e.position = at.origin + (e.position - Point{0, 0}).rotated(at.turn);
            auto rounded = exact;
            for (auto& e : rounded)
                e.position = {growth_lattices::rounded(e.position.x, at.spacing, 3),
                              growth_lattices::rounded(e.position.y, at.spacing, 3)};
            Reference a = Reference::from_elements(exact), b = Reference::from_elements(rounded);
            const std::string what = std::string(growth_lattices::name(kind)) + " at spacing " +
                                     std::to_string(at.spacing) + " turned " +
                                     std::to_string(at.turn);
            EXPECT_EQ(a.edges(), b.edges()) << what;
            int differ = 0;
            for (std::size_t i = 0; i < a.size(); ++i)
                differ += a.ring(i) != b.ring(i) || a.boundary(i) != b.boundary(i);
            EXPECT_EQ(differ, 0) << what << ": elements whose ring differs";
            EXPECT_EQ(a.data().candidates, b.data().candidates) << what;
            int interior = 0;
            for (std::size_t i = 0; i < a.size(); ++i) interior += !a.boundary(i);
            EXPECT_GT(interior, 0) << what;  // a honeycomb's hexagons are kept whole
        }
}

TEST(GrowthReference, FlipReplacesTheDiagonal) {
    std::vector<Point> points{{0, 0}, {1, 0}, {1.1, 1}, {0, 1}};
    auto before = analyse_connectivity(points, {}, "test");
    bool d02 = has_edge(before.edges, 0, 2);
    ASSERT_NE(d02, has_edge(before.edges, 1, 3));
    std::pair<int, int> diagonal = d02 ? std::pair{0, 2} : std::pair{1, 3};
    auto after = analyse_connectivity(points, {diagonal}, "test");
    EXPECT_FALSE(has_edge(after.edges, diagonal.first, diagonal.second));
    EXPECT_TRUE(d02 ? has_edge(after.edges, 1, 3) : has_edge(after.edges, 0, 2));
    EXPECT_EQ(after.edges.size(), before.edges.size());
    for (const auto& t : after.triangles)  // still counter-clockwise
        EXPECT_GT((points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]), 0);
}

TEST(GrowthReference, BadFlipsThrowNamingTheFlip) {
    std::vector<Point> points{{0, 0}, {1, 0}, {1.1, 1}, {0, 1}};
    auto c = analyse_connectivity(points, {}, "ref.json");
    std::pair<int, int> not_edge = has_edge(c.edges, 0, 2) ? std::pair{1, 3} : std::pair{0, 2};
    try {
        analyse_connectivity(points, {not_edge}, "ref.json");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("ref.json: flip 0"), std::string::npos) << e.what();
    }
    EXPECT_THROW(analyse_connectivity(points, {{0, 1}}, "ref.json"), InputError);  // hull edge
    EXPECT_THROW(analyse_connectivity(points, {{0, 9}}, "ref.json"), InputError);
}

TEST(GrowthReference, RingsAreCounterClockwiseAndInteriorIsNotBoundary) {
    auto points = growth_fixtures::hex_patch(2, 10.0);
    ASSERT_EQ(points.size(), 19u);
    std::vector<ReferenceElement> elements;
    for (Point p : points) elements.push_back({"a", "", p, 0, 0});
    Reference ref = Reference::from_elements(elements, {}, "hex");
    int interior = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        bool centre_or_first = distance(points[i], {0, 0}) < 10.5;
        EXPECT_EQ(ref.boundary(i), !centre_or_first) << i;
        if (ref.boundary(i)) continue;
        ++interior;
        const auto& ring = ref.ring(i);
        ASSERT_EQ(ring.size(), 6u);
        for (std::size_t k = 0; k < ring.size(); ++k) {
            Vector u = points[ring[k]] - points[i];
            Vector v = points[ring[(k + 1) % 6]] - points[i];
            EXPECT_GT(u.cross(v), 0) << "ring of " << i << " turns clockwise at " << k;
            EXPECT_NEAR(u.length(), 10.0, 1e-9);
        }
        EXPECT_TRUE(std::all_of(ref.data().rings[i].begin(), ref.data().rings[i].end(),
                                [](const auto& s) { return s.closed; }));
    }
    EXPECT_EQ(interior, 7);
    EXPECT_NEAR(ref.mean_edge_length(), 10.0, 1e-9);
    EXPECT_NEAR(ref.radius(0), 3.5, 1e-9);  // default size: 0.35 x mean edge
    // Candidates are exactly the interior elements.
    EXPECT_EQ(ref.data().candidates.size(), 7u);
}

TEST(GrowthReference, SymbolsAreInternedAndLabelsKeptAsGiven) {
    auto elements = growth_fixtures::triangular_lattice(3, 4, 5.0, {"b", "a"});
    elements[1].label = "x";
    elements[2].label = "x";
    Reference ref = Reference::from_elements(elements);
    const auto& d = ref.data();
    EXPECT_EQ(d.symbols, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(d.symbol[0], 1);
    EXPECT_EQ(d.symbol[1], 0);
    EXPECT_EQ(ref.element(0).label, "");
    EXPECT_EQ(ref.element(1).label, "x");
    EXPECT_EQ(ref.element(2).label, "x");
}

}  // namespace
