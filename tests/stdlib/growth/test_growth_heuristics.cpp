// Section 5.4's heuristics (Figure 6) and section 5.1's symbol priority, one test each, on
// patterns set up by hand around one seed of a triangular lattice reference (spacing 10, ring
// slots every 60 degrees from 0): a node near a ring slot is merged (b), a slot at a sharp angle
// to an edge is dropped (c), a slot whose edge crosses a link is dropped (d), a ring edge longer
// than 1.5 times its original gets an extra seed on the bisector (e); a seed waits for a
// higher-priority seed within 5 l. The paper's growth (no lattice) with relaxation off, so that
// positions stay where the heuristics put them. And the lattice repair, on a pattern disturbed
// by hand.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "fidelity.hpp"
#include "growth_fixtures.hpp"
#include "growth_lattices.hpp"
#include "panel.hpp"
#include "synthesis.hpp"

using namespace acanthus;
using namespace acanthus::growth;
namespace gd = acanthus::growth::detail;

namespace {

const Point S{100, 100};  // the seed that grows

Point slot(double degrees, double length = 10) {
    const double t = degrees * M_PI / 180;
    return S + Vector{length * std::cos(t), length * std::sin(t)};
}

struct Scene {
    explicit Scene(std::vector<ReferenceElement> elements = growth_fixtures::triangular_lattice(7,
                                                                                                7,
                                                                                                10),
                   Options o = paper())
        : reference(Reference::from_elements(std::move(elements))),
          options(std::move(o)),
          synthesis(reference.data(), panel, options, random) {}
    static Options paper() {
        Options o;
        o.lattice = false;
        o.relax = false;
        o.max_elements = 1;  // the first seed planted grows, nothing else
        o.gap_factor = 0;    // the paper merges within l_short only
        return o;
    }
    // Alive nodes within r of p.
    int nodes_near(Point p, double r) const {
        int n = 0;
        for (const gd::Node& node : synthesis.arrangement().nodes())
            n += node.alive && distance(node.position, p) < r;
        return n;
    }
    int node_at(Point p) const {
        const auto& nodes = synthesis.arrangement().nodes();
        for (std::size_t i = 0; i < nodes.size(); ++i)
            if (nodes[i].alive && distance(nodes[i].position, p) < 1e-6) return static_cast<int>(i);
        return -1;
    }
    gd::Arrangement& pattern() { return synthesis.arrangement(); }

