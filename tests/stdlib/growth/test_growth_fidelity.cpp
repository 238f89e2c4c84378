// The expert's checker (the library's fidelity code, stdlib/growth/fidelity.cpp: interior motifs
// whose ring matches no reference ring) on its own, and regular references grown through the
// library's synthesis into a rectangle and measured by it. The numbers are printed, so that a run
// shows where each lattice kind stands.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "fidelity.hpp"
#include "growth_lattices.hpp"
#include "panel.hpp"

using namespace acanthus;
using namespace acanthus::growth;
namespace gd = acanthus::growth::detail;
using growth_lattices::Kind;

namespace {

// The library's report for these motifs in this region.
Fidelity measure(const Reference& ref, const std::vector<Motif>& motifs, const Region& region) {
    gd::RegionPanel panel(region);
    return gd::measure_fidelity(ref.data(), motifs, panel, 0.0);
}

std::vector<Motif> as_motifs(const std::vector<ReferenceElement>& elements) {
    std::vector<Motif> out;
    for (const ReferenceElement& e : elements) {
        Motif m;
        m.position = e.position;
        m.symbol = e.symbol;
        out.push_back(m);
    }
    return out;
}

// The box of the motifs' centres, one unit wider on every side.
Region box_around(const std::vector<Motif>& motifs) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Motif& m : motifs) {
        x0 = std::min(x0, m.position.x), x1 = std::max(x1, m.position.x);
        y0 = std::min(y0, m.position.y), y1 = std::max(y1, m.position.y);
    }
    return Region::from_svg_string("<svg xmlns='http://www.w3.org/2000/svg'><rect x='" +
                                       std::to_string(x0 - 1) + "' y='" + std::to_string(y0 - 1) +
                                       "' width='" + std::to_string(x1 - x0 + 2) + "' height='" +
                                       std::to_string(y1 - y0 + 2) + "'/></svg>",
                                   "patch box");
}

Fidelity grow(const Reference& ref, std::uint64_t seed, const Options& options = {}) {
    Region region = Region::from_spec("rect:240,180");
    SynthesisResult r = synthesize(ref, region, options, {}, seed);
    Fidelity f = measure(ref, r.motifs, region);
    std::printf(
        "%-24s seed %d: interior %4ld, defects %5.1f%%, same-symbol pairs %5.1f%% "
        "(reference %5.1f%%), NN median ratio %.3f, lattice sites %d, repaired %ld\n",
        ref.name().c_str(), static_cast<int>(seed), f.interior, 100 * f.defect_share,
        100 * f.same_symbol_share, 100 * f.reference_same_symbol_share, f.nn_median,
        r.stats.lattice_sites, r.stats.repaired);
    // What synthesize reports is the same measurement.
    EXPECT_EQ(r.fidelity.defects, f.defects);
    EXPECT_EQ(r.fidelity.interior, f.interior);
    return f;
}

Reference lattice(Kind kind, int decimals) {
    return Reference::from_elements(
        growth_lattices::lattice(kind, 9, 10, decimals), {},
        std::string(growth_lattices::name(kind)) + (decimals < 0 ? " exact" : " rounded"));
}

// The checker itself: a patch of the reference's own lattice, larger than it, has no defect; one
// motif moved by a fifth of the spacing, or given the other symbol, is a defect with the
// neighbours that see it.
TEST(GrowthFidelity, CheckerFindsMovedAndSwappedMotifsOnly) {
    for (Kind kind : growth_lattices::all_kinds()) {
        Reference ref = lattice(kind, 3);
        std::vector<Motif> patch =
            as_motifs(growth_lattices::lattice(kind, 24, 10, -1, Point{60, 60}));
        // The panel is the patch's box, so that its edge motifs are not interior.
        Region region = box_around(patch);
        Fidelity clean = measure(ref, patch, region);
        EXPECT_GT(clean.interior, 250) << growth_lattices::name(kind);
        EXPECT_EQ(clean.defects, 0) << growth_lattices::name(kind);
        // The motif nearest the middle.
        std::size_t middle = 0;
        for (std::size_t i = 0; i < patch.size(); ++i)
            if (distance(patch[i].position, {180, 170}) <
                distance(patch[middle].position, {180, 170}))
                middle = i;
        std::vector<Motif> moved = patch;
        moved[middle].position += Vector{2.0, 0.0};
        Fidelity m = measure(ref, moved, region);
        EXPECT_GE(m.defects, 2) << growth_lattices::name(kind);
        EXPECT_LE(m.defects, 7) << growth_lattices::name(kind);
        if (kind == Kind::checker || kind == Kind::three_colour) {
            std::vector<Motif> swapped = patch;
            swapped[middle].symbol = swapped[middle].symbol == "a" ? "b" : "a";
            EXPECT_GE(measure(ref, swapped, region).defects, 4) << growth_lattices::name(kind);
        }
    }
}

