// Rings of arches close together (ring_check.hpp): turned as half-brick rings where that clears
// them, refused naming both openings where even those meet; a lintel's bearing clear of rings.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
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

namespace {

// texture() refuses `f` with an InputError whose message holds `words`.
void expect_refused(const Facade& f, const std::string& words) {
    try {
        texture(f, brick_tree(), centimetres(), 1);
        ADD_FAILURE() << "laid, not refused: " << words;
    } catch (const acanthus::InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(words), std::string::npos) << m;
    }
}

}  // namespace

TEST(CellsArchRings, RingsThatMeetEvenHalvedAreRefused) {
    const Facade f = two_arches(15);
    const detail::RingPlan p = detail::plan_rings(f, centimetres(), 22.5);
    EXPECT_EQ(p.clash_a, "window arch a");
    EXPECT_EQ(p.clash_b, "window arch b");
    expect_refused(f,
                   "two.svg: the openings \"window arch a\" and \"window arch b\" are too close");
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

// Two round heads 3 cm apart: not even half-brick rings fit between them, and the message names
// both openings (it named only the first).
TEST(CellsArchRings, ArchesAFewCentimetresApartAreBothNamed) {
    expect_refused(two_arches(3),
                   "two.svg: the openings \"window arch a\" and \"window arch b\" are too close");
}

// A round head 20.5 cm from a wide flat head: the most a lintel there may take (its bearing
// rounded out and a quarter more) would meet a brick-deep ring, the lintel laid does not (its
// end 3.6 cm or more clear of the ring), so the ring is a brick deep (it was a half brick).
TEST(CellsArchRings, ALintelIsJudgedByWhatIsLaid) {
    const Facade f = Facade::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 320 260\">"
        "<rect id=\"w\" class=\"wall\" width=\"320\" height=\"260\"/>"
        "<path id=\"a\" class=\"window arch\" d=\"M 50 200 V 100 A 30 30 0 0 1 110 100 V 200 Z\"/>"
        "<rect id=\"wide\" class=\"window\" x=\"153\" y=\"100\" width=\"137\" height=\"100\"/>"
        "</svg>",
        "lintel.svg");
    Options o = centimetres();
    const Texture t = texture(f, brick_tree(), o, 1);
    EXPECT_NEAR(ring_reach(f, t.cells, "a"), 22.5 - o.mortar / 2, 0.01);
    for (const auto& [name, tree] : mason_trees()) {
        SCOPED_TRACE(name);
        const MasonReport r = mason_check(f, texture(f, tree, o, 1).cells, kCm);
        EXPECT_EQ(r.voussoirs_clipped, 0);
        EXPECT_EQ(r.openings_without_head, 0);
    }
}