    Reference reference;
    Region region = Region::from_spec("rect:200,200");
    gd::RegionPanel panel{region};
    Options options;
    Random random{1};
    gd::Synthesis synthesis;
};

// (b) A node within l_short (half the shortest edge) of a ring slot takes the new seed's place
// and is linked to the centre.
TEST(GrowthHeuristics, NodeNearARingSlotIsMerged) {
    Scene scene;
    const Point x = slot(0) + Vector{2, 1};
    ASSERT_EQ(scene.synthesis.plant({S, x}), 2);
    scene.synthesis.run();
    EXPECT_TRUE(scene.pattern().linked(0, 1));
    EXPECT_EQ(scene.nodes_near(slot(0), 5), 1) << "a seed beside the merged node";
    EXPECT_EQ(scene.synthesis.result().stats.merged, 1);
    for (double a : {60, 120, 180, 240, 300}) EXPECT_EQ(scene.nodes_near(slot(a), 1e-6), 1) << a;
}

// (b, beyond the paper) Off a lattice, a node closer to a ring slot than gap_factor times the
// reference's shortest edge between their symbols (0.9 x 10 here) also takes the new seed's
// place, so fronts meeting keep the reference's own closest spacing; l_short alone (5 here)
// lets a seed be made 6.7 from it.
TEST(GrowthHeuristics, NodeCloserThanTheReferenceSpacingIsMerged) {
    for (double factor : {0.9, 0.0}) {
        Options o = Scene::paper();
        o.gap_factor = factor;
        Scene scene(growth_fixtures::triangular_lattice(7, 7, 10), o);
        const Point x = slot(0) + Vector{6, 3};
        ASSERT_EQ(scene.synthesis.plant({S, x}), 2);
        scene.synthesis.run();
        if (factor > 0) {
            EXPECT_TRUE(scene.pattern().linked(0, 1));
            EXPECT_EQ(scene.nodes_near(slot(0), 3), 0) << "a seed 6.7 from a node";
            EXPECT_EQ(scene.synthesis.result().stats.merged, 1);
        } else {
            EXPECT_EQ(scene.nodes_near(slot(0), 1e-6), 1) << "the paper's growth";
            EXPECT_EQ(scene.synthesis.result().stats.merged, 0);
        }
        for (double a : {60, 120, 180, 240, 300})
            EXPECT_EQ(scene.nodes_near(slot(a), 1e-6), 1) << factor << " " << a;
    }
}

// (c) A slot at under half its original angle (60 degrees here) to an edge already at the
// centre is not made: the neighbour at 95 degrees, 1.5 spacings out (so not merged), makes the
// 120-degree slot 25 degrees off.
TEST(GrowthHeuristics, SlotAtASharpAngleToAnEdgeIsDropped) {
    Scene scene;
    const Point n1 = slot(0), n2 = slot(95, 15);
    ASSERT_EQ(scene.synthesis.plant({S, n1, n2}), 3);
    scene.pattern().link(0, 1, n1 - S);
    scene.pattern().link(0, 2, n2 - S);
    ASSERT_GT(distance(slot(120), n2), 5.0);  // not a merge
    scene.synthesis.run();
    EXPECT_EQ(scene.nodes_near(slot(120), 3), 0) << "the sharp slot was made";
    for (double a : {180, 240, 300}) EXPECT_EQ(scene.nodes_near(slot(a), 1e-6), 1) << a;
}

// (d) A slot whose edge would cross a link is not made. A-B crosses the edge to the 120-degree
// slot and lies more than l_short from every slot.
TEST(GrowthHeuristics, SlotWhoseEdgeCrossesALinkIsDropped) {
    Scene scene;
    const Point a = S + Vector{1.5, 4}, b = S + Vector{-4.5, 2.5};
    ASSERT_EQ(scene.synthesis.plant({S, a, b}), 3);
    scene.pattern().link(1, 2, b - a);
    for (double d : {0, 60, 120, 180, 240, 300}) {
        ASSERT_GT(distance(slot(d), a), 5.0);
        ASSERT_GT(distance(slot(d), b), 5.0);
    }
    auto side = [](Point o, Point p, Point q) { return (p - o).cross(q - o); };
    ASSERT_LT(side(S, slot(120), a) * side(S, slot(120), b), 0);  // the premise: they cross
    ASSERT_LT(side(a, b, S) * side(a, b, slot(120)), 0);
    scene.synthesis.run();
    EXPECT_EQ(scene.nodes_near(slot(120), 3), 0) << "the crossing slot was made";
    for (double d : {0, 60, 180, 240, 300}) EXPECT_EQ(scene.nodes_near(slot(d), 1e-6), 1) << d;
}

// (e) A ring edge longer than l_long = 1.5 x its original gets an id-less seed at the end of the
// bisector, as long as the mean of the two edges, linked to all three. The neighbour 1.8
// spacings out makes its ring edges to the 60- and 300-degree slots 1.56 spacings long.
TEST(GrowthHeuristics, LongRingEdgeGetsAnExtraSeedOnTheBisector) {
    Scene scene;
    const Point n = slot(0, 18);
    ASSERT_EQ(scene.synthesis.plant({S, n}), 2);
    scene.pattern().link(0, 1, n - S);
    scene.synthesis.run();
    for (double d : {30.0, -30.0}) {
        int extra = scene.node_at(slot(d, 14));
        ASSERT_GE(extra, 0) << "no extra seed at " << d << " degrees";
        const gd::Node& e = scene.pattern()[extra];
        EXPECT_EQ(e.symbol, -1);
        EXPECT_FALSE(e.placed());
        EXPECT_TRUE(scene.pattern().linked(extra, 0));
        EXPECT_TRUE(scene.pattern().linked(extra, 1));
        EXPECT_TRUE(scene.pattern().linked(extra, scene.node_at(slot(d > 0 ? 60 : 300))));
    }
    // The ring edges between the other slots are their original length: no extra seed there.
    EXPECT_EQ(scene.nodes_near(slot(90, 8.66), 3), 0);
}

// Section 5.1: a seed waits while a seed of a higher-priority symbol lies within 5 l.
TEST(GrowthHeuristics, SeedWaitsForAHigherPrioritySeedWithinFiveL) {
    auto elements = growth_fixtures::triangular_lattice(7, 7, 10, {"a", "b"});
    auto first_motif = [&](Point other, bool prioritized) {
        Options o = Scene::paper();
        if (prioritized) o.priority = {{"b", 1}};
        Scene scene(elements, o);
        EXPECT_EQ(scene.synthesis.plant({S, other}), 2);
        scene.pattern()[0].symbol = scene.reference.data().symbol_id("a");
        scene.pattern()[1].symbol = scene.reference.data().symbol_id("b");
        scene.synthesis.run();
        SynthesisResult r = scene.synthesis.result();
        EXPECT_EQ(r.motifs.size(), 1u);
        return r.motifs.empty() ? Motif{} : r.motifs.front();
    };
    // 30 from the a seed (first in the queue), the b seed grows first.
    Motif m = first_motif(S + Vector{30, 0}, true);
    EXPECT_EQ(m.symbol, "b");
    EXPECT_EQ(m.position, (S + Vector{30, 0}));
    // Without priorities, or 70 away (beyond 5 l = 50), the a seed goes first.
    EXPECT_EQ(first_motif(S + Vector{30, 0}, false).symbol, "a");
    EXPECT_EQ(first_motif(S + Vector{70, 0}, true).symbol, "a");
}

// Over a whole growth: with b first, the b motifs come early.
TEST(GrowthHeuristics, PriorityGrowsTheHigherSymbolFirst) {
    Reference ref =
        Reference::from_elements(growth_fixtures::triangular_lattice(8, 8, 10, {"a", "b"}));
    Region region = Region::from_spec("rect:200,160");
    auto early_b = [&](bool prioritized) {
        Options o;
        o.lattice = false;
        if (prioritized) o.priority = {{"b", 1}};
        SynthesisResult r = synthesize(ref, region, o, {}, 3);
        int b = 0;
        for (std::size_t i = 0; i < 60; ++i) b += r.motifs[i].symbol == "b";
        return b;
    };
    int with = early_b(true), without = early_b(false);
    EXPECT_GT(with, without + 10) << "b among the first 60: " << with << " vs " << without;
}

// A waiting seed goes back to the queue as soon as the higher-priority seeds near it are grown:
// growth still goes outward, no motif near the start is left for the end.
TEST(GrowthHeuristics, WaitingSeedsGrowWhenTheirBlockersAreGone) {
    Reference ref =
        Reference::from_elements(growth_fixtures::triangular_lattice(8, 8, 10, {"a", "b"}));
    Region region = Region::from_spec("rect:240,180");
    Options o;
    o.lattice = false;
    o.fill_holes = false;
    o.priority = {{"b", 1}};
    const Point start{120, 90};
    SynthesisResult r = synthesize(ref, region, o, {start}, 3);
    ASSERT_GT(r.motifs.size(), 300u);
    const std::size_t last = r.motifs.size() * 3 / 4;
    for (std::size_t i = last; i < r.motifs.size(); ++i)
        EXPECT_GT(distance(r.motifs[i].position, start), 60.0)
            << "motif " << i << " of " << r.motifs.size() << " (" << r.motifs[i].symbol << ")";
}

// The lattice repair: a motif moved off its lattice point and another given an element of
// another site are found by the checker, removed with what they spoil, and grown again.
TEST(GrowthRepair, DisturbedMotifsAreRemovedAndGrownAgain) {
    Options o;
    Scene scene(growth_lattices::lattice(growth_lattices::Kind::three_colour, 9, 10, 3), o);
    scene.synthesis.plant({S});
    scene.synthesis.run();
    ASSERT_TRUE(scene.synthesis.lattice_found());
    SynthesisResult before = scene.synthesis.result();
    ASSERT_EQ(gd::measure_fidelity(scene.reference.data(), before.motifs, scene.panel, 0).defects,
              0);
    ASSERT_EQ(before.stats.repaired, 0);
    // Two interior motifs: one moved by a quarter spacing, one turned into another site's.
    int moved = -1, swapped = -1;
    const auto& nodes = scene.pattern().nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (!nodes[i].alive || !nodes[i].placed() || nodes[i].fixed) continue;
        if (moved < 0 && distance(nodes[i].position, S + Vector{30, 20}) < 6)
            moved = static_cast<int>(i);
        if (swapped < 0 && distance(nodes[i].position, S + Vector{-30, -20}) < 6)
            swapped = static_cast<int>(i);
    }
    ASSERT_GE(moved, 0);
    ASSERT_GE(swapped, 0);
    scene.pattern().move(moved, nodes[moved].position + Vector{2.5, 0});
    int other = -1;
    for (int c : scene.reference.data().candidates)
        if (scene.reference.data().symbol[c] != nodes[swapped].symbol) other = c;
    scene.pattern()[swapped].source = other;
    scene.pattern()[swapped].symbol = scene.reference.data().symbol[other];
    SynthesisResult broken = scene.synthesis.result();
    EXPECT_GE(gd::measure_fidelity(scene.reference.data(), broken.motifs, scene.panel, 0).defects,
              8);

