// GrowthEngine: the main loop of Wong et al. 4.1 with the dots of Appendix A: geometry of the
// result, incremental == reference engine, determinism, region parts and seeds.
#include <gtest/gtest.h>

#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "fixtures/growth_tree.hpp"

using namespace acanthus;

using namespace acanthus::test;

TEST(Growth, DotsFillRectangleWithoutOverlap) {
    const Region region = Region::from_spec("rect:100,60");
    acanthus::GrowthStats stats;
    GrowthOptions o = small_options();
    o.resolution = 200;
    o.min_radius = 0.05;  // lets circles through that the rule refuses (radius < 0.5)
    const auto tree = grow(dots::pattern(), region, o, &stats);
    expect_valid_tree(tree);
    expect_dots_fit(tree, region);
    EXPECT_EQ(stats.stop_reason, "exhausted");
    // One seed, every other element a dot; dots cover a good part of the panel.
    ASSERT_GT(tree.size(), 100u);
    EXPECT_EQ(tree[0].type, "seed");
    EXPECT_TRUE(tree[0].sterile);
    double area = 0;
    for (const Circle& c : dots_of(tree)) area += M_PI * c.radius * c.radius;
    EXPECT_GT(area / region.area(), 0.5);
    // Rule statistics: the seed rule ran once, every other dot came from dot --> dot.
    ASSERT_EQ(stats.rules.size(), 2u);
    EXPECT_EQ(stats.rules[0].successes, 1);
    EXPECT_EQ(stats.rules[1].successes, static_cast<long>(tree.size()) - 2);
    EXPECT_GT(stats.rules[1].failures, 0);  // tiny gaps (radius < 0.5) fail
    EXPECT_GT(stats.exclude_points, 0);
    EXPECT_GE(stats.iterations, static_cast<long>(tree.size()) - 1);
}

TEST(Growth, FirstDotSitsOnTheDefaultSeedAtTheInscribedCentre) {
    const Region region = Region::from_spec("circle:40");
    const auto tree = grow(dots::pattern(), region, small_options());
    const Circle inscribed = region.largest_inscribed_circle(0.01);
    ASSERT_GE(tree.size(), 2u);
    EXPECT_NEAR(tree[0].coords[0], inscribed.center.x, 0.5);
    EXPECT_NEAR(tree[0].coords[1], inscribed.center.y, 0.5);
    EXPECT_EQ(tree[1].parent, 0);
    EXPECT_EQ(tree[1].coords[0], tree[0].coords[0]);
    EXPECT_EQ(tree[1].coords[2], 3.0);
}

class EnginesAgree : public ::testing::TestWithParam<std::string> {};

TEST_P(EnginesAgree, IncrementalAndReferenceGiveIdenticalTrees) {
    const Region region = region_named(GetParam());
    acanthus::GrowthStats inc_stats, ref_stats;
    const auto incremental = grow(dots::pattern(), region, small_options(false), &inc_stats);
    const auto reference = grow(dots::pattern(), region, small_options(true), &ref_stats);
    ASSERT_GT(incremental.size(), 50u);
    ASSERT_EQ(incremental.size(), reference.size());
    for (std::size_t k = 0; k < incremental.size(); ++k)
        ASSERT_EQ(incremental[k], reference[k]) << "element " << k;
    EXPECT_EQ(inc_stats.iterations, ref_stats.iterations);
    EXPECT_EQ(inc_stats.exclude_points, ref_stats.exclude_points);
    expect_valid_tree(incremental);
    expect_dots_fit(incremental, region);
    // The lazy far field (on by default only for large buffers) grows the same tree.
    GrowthOptions lazy = small_options(false);
    lazy.lazy_field_pixels = 0;
    EXPECT_EQ(grow(dots::pattern(), region, lazy), reference);
}

INSTANTIATE_TEST_SUITE_P(Regions, EnginesAgree,
                         ::testing::Values("rect:100,60", "circle:40", "ellipse:60,25", "hole"),
                         [](const auto& info) {
                             std::string s = info.param;
                             for (char& c : s)
                                 if (!isalnum(static_cast<unsigned char>(c))) c = '_';
                             return s;
                         });

TEST(Growth, EnginesAgreeWithSeveralSeedsAndAMinimumRadius) {
    const Region region = region_named("hole");
    GrowthOptions o = small_options();
    o.seeds = {{10, 10}, {90, 70}, {50, 10}};
    o.min_radius = 1.5;
    const auto incremental = grow(dots::pattern(), region, o);
    o.reference_engine = true;
    const auto reference = grow(dots::pattern(), region, o);
    ASSERT_EQ(incremental, reference);
    // Seeds come first, in the order given, at the given points.
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(incremental[k].type, "seed");
        EXPECT_EQ(incremental[k].coords, (std::vector<double>{o.seeds[k].x, o.seeds[k].y}));
    }
}

