// A rule body that commits many elements at once (as the stdlib libraries do): the engine places
// them in one pass and brings the field up to date once, growing the same tree as the reference
// engine, eagerly and lazily; and growth ends once no element can parent a rule.
#include <gtest/gtest.h>

#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <vector>

#include "fixtures/growth_tree.hpp"

using namespace acanthus;
using namespace acanthus::test;

namespace bulk {

int lattice_rows = 0, lattice_cols = 0;
bool sterile_dots = false;

// seed --> a lattice of dots about the seed, all in one commit.
Result seed_lattice(RuleCall& call_) {
    const auto& seed = call_.parent<dots::seed>().p0;
    const Point c{seed.x, seed.y};
    for (int j = 0; j < lattice_rows; ++j)
        for (int i = 0; i < lattice_cols; ++i) {
            auto* d = new dots::dot;
            // Rows shifted by half a step, as in a triangular lattice.
            const double x = c.x + (i - (lattice_cols - 1) / 2.0) * 9 + (j % 2) * 4.5;
            const double y = c.y + (j - (lattice_rows - 1) / 2.0) * 8;
            d->p0.set(Point{x, y}, 1.5);
            d->order = dots::dot_count++;
            d->sterile = sterile_dots;
            call_.add_dynamic(*d);
        }
    call_.parent<dots::seed>().sterile = true;
    return SUCCESS;
}

Pattern lattice_then_dots(int rows, int cols, bool sterile = false) {
    sterile_dots = sterile;
    lattice_rows = rows;
    lattice_cols = cols;
    Pattern p = dots::pattern();
    p.rules[0].body = &seed_lattice;
    return p;
}

}  // namespace bulk

TEST(BulkPlacement, ALatticeInOneCommitGrowsTheReferenceTree) {
    const Region region = Region::from_spec("rect:200,120");
    const Pattern p = bulk::lattice_then_dots(12, 20);
    GrowthOptions o;
    o.resolution = 600;  // 600 x 360 pixels: the eager field
    o.max_elements = 1200;
    o.reference_engine = true;
    const auto reference = grow(p, region, o);
    ASSERT_GT(reference.size(), 241u + 200u);  // the lattice, then dots between its rows
    expect_valid_tree(reference);
    expect_dots_fit(reference, region);
    o.reference_engine = false;
    EXPECT_EQ(grow(p, region, o), reference);
    o.lazy_field_pixels = 0;  // the lazy field
    EXPECT_EQ(grow(p, region, o), reference);
    o.distance = DistanceMetric::manhattan;
    const auto manhattan = grow(p, region, o);
    o.reference_engine = true;
    EXPECT_EQ(grow(p, region, o), manhattan);
}

// Two bulk commits in a row, then single placements: the second finds the field still stale.
TEST(BulkPlacement, StaleFieldThroughSeveralCommits) {
    const Region region = Region::from_spec("rect:200,120");
    const Pattern p = bulk::lattice_then_dots(6, 8);
    GrowthOptions o;
    o.resolution = 800;
    o.seeds = {{50, 40}, {150, 80}};
    o.max_elements = 700;
    o.lazy_field_pixels = 0;
    const auto incremental = grow(p, region, o);
    o.reference_engine = true;
    const auto reference = grow(p, region, o);
    ASSERT_EQ(incremental, reference);
    EXPECT_GT(reference.size(), 2u + 96u + 100u);
}

TEST(BulkPlacement, GrowthEndsWhenNoElementCanParentARule) {
    Pattern p = bulk::lattice_then_dots(4, 4);
    p.rules.pop_back();  // dots take no rule: the lattice is all there is
    GrowthOptions o = small_options();
    GrowthStats stats;
    const auto tree = grow(p, Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(tree.size(), 1u + 16u);
    EXPECT_EQ(stats.iterations, 1);  // no circle is searched for after the lattice
    EXPECT_EQ(stats.exclude_points, 0);
    EXPECT_EQ(stats.stop_reason, "exhausted");
    o.reference_engine = true;
    GrowthStats ref;
    EXPECT_EQ(grow(p, Region::from_spec("rect:100,60"), o, &ref), tree);
    EXPECT_EQ(ref.iterations, 1);
    // The same when dots take a rule but every one is sterile.
    const Pattern q = bulk::lattice_then_dots(4, 4, /*sterile=*/true);
    o.reference_engine = false;
    GrowthStats sterile;
    EXPECT_EQ(grow(q, Region::from_spec("rect:100,60"), o, &sterile).size(), 17u);
    EXPECT_EQ(sterile.iterations, 1);
    // And with fertile dots, growth goes on between them.
    EXPECT_GT(grow(bulk::lattice_then_dots(4, 4), Region::from_spec("rect:100,60"), o).size(),
              17u);
}
