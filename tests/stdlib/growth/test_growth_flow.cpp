// Flow mode (section 5.3): the RBF field reproduces the stroke directions where it was sampled,
// and grown motifs (and their rings) turn with it; circular strokes are followed within 15 degrees.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "flow_field.hpp"
#include "growth_fixtures.hpp"

using namespace acanthus;
using namespace acanthus::growth;
using acanthus::growth::Options;
using acanthus::growth::detail::FlowField;

namespace {

// Absolute difference of two directions, in [0, pi].
double direction_error(double a, double b) {
    double d = std::fmod(std::abs(a - b), 2 * M_PI);
    return d > M_PI ? 2 * M_PI - d : d;
}

std::vector<Point> circle_stroke(Point c, double r, int n = 64) {
    std::vector<Point> s;
    for (int k = 0; k <= n; ++k)
        s.push_back(c + Vector{std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n)} * r);
    return s;
}

TEST(GrowthFlow, FieldReproducesTheStrokesAtItsSamples) {
    FlowField field({circle_stroke({50, 50}, 20), {{0, 0}, {100, 10}}}, 3.0, "test");
    ASSERT_GT(field.samples().size(), 50u);
    for (std::size_t i = 0; i < field.samples().size(); ++i) {
        double want = std::atan2(field.directions()[i].y, field.directions()[i].x);
        EXPECT_LT(direction_error(field.angle(field.samples()[i]), want), 1e-5) << i;
    }
}

TEST(GrowthFlow, OneStraightStrokeGivesItsDirectionEverywhere) {
    FlowField field({{{0, 0}, {10, 10}}}, 1.0, "test");
    for (Point p : {Point{-50, 20}, Point{100, -40}, Point{5, 5}})
        EXPECT_NEAR(field.angle(p), M_PI / 4, 1e-6);
}

// Thousands of short strokes (a hostile guides file,
// tests/fuzz/growth_guides/many-flow-strokes.svg) once gave a sample each, and the dense solve took
// minutes: the samples stay within the budget, spread over all the strokes, and the field still
// follows them.
TEST(GrowthFlow, ThousandsOfStrokesStayWithinTheSampleBudget) {
    std::vector<std::vector<Point>> strokes;
    for (int i = 0; i < 3000; ++i) {
        Point p{i % 60 * 4.0, i / 60 * 3.0};
        strokes.push_back({p, p + Vector{1, 0.5}});
    }
    FlowField field(strokes, 1.0, "test", 600);
    EXPECT_LE(field.samples().size(), 600u);
    EXPECT_GE(field.samples().size(), 500u);
    double top = 0;
    for (Point p : field.samples()) top = std::max(top, p.y);
    EXPECT_GT(top, 140);  // the last strokes are sampled too, not only the first 600
    for (Point p : {Point{10, 10}, Point{120, 75}, Point{230, 140}})
        EXPECT_NEAR(field.angle(p), std::atan2(0.5, 1.0), 1e-3);
}

TEST(GrowthFlow, BadStrokes) {
    EXPECT_THROW(FlowField({}, 1.0, "test"), InputError);
    EXPECT_THROW(FlowField({{{1, 1}, {1, 1}}}, 1.0, "test"), InputError);
    EXPECT_THROW(FlowField({{{1, 1}, {NAN, 1}}}, 1.0, "test"), InputError);
    Reference ref = Reference::from_elements(growth_fixtures::triangular_lattice(5, 5, 8));
    Options o;
    o.mode = Mode::flow;  // no strokes
    EXPECT_THROW(synthesize(ref, Region::from_spec("rect:50,50"), o, {}, 1), InputError);
}

TEST(GrowthFlow, StraightFieldTurnsTheWholeLattice) {
    Reference ref = Reference::from_elements(growth_fixtures::triangular_lattice(7, 7, 8));
    Options o;
    o.mode = Mode::flow;
    const double turn = 0.5;  // radians; the lattice's 60-degree symmetry does not hide it
    o.flow_strokes = {{{0, 0}, {std::cos(turn) * 10, std::sin(turn) * 10}}};
    Region region = Region::from_spec("rect:120,100");
    SynthesisResult r = synthesize(ref, region, o, {}, 4);
    ASSERT_GT(r.motifs.size(), 100u);
    int checked = 0;
    for (const Motif& m : r.motifs) EXPECT_NEAR(m.angle, turn, 1e-9);
    // Lattice edges point along turn + k * 60 degrees.
    for (auto [i, j] : r.edges) {
        Vector d = r.motifs[j].position - r.motifs[i].position;
        double a = std::atan2(d.y, d.x) - turn;
        double off = std::abs(std::remainder(a, M_PI / 3));
        EXPECT_LT(off, 0.05) << "edge " << i << "-" << j;
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

TEST(GrowthFlow, CircularStrokesAreFollowed) {
    Reference ref = Reference::from_elements(growth_fixtures::triangular_lattice(7, 7, 6));
    Region region = Region::from_spec("circle:90");
    const Point c{90, 90};
    Options o;
    o.mode = Mode::flow;
    o.flow_strokes = {circle_stroke(c, 35), circle_stroke(c, 70)};
    SynthesisResult r = synthesize(ref, region, o, {{90 + 35, 90}}, 9);
    ASSERT_GT(r.motifs.size(), 200u);
    double total = 0;
    int near = 0;
    for (const Motif& m : r.motifs) {
        double radius = distance(m.position, c);
        if (std::min(std::abs(radius - 35), std::abs(radius - 70)) > 6) continue;
        Vector d = m.position - c;
        double tangent = std::atan2(d.y, d.x) + M_PI / 2;  // counter-clockwise strokes
        total += direction_error(m.angle, tangent);
        ++near;
    }
    ASSERT_GT(near, 50);
    EXPECT_LT(total / near, 15 * M_PI / 180) << "mean error near the strokes";
}

}  // namespace