    scene.synthesis.repair();
    SynthesisResult after = scene.synthesis.result();
    Fidelity f = gd::measure_fidelity(scene.reference.data(), after.motifs, scene.panel, 0);
    EXPECT_EQ(f.defects, 0);
    EXPECT_GE(after.stats.repaired, 2);
    EXPECT_EQ(after.motifs.size(), before.motifs.size());
}

}  // namespace

namespace {

// Candidate pruning (prune.cpp) chooses what matching every candidate chooses: the same motifs,
// sources and links, in modes none and flow, for an irregular reference and a jittered one, with
// the symbol-mix term (w4) and without it.
TEST(GrowthPruning, SameChoicesAsMatchingEveryCandidate) {
    std::vector<Reference> refs{
        Reference::from_file(std::string(ACANTHUS_SOURCE_DIR) + "/examples/references/stones.json"),
        Reference::from_elements(growth_fixtures::jittered_lattice(12, 12, 10, 1.5, {"a", "b"}))};
    Region region = Region::from_spec("rect:150,110");
    gd::RegionPanel panel(region);
    for (const Reference& ref : refs)
        for (Mode mode : {Mode::none, Mode::flow})
            for (double w4 : {0.0, 20.0}) {
                Options o;
                o.mode = mode;
                o.w4 = w4;
                o.flow_strokes = {{{0, 0}, {150, 110}}};
                std::vector<SynthesisResult> results;
                for (bool pruned : {false, true}) {
                    Random random(5);
                    gd::Synthesis s(ref.data(), panel, o, random);
                    s.set_pruning(pruned);
                    s.plant({{75, 55}});
                    s.run();
                    results.push_back(s.result());
                }
                const SynthesisResult &all = results[0], &pruned = results[1];
                ASSERT_GT(all.motifs.size(), 100u);
                ASSERT_EQ(all.motifs.size(), pruned.motifs.size()) << ref.name() << " w4 " << w4;
                for (std::size_t i = 0; i < all.motifs.size(); ++i) {
                    ASSERT_EQ(all.motifs[i].source, pruned.motifs[i].source) << i << " w4 " << w4;
                    ASSERT_EQ(all.motifs[i].position, pruned.motifs[i].position)
                        << i << " w4 " << w4;
                }
                EXPECT_EQ(all.edges, pruned.edges);
            }
}

}  // namespace