// The NN median three ways: a square patch whose edge motifs (within 1.5 NN of the panel's edge)
// each have a companion 0.6 NN further out. Over all motifs the median falls to 0.6 NN; the inner
// motifs' stays the reference's 1, as does the inner reference elements'.
TEST(GrowthFidelity, InnerNNMediansLeaveTheEdgesOut) {
    Reference ref = lattice(Kind::square, -1);
    std::vector<Motif> patch =
        as_motifs(growth_lattices::lattice(Kind::square, 12, 10, -1, Point{60, 60}));
    Region region = box_around(patch);
    const Rect box = region.bounds();
    const Point middle{(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2};
    std::vector<Motif> crowded = patch;
    long edge = 0;
    for (const Motif& m : patch) {
        if (region.distance_to_boundary(m.position) >= 15) continue;
        ++edge;
        Motif companion = m;
        companion.position += (m.position - middle).normalized() * 6.0;
        crowded.push_back(companion);
    }
    Fidelity f = measure(ref, crowded, region);
    std::printf(
        "%ld edge motifs doubled: NN median %.3f all, %.3f inner; reference %.3f, inner "
        "%.3f\n",
        edge, f.nn_median, f.nn_median_inner, f.reference_nn_median, f.reference_nn_median_inner);
    EXPECT_GT(edge, 60);
    EXPECT_LT(f.nn_median, 0.7);
    EXPECT_NEAR(f.nn_median_inner, 1.0, 1e-9);
    EXPECT_NEAR(f.reference_nn_median, 1.0, 1e-9);
    EXPECT_NEAR(f.reference_nn_median_inner, 1.0, 1e-9);
    // Without edge effects the three ways agree.
    Fidelity plain = measure(ref, patch, region);
    EXPECT_NEAR(plain.nn_median, 1.0, 1e-9);
    EXPECT_NEAR(plain.nn_median_inner, 1.0, 1e-9);
}

// Labels shared by symbol ("0", "1", "2") were the sub-id term once, and collapsed every lattice
// with more than one symbol; each element is its own sub-id now. Rounded to 3 decimals of the
// spacing, the zigzag sides' slivers once made edge elements interior with gapped rings.
TEST(GrowthFidelity, EveryLatticeKindGrowsWithoutDefectsExactOrRounded) {
    for (Kind kind : growth_lattices::all_kinds())
        for (int decimals : {-1, 3})
            for (std::uint64_t seed : {1u, 2u}) {
                Fidelity f = grow(lattice(kind, decimals), seed);
                EXPECT_GT(f.interior, 150);
                EXPECT_EQ(f.defects, 0) << growth_lattices::name(kind) << " seed " << seed;
                // Where the panel's edge cuts the stripes shifts the share a little.
                EXPECT_NEAR(f.same_symbol_share, f.reference_same_symbol_share, 0.03);
                EXPECT_NEAR(f.nn_median, 1.0, 0.01);
            }
}

// The example references and, for comparison, the paper's growth alone (Options::lattice false):
// printed, the examples asserted.
TEST(GrowthFidelity, ExampleReferencesAndThePapersGrowth) {
    for (const char* file : {"lattice.json", "tricolour.json", "checker.json", "stripes.json"}) {
        Reference ref =
            Reference::from_file(std::string(ACANTHUS_SOURCE_DIR) + "/examples/references/" + file);
        EXPECT_EQ(grow(ref, 1).defects, 0) << file;
    }
    Options paper;
    paper.lattice = false;
    for (Kind kind : growth_lattices::all_kinds()) grow(lattice(kind, 3), 1, paper);
}

}  // namespace

TEST(GrowthFidelity, ALatticesSymbolMixIsItsSitesPerCell) {
    // Ten stripe columns hold 2 b columns (20%) where the lattice has 1 in 4, ten rows of the
    // 3-colour lattice 35% a; a faithful copy grows the lattice's share, so the report compares
    // with that.
    for (auto [kind, symbol, share] :
         {std::tuple{Kind::stripes, "b", 0.25}, std::tuple{Kind::three_colour, "a", 1.0 / 3}}) {
        const std::vector<ReferenceElement> elements = growth_lattices::lattice(kind, 10, 10);
        const double count = static_cast<double>(std::count_if(
            elements.begin(), elements.end(), [&](const auto& e) { return e.symbol == symbol; }));
        EXPECT_GT(std::abs(count / static_cast<double>(elements.size()) - share), 0.01);
        Reference ref = Reference::from_elements(elements);
        const std::vector<Motif> motifs = as_motifs(elements);
        Fidelity f = measure(ref, motifs, box_around(motifs));
        EXPECT_NEAR(f.reference_symbol_mix.at(symbol), share, 1e-12) << growth_lattices::name(kind);
    }
    // Off a lattice the share is the count.
    std::vector<ReferenceElement> jittered = growth_lattices::lattice(Kind::stripes, 10, 10);
    for (std::size_t i = 0; i < jittered.size(); ++i)
        jittered[i].position.x += 3.0 * std::sin(7.0 * static_cast<double>(i));
    Reference off = Reference::from_elements(jittered);
    const std::vector<Motif> motifs = as_motifs(jittered);
    EXPECT_NEAR(measure(off, motifs, box_around(motifs)).reference_symbol_mix.at("b"), 0.2, 1e-12);
}
