// Fills that finish (issue 27): when the growth front stops, growth restarts in the largest empty
// circle that holds a motif at the reference's spacing, so a lobe behind a narrow neck fills too,
// while a lattice's own holes stay empty and the tools still hold.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>

#include "fidelity.hpp"
#include "growth_fixtures.hpp"
#include "growth_lattices.hpp"

using namespace acanthus;
using namespace acanthus::growth;

namespace {

// Two round lobes joined by a channel a motif barely passes (examples/panels/narrow-neck.svg).
Region dumbbell() {
    return Region::from_svg_string(
        R"(<svg xmlns="http://www.w3.org/2000/svg"><g fill="#eee">
        <circle cx="60" cy="60" r="55"/><rect x="100" y="54" width="80" height="12"/>
        <circle cx="220" cy="60" r="55"/></g></svg>)",
        "dumbbell");
}

// The largest circle, centred where the smallest motif fits, with no motif centre inside; sampled
// on a grid of a tenth of the spacing.
double largest_empty_circle(const SynthesisResult& r, const Region& region, double motif_radius,
                            double spacing) {
    Rect box = region.bounds();
    double best = 0;
    for (double y = box.y0; y <= box.y1; y += spacing / 10)
        for (double x = box.x0; x <= box.x1; x += spacing / 10) {
            Point p{x, y};
            if (!region.contains(p) || region.distance_to_boundary(p) < motif_radius) continue;
            double free = INFINITY;
            for (const Motif& m : r.motifs) free = std::min(free, distance(m.position, p));
            best = std::max(best, free);
        }
    return best;
}

struct Lobes {
    int left = 0, right = 0;
};

Lobes count(const SynthesisResult& r) {
    Lobes n;
    for (const Motif& m : r.motifs) (m.position.x < 140 ? n.left : n.right)++;
    return n;
}

TEST(GrowthHoles, BothLobesOfANarrowNeckFill) {
    Region panel = dumbbell();
    for (const auto& elements : {growth_fixtures::jittered_lattice(8, 8, 10, 1.5, {"a", "b"}),
                                 growth_fixtures::triangular_lattice(7, 7, 10, {"a", "b"})}) {
        Reference reference = Reference::from_elements(elements);
        const double nn = acanthus::growth::detail::reference_spacing(reference.data());
        double smallest = INFINITY;
        for (std::size_t i = 0; i < reference.size(); ++i)
            smallest = std::min(smallest, reference.radius(i));
        Options paper;
        paper.fill_holes = false;
        SynthesisResult before = synthesize(reference, panel, paper, {{40, 60}}, 7);
        SynthesisResult after = synthesize(reference, panel, Options{}, {{40, 60}}, 7);
        Lobes b = count(before), a = count(after);
        double hole = largest_empty_circle(after, panel, smallest, nn);
        std::printf(
            "narrow neck: %zu motifs (right lobe %d) without restarts, %zu (right %d) "
            "with %ld restarts; largest empty circle %.2f NN\n",
            before.motifs.size(), b.right, after.motifs.size(), a.right, after.stats.restarts,
            hole / nn);
        EXPECT_GT(a.left, 50);
        EXPECT_GT(a.right, 50);
        EXPECT_LE(hole, 1.5 * nn);
    }
}

// A honeycomb's own holes are exactly one spacing across the centre: a motif there would have six
// neighbours at the spacing instead of three. (Growth itself still leaves a few crowded motifs
// where fronts meet; restarts must add none.)
int crowded(const SynthesisResult& r, double spacing) {
    int n = 0;
    for (const Motif& m : r.motifs) {
        int close = 0;
        for (const Motif& o : r.motifs)
            close += &o != &m && distance(o.position, m.position) < 1.05 * spacing;
        n += close > 3;
    }
    return n;
}

TEST(GrowthHoles, NoMotifInAHoneycombsOwnHoles) {
    Region panel = Region::from_spec("rect:200,140");
    Reference reference =
        Reference::from_elements(growth_lattices::lattice(growth_lattices::Kind::honeycomb, 9, 10));
    for (std::uint64_t seed : {1u, 2u}) {
        Options paper;
        paper.fill_holes = false;
        SynthesisResult before = synthesize(reference, panel, paper, {{100, 70}}, seed);
        SynthesisResult after = synthesize(reference, panel, Options{}, {{100, 70}}, seed);
        std::printf(
            "honeycomb seed %d: %zu motifs, %d crowded without restarts; %zu, %d with %ld\n",
            static_cast<int>(seed), before.motifs.size(), crowded(before, 10), after.motifs.size(),
            crowded(after, 10), after.stats.restarts);
        EXPECT_GE(after.motifs.size(), before.motifs.size());
        EXPECT_LE(crowded(after, 10), crowded(before, 10));
    }
}

// Restarts stay on the start's side of a boundary stroke and inside spray brushes.
TEST(GrowthHoles, ToolsStillHold) {
    Region panel = dumbbell();
    Reference reference =
        Reference::from_elements(growth_fixtures::triangular_lattice(7, 7, 10, {"a", "b"}));
    Options wall;
    wall.boundary_strokes = {{{140, -5}, {140, 125}}};
    SynthesisResult r = synthesize(reference, panel, wall, {{40, 60}}, 3);
    EXPECT_GT(count(r).left, 50);
    EXPECT_EQ(count(r).right, 0);
}

}  // namespace

namespace {

// Inputs on which the growth fuzz target once spent minutes (kept in tests/fuzz/growth_json/): a
// dozen elements, some far apart, sizes from 0.01 to 20, grown as the target grows them (40 motifs
// in rect:200,120). A restart from which nothing grows closes its circle for good, and a run of 16
// ends the fill (holes come largest first), so there are a handful of restarts, not thousands.
TEST(GrowthHoles, FruitlessRestartsAreBounded) {
    const Region panel = Region::from_spec("rect:200,120");
    for (const char* name : {"restarts-that-grow-nothing.json", "restarts-far-apart-sizes.json"}) {
        Reference reference = Reference::from_json_file(std::string(ACANTHUS_SOURCE_DIR) +
                                                        "/tests/fuzz/growth_json/" + name);
        for (Mode mode : {Mode::none, Mode::rotation}) {
            Options options;
            options.max_elements = 40;
            options.mode = mode;
            SynthesisResult r = synthesize(reference, panel, options, {}, 1);
            std::printf("%s, mode %d: %zu motifs, %ld restarts (%ld fruitless), %ld searches\n",
                        name, static_cast<int>(mode), r.motifs.size(), r.stats.restarts,
                        r.stats.fruitless, r.stats.hole_searches);
            const long grown = r.stats.restarts - r.stats.fruitless;
            EXPECT_GE(grown, 0);
            EXPECT_LE(grown, static_cast<long>(r.motifs.size()));
            EXPECT_LE(r.stats.fruitless, 16 * (grown + 1));
            EXPECT_LE(r.stats.hole_searches, r.stats.restarts + 1);
            EXPECT_LE(r.stats.restarts, 17 * 41);
        }
    }
}

}  // namespace
