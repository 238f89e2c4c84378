// The tools of section 3 (issue 10): growth never crosses a boundary stroke, stays in the spray
// brush, and varies colour by the seed.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>

#include "growth_fixtures.hpp"

using namespace acanthus;
using namespace acanthus::growth;

namespace {

Reference lattice() {
    return Reference::from_elements(growth_fixtures::triangular_lattice(7, 7, 10, {"a", "b"}));
}

double distance_to_polyline(Point p, const std::vector<Point>& line) {
    double best = INFINITY;
    for (std::size_t i = 1; i < line.size(); ++i) {
        Vector ab = line[i] - line[i - 1];
        double t = std::clamp((p - line[i - 1]).dot(ab) / ab.dot(ab), 0.0, 1.0);
        best = std::min(best, distance(p, line[i - 1] + ab * t));
    }
    return best;
}

TEST(GrowthTools, BoundaryStrokeIsNeverCrossed) {
    Region panel = Region::from_spec("rect:200,140");
    Options o;
    // A bent wall from top to bottom; growth starts left of it.
    o.boundary_strokes = {{{110, -5}, {90, 70}, {115, 145}}};
    SynthesisResult r = synthesize(lattice(), panel, o, {{40, 70}}, 3);
    ASSERT_GT(r.motifs.size(), 40u);
    for (const Motif& m : r.motifs) {
        // Left of the wall at the motif's height, and clear of it by its radius.
        double t = m.position.y < 70 ? (m.position.y + 5) / 75 : (m.position.y - 70) / 75;
        double wall_x = m.position.y < 70 ? 110 - 20 * t : 90 + 25 * t;
        EXPECT_LT(m.position.x, wall_x) << m.position.x << "," << m.position.y;
        EXPECT_GE(distance_to_polyline(m.position, o.boundary_strokes[0]), m.radius - 1e-7);
    }
    // Without the wall the same growth fills both sides.
    Options free;
    SynthesisResult all = synthesize(lattice(), panel, free, {{40, 70}}, 3);
    EXPECT_GT(all.motifs.size(), r.motifs.size() * 3 / 2);
}

TEST(GrowthTools, SprayKeepsGrowthInTheBrush) {
    Region panel = Region::from_spec("rect:200,140");
    Options o;
    o.spray_strokes = {{{{20, 110}, {80, 60}, {120, 80}, {180, 30}}, 30}};
    SynthesisResult r = synthesize(lattice(), panel, o, {}, 5);
    ASSERT_GT(r.motifs.size(), 20u);
    for (const Motif& m : r.motifs)
        EXPECT_LE(distance_to_polyline(m.position, o.spray_strokes[0].points), 15 + 1e-9);
    // It reaches along the whole stroke, not only around its start.
    auto far_end = std::count_if(r.motifs.begin(), r.motifs.end(),
                                 [](const Motif& m) { return m.position.x > 150; });
    EXPECT_GT(far_end, 2);
    o.spray_strokes[0].width = 0;
    EXPECT_THROW(synthesize(lattice(), panel, o, {}, 5), InputError);
}

TEST(GrowthTools, ColourVariationIsSeeded) {
    Region panel = Region::from_spec("rect:120,90");
    Options o;
    SynthesisResult plain = synthesize(lattice(), panel, o, {}, 9);
    EXPECT_TRUE(std::all_of(plain.motifs.begin(), plain.motifs.end(),
                            [](const Motif& m) { return m.tint == 0; }));
    o.color_variation = 0.3;
    SynthesisResult a = synthesize(lattice(), panel, o, {}, 9);
    SynthesisResult b = synthesize(lattice(), panel, o, {}, 9);
    ASSERT_EQ(a.motifs.size(), b.motifs.size());
    double lo = 1, hi = -1;
    for (std::size_t i = 0; i < a.motifs.size(); ++i) {
        EXPECT_EQ(a.motifs[i].tint, b.motifs[i].tint);
        lo = std::min(lo, a.motifs[i].tint);
        hi = std::max(hi, a.motifs[i].tint);
    }
    EXPECT_GE(lo, -0.3);
    EXPECT_LE(hi, 0.3);
    EXPECT_GT(hi - lo, 0.3);  // it varies
    o.color_variation = 1.5;
    EXPECT_THROW(synthesize(lattice(), panel, o, {}, 9), InputError);
}

}  // namespace