// The engines agree on a 2048 px buffer too (a long strip keeps the reference engine's whole
// field per iteration cheap): about one unit per pixel, as on a poster.
TEST(Growth, EnginesAgreeAt2048Pixels) {
    const Region region = Region::from_spec("rect:2000,40");
    GrowthOptions o;
    o.resolution = 2048;
    o.max_elements = 300;
    const auto incremental = grow(dots::pattern(), region, o);
    o.reference_engine = true;
    const auto reference = grow(dots::pattern(), region, o);
    ASSERT_EQ(incremental.size(), 300u);
    ASSERT_EQ(incremental, reference);
    expect_dots_fit(incremental, region);
    o.reference_engine = false;
    o.lazy_field_pixels = 0;
    EXPECT_EQ(grow(dots::pattern(), region, o), reference);
}

// The paper's Manhattan MAT (--distance manhattan): it grows a valid ornament, the same one on
// every run and with the reference engine, and not the Euclidean one.
TEST(Growth, ManhattanMetricGrowsDeterministicallyAndDiffersFromEuclidean) {
    const Region region = region_named("hole");
    GrowthOptions o = small_options();
    o.distance = DistanceMetric::manhattan;
    const auto manhattan = grow(dots::pattern(), region, o);
    ASSERT_GT(manhattan.size(), 50u);
    expect_valid_tree(manhattan);
    expect_dots_fit(manhattan, region);
    EXPECT_EQ(grow(dots::pattern(), region, o), manhattan);
    GrowthOptions lazy = o;  // the lazy field with the city-block metric
    lazy.lazy_field_pixels = 0;
    EXPECT_EQ(grow(dots::pattern(), region, lazy), manhattan);
    o.reference_engine = true;
    EXPECT_EQ(grow(dots::pattern(), region, o), manhattan);
    EXPECT_NE(grow(dots::pattern(), region, small_options()), manhattan);
}

TEST(Growth, SameInputsGiveTheSameTree) {
    const Region region = Region::from_spec("ellipse:50,30");
    EXPECT_EQ(grow(dots::pattern(), region, small_options()),
              grow(dots::pattern(), region, small_options()));
}

TEST(RegionParts, TwoSeparatePartsAndASquareWithAHole) {
    const Region two =
        Region::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) + "/examples/panels/two-parts.svg");
    const auto parts = two.parts();
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_NEAR(parts[0].area() + parts[1].area(), two.area(), 1e-6 * two.area());
    // The rounded square on the left, the disc on the right.
    EXPECT_LT(parts[0].bounds().x1, parts[1].bounds().x0);
    EXPECT_TRUE(parts[0].contains({55, 55}));
    EXPECT_FALSE(parts[0].contains({205, 55}));
    EXPECT_TRUE(parts[1].contains({205, 55}));
    EXPECT_NEAR(parts[1].area(), M_PI * 55 * 55, 0.01 * 55 * 55);

    const Region hole = region_named("hole");
    const auto one = hole.parts();
    ASSERT_EQ(one.size(), 1u);
    EXPECT_DOUBLE_EQ(one[0].area(), hole.area());
    EXPECT_FALSE(one[0].contains({50, 40}));
    EXPECT_TRUE(one[0].contains({10, 10}));
}

TEST(RegionParts, IslandInAHoleIsAPartOfItsOwn) {
    const Region r = Region::from_svg_string(
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">)"
        R"(<path fill-rule="evenodd" d="M0,0 H100 V100 H0 Z M20,20 H80 V80 H20 Z )"
        R"(M40,40 H60 V60 H40 Z"/></svg>)",
        "island.svg");
    const auto parts = r.parts();
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_NEAR(parts[0].area(), 100 * 100 - 60 * 60, 1e-6);
    EXPECT_NEAR(parts[1].area(), 20 * 20, 1e-6);
    EXPECT_FALSE(parts[0].contains({50, 50}));
    EXPECT_FALSE(parts[0].contains({30, 30}));
    EXPECT_TRUE(parts[1].contains({50, 50}));
}

