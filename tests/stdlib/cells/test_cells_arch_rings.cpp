// Rings of arches close together (ring_check.hpp): turned as half-brick rings where that clears
// them, refused naming both openings where even those meet; a lintel's bearing clear of rings.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <cmath>
#include <string>

#include "cells_oracle.hpp"
#include "mason_check.hpp"
#include "ring_check.hpp"

using namespace cells_test;
namespace detail = acanthus::cells::detail;

namespace {

const MasonSpec kCm{21.5, 6.5, 1, 0.3};

Options centimetres() {
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1, o.joint_tolerance = 0.3;
    return o;
}

// Two round-headed windows 60 wide, their jambs `gap` apart, springing at y = 100.
Facade two_arches(double gap) {
    const std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 320 260\">"
        "<rect id=\"w\" class=\"wall\" width=\"320\" height=\"260\"/>"
        "<path id=\"a\" class=\"window arch\" d=\"M 50 200 V 100 A 30 30 0 0 1 110 100 V 200 Z\"/>"
        "<path id=\"b\" class=\"window arch\" d=\"M " +
        std::to_string(110 + gap) + " 200 V 100 A 30 30 0 0 1 " + std::to_string(170 + gap) +
        " 100 V 200 Z\"/></svg>";
    return Facade::from_svg_string(svg, "two.svg");
}

const Edge& arc_labelled(const Facade& f, const std::string& id) {
    for (const Edge& e : f.edges())
        if (e.arc && e.labels.back() == id) return e;
    throw std::runtime_error("no arc " + id);
}

double planned(const Facade& f, const detail::RingPlan& p, const std::string& id) {
    return p.depth.at(detail::arch_key(f, arc_labelled(f, id)));
}

// The deepest an arch cell of `id` reaches from the arc's circle.
double ring_reach(const Facade& f, const std::vector<Cell>& cells, const std::string& id) {
    const Segment& s = arc_labelled(f, id).segments.front();
    double reach = 0;
    for (const Cell& c : cells) {
        if (c.feature != FeatureKind::edge || c.generator.rfind("arch_", 0) != 0) continue;
        if (f.edges()[static_cast<std::size_t>(c.feature_index)].labels.back() != id) continue;
        for (Point p : c.polygon)
            reach = std::max(reach, std::hypot(p.x - s.center.x, p.y - s.center.y) - s.radius);
    }
    return reach;
}

}  // namespace

TEST(CellsArchRings, PolygonsMeetOnlyWhereTheyShareArea) {
    const std::vector<Point> a{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    EXPECT_TRUE(detail::polygons_meet(a, {{5, 5}, {15, 5}, {15, 15}, {5, 15}}));
    EXPECT_FALSE(detail::polygons_meet(a, {{10, 0}, {20, 0}, {20, 10}, {10, 10}}));  // touching
    EXPECT_FALSE(detail::polygons_meet(a, {{11, 0}, {20, 0}, {20, 10}, {11, 10}}));
    EXPECT_TRUE(detail::polygons_meet(a, {{2, 2}, {3, 2}, {3, 3}}));  // one within the other
    EXPECT_TRUE(detail::polygons_meet({{2, 2}, {3, 2}, {3, 3}}, a));
    // A concave C round a square in its mouth: apart, though their boxes meet.
    const std::vector<Point> c{{0, 0},  {30, 0},  {30, 5},  {5, 5},
                               {5, 25}, {30, 25}, {30, 30}, {0, 30}};
    EXPECT_FALSE(detail::polygons_meet(c, {{10, 10}, {20, 10}, {20, 20}, {10, 20}}));
    EXPECT_TRUE(detail::polygons_meet(c, {{3, 10}, {20, 10}, {20, 20}, {3, 20}}));
}

// Both rings of two_arches() planned `depth` deep, neither refused.
void expect_both(const Facade& f, double depth) {
    const detail::RingPlan p = detail::plan_rings(f, centimetres(), 22.5);
    EXPECT_DOUBLE_EQ(planned(f, p, "a"), depth);
    EXPECT_DOUBLE_EQ(planned(f, p, "b"), depth);
    EXPECT_TRUE(p.clash_a.empty());
}

TEST(CellsArchRings, RingsApartKeepTheirDepth) { expect_both(two_arches(60), 22.5); }

// 30 cm apart: brick-deep rings would overlap by 15 cm at the springing; half-brick ones leave
// 7.5 cm of walling between them.
TEST(CellsArchRings, RingsThatWouldMeetAreHalfBrickRings) {
    const Facade f = two_arches(30);
    expect_both(f, 11.25);
    Options o = centimetres();
    for (const auto& [name, tree] : mason_trees()) {
        const Texture t = texture(f, tree, o, 1);
        SCOPED_TRACE(name);
        // The cells lie inside the joints.
        EXPECT_NEAR(ring_reach(f, t.cells, "a"), 11.25 - o.mortar / 2, 0.01);
        EXPECT_NEAR(ring_reach(f, t.cells, "b"), 11.25 - o.mortar / 2, 0.01);
        EXPECT_EQ(mason_check(f, t.cells, kCm).voussoirs_clipped, 0);
    }
}

TEST(CellsArchRings, RingsThatMeetEvenHalvedAreRefused) {
    const Facade f = two_arches(15);
    const detail::RingPlan p = detail::plan_rings(f, centimetres(), 22.5);
    EXPECT_EQ(p.clash_a, "window arch a");
    EXPECT_EQ(p.clash_b, "window arch b");
    try {
        texture(f, brick_tree(), centimetres(), 1);
        FAIL() << "two rings 15 cm apart laid";
    } catch (const acanthus::InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("two.svg: the openings \"window arch a\" and \"window arch b\" are too "
                         "close"),
                  std::string::npos)
            << m;
    }
}

// A segmental window springing 20 cm from a small flat-headed one (the corner shop's): the
// small one's lintel bears where a brick-deep ring would pass, so the ring is half a brick and
// no lintel or brick cuts a voussoir.
TEST(CellsArchRings, ALintelsBearingIsClearOfTheRing) {
    const Facade f = Facade::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 300 250\">"
        "<rect id=\"w\" class=\"wall\" width=\"300\" height=\"250\"/>"
        "<rect id=\"small\" class=\"window\" x=\"9.7\" y=\"41.3\" width=\"31.4\" height=\"30.8\"/>"
        "<path id=\"seg\" class=\"window arch segmental\" "
        "d=\"M 61.9 178.3 V 62.7 A 95 95 0 0 1 181.2 62.7 V 178.3 Z\"/></svg>",
        "lintel.svg");
    const detail::RingPlan p = detail::plan_rings(f, centimetres(), 22.5);
    EXPECT_DOUBLE_EQ(planned(f, p, "seg"), 11.25);
    Options o = centimetres();
    for (const auto& [name, tree] : mason_trees()) {
        const Texture t = texture(f, tree, o, 1);
        SCOPED_TRACE(name);
        EXPECT_EQ(mason_check(f, t.cells, kCm).voussoirs_clipped, 0);
    }
}