// Issue 27: after growth from an irregular reference, motifs of two symbols exchange their
// elements until the close pairs' same-symbol share is the reference's; positions, the number of
// motifs and the symbol mix stay as grown. Without the exchange the share is off by a few points
// in at least one of the seeds (what makes this test fail on a version that does nothing).
TEST(GrowthNeighbourShare, ExchangesBringTheSameSymbolShareToTheReferencesAndMoveNothing) {
    Reference ref = Reference::from_json_file(std::string(ACANTHUS_SOURCE_DIR) +
                                              "/examples/references/stones.json");
    Region region = Region::from_spec("rect:160,120");
    double worst_off = 0;
    for (unsigned long long seed : {1ULL, 2ULL, 3ULL, 4ULL}) {
        Options grown;
        grown.neighbour_share = false;
        SynthesisResult a = synthesize(ref, region, grown, {}, seed);
        SynthesisResult b = synthesize(ref, region, Options{}, {}, seed);
        ASSERT_EQ(a.motifs.size(), b.motifs.size());
        std::map<std::string, int> mix_a, mix_b;
        int changed = 0;
        for (std::size_t i = 0; i < a.motifs.size(); ++i) {
            EXPECT_EQ(a.motifs[i].position, b.motifs[i].position) << "motif " << i;
            ++mix_a[a.motifs[i].symbol];
            ++mix_b[b.motifs[i].symbol];
            changed += a.motifs[i].source != b.motifs[i].source;
        }
        EXPECT_EQ(mix_a, mix_b);
        const Fidelity& f = b.fidelity;
        EXPECT_NEAR(f.same_symbol_share, f.reference_same_symbol_share, 0.01) << "seed " << seed;
        worst_off = std::max(worst_off, std::abs(a.fidelity.same_symbol_share -
                                                 a.fidelity.reference_same_symbol_share));
        EXPECT_EQ(changed > 0, b.stats.exchanges > 0);
        EXPECT_EQ(a.stats.exchanges, 0);
    }
    EXPECT_GT(worst_off, 0.02) << "growth alone already keeps the share: the test tests nothing";
}