namespace {

Facade relieving_example(bool labelled = true) {
    std::ifstream in(std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/relieving.svg");
    std::stringstream text;
    text << in.rdbuf();
    std::string svg = text.str();
    if (!labelled)
        for (std::size_t at; (at = svg.find(" relieving\"")) != std::string::npos;)
            svg.erase(at, std::string(" relieving").size());
    return Facade::from_svg_string(svg, "relieving.svg");
}

}  // namespace

// Relieving arches over the lintels of the coach-house's cart door and loft window, in every
// bond and tree: whole voussoirs, an odd count with a key at the crown, skewbacks at both
// springings; no straight joint or head joint off, and no shaved brick, odd or narrow piece
// that the same front without the label does not have (the tympanum's bricks are the bond's,
// cut to the intrados).
TEST(CellsArchRings, RelievingArchesInEveryBondAndTree) {
    const Facade f = relieving_example(), plain = relieving_example(false);
    for (Bond bond : {Bond::running, Bond::english, Bond::flemish, Bond::header, Bond::ashlar}) {
        Options o = centimetres();
        o.bond = bond;
        std::map<std::string, Node> trees = mason_trees();
        if (bond == Bond::ashlar) trees = {{"ashlar", ashlar_tree()}};
        for (const auto& [name, tree] : trees) {
            SCOPED_TRACE(name + " " + std::to_string(static_cast<int>(bond)));
            MasonSpec spec = kCm;
            spec.stone = bond == Bond::ashlar;
            const MasonReport r = mason_check(f, texture(f, tree, o, 1).cells, spec);
            const MasonReport p = mason_check(plain, texture(plain, tree, o, 1).cells, spec);
            EXPECT_EQ(r.relieving_arches, 2) << r;
            EXPECT_EQ(p.relieving_arches, 0);
            EXPECT_GE(r.relieving_voussoirs, 2 * 9);
            EXPECT_EQ(r.relieving_clipped, 0) << r;
            EXPECT_EQ(r.relieving_even, 0);
            EXPECT_EQ(r.relieving_open, 0);
            EXPECT_EQ(r.relieving_skewbacks, 0);
            EXPECT_EQ(r.openings_without_head, 0);
            EXPECT_EQ(r.slivers, 0);
            if (bond == Bond::ashlar) continue;
            EXPECT_EQ(r.straight_joints, 0) << r;
            EXPECT_EQ(r.joints_off, 0) << r;
            EXPECT_EQ(r.narrow_pieces, 0) << r;
            EXPECT_EQ(r.courses_off_gauge, 0);
            EXPECT_EQ(r.king_closers_misplaced, 0);
            EXPECT_LE(r.shaved_bricks, p.shaved_bricks);
            EXPECT_LE(r.odd_pieces, p.odd_pieces);
            EXPECT_LE(r.unforced_odd, p.unforced_odd);
        }
    }
}

// The checker finds a relieving arch laid wrong: its key taken out (an even count, the crown
// open), or a voussoir cut short (notched).
TEST(CellsArchRings, FindsABrokenRelievingArch) {
    const Facade f = relieving_example();
    const Texture t = texture(f, brick_tree(), centimetres(), 1);
    std::vector<Cell> keyless = t.cells, notched = t.cells;
    // The loft's key: the voussoir over the middle of its opening.
    auto key_of = [&](std::vector<Cell>& cells) {
        for (std::size_t i = 0; i < cells.size(); ++i) {
            const Cell& c = cells[i];
            if (c.generator != "relieving_arch" || c.piece != "voussoir" ||
                c.label.find("loft") == std::string::npos)
                continue;
            const Rect b = mason_detail::extent(c.polygon);
            if (b.x0 < 375 && b.x1 > 375) return i;
        }
        return cells.size();
    };
    const std::size_t k = key_of(keyless);
    ASSERT_LT(k, keyless.size());
    keyless.erase(keyless.begin() + static_cast<std::ptrdiff_t>(k));
    const MasonReport a = mason_check(f, keyless, kCm);
    EXPECT_EQ(a.relieving_even, 1);
    EXPECT_EQ(a.relieving_open, 1);
    // Its outer half cut off, as a brick laid first would notch it.
    Cell& v = notched[key_of(notched)];
    Point o{0, 0};
    for (Point p : v.polygon) o = {o.x + p.x / v.polygon.size(), o.y + p.y / v.polygon.size()};
    for (Point& p : v.polygon) p.y = std::max(p.y, o.y);
    EXPECT_EQ(mason_check(f, notched, kCm).relieving_clipped, 1);
    EXPECT_EQ(mason_check(f, t.cells, kCm).relieving_clipped, 0);
}

// A label that cannot be built is refused naming the opening: on a round window, over an
// opening too narrow for the arch to rise a course, and where the arch would reach past the
// wall's top.
TEST(CellsArchRings, RelievingLabelsRefused) {
    auto refused = [](const std::string& shapes, const std::string& words) {
        expect_refused(Facade::from_svg_string(
                           "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 320 260\">"
                           "<rect id=\"w\" class=\"wall\" width=\"320\" height=\"260\"/>" +
                               shapes + "</svg>",
                           "bad.svg"),
                       words);
    };
    refused("<circle id=\"eye\" class=\"window relieving\" cx=\"160\" cy=\"100\" r=\"30\"/>",
            "bad.svg: the opening \"window relieving eye\" is labelled relieving but has no "
            "straight head");
    refused(
        "<rect id=\"slot\" class=\"window relieving\" x=\"100\" y=\"100\" width=\"40\" "
        "height=\"60\"/>",
        "bad.svg: the opening \"window relieving slot\" is labelled relieving but is 40 wide");
    refused(
        "<rect id=\"high\" class=\"window relieving\" x=\"60\" y=\"40\" width=\"200\" "
        "height=\"100\"/>",
        "bad.svg: the opening \"window relieving high\": its relieving arch would reach past "
        "the wall");
}

// A king closer at a jamb with a segmental arch's skewback beside it, stepped with the bond: the
// bond goes on through the skewback, and the checker reads the skewback's plumb step beside the
// closer (inside the skewback's extent) as it reads a head's end. It read a misplaced closer.
TEST(CellsArchRings, AKingCloserBesideASteppedSkewbackIsInPlace) {
    const Facade f = Facade::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 200 100\">"
        "<rect id=\"w\" class=\"wall\" width=\"200\" height=\"100\"/>"
        "<rect id=\"o\" class=\"window\" x=\"100\" y=\"20\" width=\"60\" height=\"60\"/></svg>",
        "king.svg");
    // The closer: three quarters less a joint, its end half a joint off the jamb at x = 100, in
    // the course 40..47.5 (drawn 40.5..47).
    const double m = 0.5, king = 3 * 22.5 / 4 - 1;
    Cell closer;
    closer.generator = "bricks";
    closer.piece = "king closer";
    closer.polygon = {{100 - m - king, 40.5}, {100 - m, 40.5}, {100 - m, 47}, {100 - m - king, 47}};
    // The skewback beyond it: its plumb side a joint from the closer's far end in this course,
    // stepped half a brick in under the closer in the course below (so its extent ends there).
    const double x = 100 - king - 2 * m;
    Cell skewback;
    skewback.generator = "arch_stones";
    skewback.polygon = {{x - m, 33},           {x - m, 47},    {x - m + 11.25, 47},
                        {x - m + 11.25, 54.5}, {x - 20, 54.5}, {x - 20, 33}};
    const MasonReport r = mason_check(f, {closer, skewback}, kCm);
    EXPECT_EQ(r.king_closers, 1);
    EXPECT_EQ(r.king_closers_misplaced, 0);
}
