// Regular references grown through the library's synthesis into a rectangle and measured by the
// fidelity checker (growth_fidelity.hpp): interior defects, same-symbol neighbours, spacing. The
// numbers are printed, so that a run shows where each lattice kind stands.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <cstdio>
#include <string>

#include "growth_fidelity.hpp"
#include "growth_lattices.hpp"

using namespace acanthus;
using namespace acanthus::growth;
using growth_lattices::Kind;

namespace {

growth_fidelity::Fidelity grow(const Reference& ref, std::uint64_t seed) {
    Region region = Region::from_spec("rect:240,180");
    SynthesisResult r = synthesize(ref, region, Options{}, {}, seed);
    growth_fidelity::Fidelity f =
        growth_fidelity::measure(growth_fidelity::sites(ref), growth_fidelity::sites(r), region);
    std::printf(
        "%-24s seed %d: interior %4d, defects %5.1f%%, same-symbol pairs %5.1f%% "
        "(reference %5.1f%%), NN median ratio %.3f\n",
        ref.name().c_str(), static_cast<int>(seed), f.interior, 100 * f.defect_share(),
        100 * f.same_share, 100 * f.reference_same, f.spacing_ratio);
    return f;
}

Reference lattice(Kind kind, int decimals) {
    return Reference::from_elements(
        growth_lattices::lattice(kind, 9, 10, decimals), {},
        std::string(growth_lattices::name(kind)) + (decimals < 0 ? " exact" : " rounded"));
}

// Labels shared by symbol ("0", "1", "2") were the sub-id term once, and collapsed every lattice
// with more than one symbol; each element is its own sub-id now. Rounded to 3 decimals of the
// spacing, the zigzag sides' slivers once made edge elements interior with gapped rings.
TEST(GrowthFidelity, TriangularLatticesGrowWithoutDefectsExactOrRounded) {
    for (Kind kind : {Kind::triangular, Kind::three_colour})
        for (int decimals : {-1, 3})
            for (std::uint64_t seed : {1u, 2u}) {
                growth_fidelity::Fidelity f = grow(lattice(kind, decimals), seed);
                EXPECT_GT(f.interior, 300);
                EXPECT_EQ(f.defects, 0) << growth_lattices::name(kind) << " seed " << seed;
                EXPECT_NEAR(f.same_share, f.reference_same, 1e-12);
                EXPECT_NEAR(f.spacing_ratio, 1.0, 0.01);
            }
}

// Every kind, exact and rounded, and the example references: printed, not asserted.
TEST(GrowthFidelity, Report) {
    for (Kind kind : growth_lattices::all_kinds())
        for (int decimals : {-1, 3}) grow(lattice(kind, decimals), 1);
    for (const char* file : {"lattice.json", "tricolour.json", "checker.json", "stripes.json"})
        grow(
            Reference::from_file(std::string(ACANTHUS_SOURCE_DIR) + "/examples/references/" + file),
            1);
}

}  // namespace