TEST(Growth, DefaultSeedsOnePerPartLargestFirst) {
    const Region region =
        Region::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) + "/examples/panels/two-parts.svg");
    GrowthOptions o = small_options();
    o.max_elements = 200;
    const auto tree = grow(dots::pattern(), region, o);
    ASSERT_GE(tree.size(), 2u);
    ASSERT_EQ(tree[0].type, "seed");
    ASSERT_EQ(tree[1].type, "seed");
    const auto parts = region.parts();
    const Circle a = parts[0].largest_inscribed_circle(0.01);
    const Circle b = parts[1].largest_inscribed_circle(0.01);
    // Each part has its seed near the centre of its inscribed circle.
    const Point s0{tree[0].coords[0], tree[0].coords[1]}, s1{tree[1].coords[0], tree[1].coords[1]};
    const bool first_left = s0.x < s1.x;
    const Point left = first_left ? s0 : s1, right = first_left ? s1 : s0;
    EXPECT_LT(distance(left, a.center), 1.0);
    EXPECT_LT(distance(right, b.center), 1.0);
    // Both parts grow dots.
    int in_left = 0, in_right = 0;
    for (const Circle& c : dots_of(tree)) (c.center.x < 130 ? in_left : in_right)++;
    EXPECT_GT(in_left, 10);
    EXPECT_GT(in_right, 10);
    // The engines agree, and a second run gives the same tree.
    EXPECT_EQ(grow(dots::pattern(), region, o), tree);
    o.reference_engine = true;
    EXPECT_EQ(grow(dots::pattern(), region, o), tree);
}

TEST(Growth, DefaultSeedsSkipPartsBelowTheMinimumRadius) {
    // A large square and a small one: with a minimum radius above the small one's inscribed
    // radius only the large one is seeded.
    const Region region = Region::from_svg_string(
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="60">)"
        R"(<rect x="0" y="0" width="60" height="60"/><rect x="80" y="40" width="10" height="10"/>)"
        R"(</svg>)",
        "small-part.svg");
    GrowthOptions o = small_options();
    o.max_elements = 5;
    auto tree = grow(dots::pattern(), region, o);
    int seeds = 0;
    for (const Node& n : tree) seeds += n.type == "seed";
    EXPECT_EQ(seeds, 2);
    EXPECT_NEAR(tree[0].coords[0], 30, 0.5);  // largest first
    EXPECT_NEAR(tree[1].coords[0], 85, 0.5);
    o.min_radius = 6;
    tree = grow(dots::pattern(), region, o);
    seeds = 0;
    for (const Node& n : tree) seeds += n.type == "seed";
    EXPECT_EQ(seeds, 1);
    EXPECT_NEAR(tree[0].coords[0], 30, 0.5);
}

TEST(Growth, SeedOutsideTheRegionIsRefused) {
    const Region region = Region::from_spec("rect:100,60");
    GrowthOptions o = small_options();
    o.seeds = {{50, 30}, {500, 30.5}};
    const Pattern p = dots::pattern();
    GrowthEngine engine(p, region, o);
    try {
        engine.run();
        FAIL() << "expected InputError";
    } catch (const acanthus::InputError& e) {
        EXPECT_EQ(std::string(e.what()), "seed 500,30.5 is outside the region rect:100,60");
    }
}

TEST(Growth, SeedInTheHoleIsRefused) {
    GrowthOptions o = small_options();
    o.seeds = {{50, 40}};
    const Pattern p = dots::pattern();
    const Region region = region_named("hole");
    GrowthEngine engine(p, region, o);
    EXPECT_THROW(engine.run(), acanthus::InputError);
}

TEST(Growth, BadResolutionIsAUsageError) {
    GrowthOptions o;
    o.resolution = 2;
    const Pattern p = dots::pattern();
    const Region region = Region::from_spec("rect:10,10");
    EXPECT_THROW(GrowthEngine(p, region, o), acanthus::UsageError);
}

TEST(Growth, ReleasingTheGrowthStateKeepsTheElementsStatsAndGrid) {
    const Region region = Region::from_spec("rect:100,60");
    const Pattern pattern = dots::pattern();
    GrowthEngine engine(pattern, region, small_options());
    engine.run();
    const auto tree = snapshot(engine);
    const long iterations = engine.stats().iterations;
    const GridFrame grid = engine.grid();
    ASSERT_GT(tree.size(), 50u);
    engine.release_growth_state();
    EXPECT_EQ(snapshot(engine), tree);
    EXPECT_EQ(engine.stats().iterations, iterations);
    EXPECT_EQ(engine.grid().width, grid.width);
    EXPECT_EQ(engine.grid().pixel, grid.pixel);
    EXPECT_THROW(engine.run(), std::logic_error);
}
