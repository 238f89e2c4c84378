// GrowthEngine: the main loop of Wong et al. 4.1 with hand-written patterns (the dots of
// Appendix A and variants): geometry of the result, incremental == reference engine, exclude
// list, %exhausted, stop conditions, seeds, rule failures, debug frames.
#include <gtest/gtest.h>

#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "dots_pattern.hpp"

using acanthus::Circle;
using acanthus::CircleProxy;
using acanthus::DebugFrame;
using acanthus::Element;
using acanthus::GrowthEngine;
using acanthus::GrowthOptions;
using acanthus::Pattern;
using acanthus::Point;
using acanthus::PointProxy;
using acanthus::ProxyKind;
using acanthus::Region;
using acanthus::Result;
using acanthus::RuleCall;
using acanthus::RuleInfo;

namespace {

const char* kHoleSvg =
    R"(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="80">)"
    R"(<path fill-rule="evenodd" d="M0,0 H100 V80 H0 Z M35,25 H65 V55 H35 Z"/></svg>)";

Region region_named(const std::string& name) {
    if (name == "hole") return Region::from_svg_string(kHoleSvg, "hole.svg");
    return Region::from_spec(name);
}

// Everything that defines an element tree, flattened for exact comparison.
struct Node {
    int id, parent, depth, children;
    bool sterile;
    std::string type;
    std::vector<double> coords;
    bool operator==(const Node&) const = default;
};

std::vector<double> coords_of(const Element& e) {
    std::vector<double> out;
    for (std::size_t k = 0; k < e.proxy_count(); ++k) {
        const auto& p = e.proxy(k);
        if (p.kind() == ProxyKind::point) {
            const auto& q = static_cast<const PointProxy&>(p);
            out.insert(out.end(), {q.x, q.y});
        } else if (p.kind() == ProxyKind::circle) {
            const auto& c = static_cast<const CircleProxy&>(p);
            out.insert(out.end(), {c.center.x, c.center.y, c.radius});
        }
    }
    return out;
}

std::vector<Node> snapshot(const GrowthEngine& engine) {
    std::vector<Node> out;
    for (const Element* e : engine.elements())
        out.push_back({e->id, e->parent ? e->parent->id : -1, e->depth, e->children, e->sterile,
                       e->type().name, coords_of(*e)});
    return out;
}

std::vector<Node> grow(const Pattern& pattern, const Region& region, GrowthOptions options,
                       acanthus::GrowthStats* stats = nullptr) {
    dots::dot_count = 0;
    GrowthEngine engine(pattern, region, options);
    engine.run();
    if (stats) *stats = engine.stats();
    return snapshot(engine);
}

std::vector<Circle> dots_of(const std::vector<Node>& tree) {
    std::vector<Circle> out;
    for (const Node& n : tree)
        if (n.type == "dot") out.push_back({{n.coords[0], n.coords[1]}, n.coords[2]});
    return out;
}

void expect_valid_tree(const std::vector<Node>& tree) {
    std::vector<int> children(tree.size(), 0);
    for (std::size_t k = 0; k < tree.size(); ++k) {
        const Node& n = tree[k];
        ASSERT_EQ(n.id, static_cast<int>(k));
        if (n.parent < 0) {
            EXPECT_EQ(n.depth, 0);
            EXPECT_EQ(n.type, "seed");
        } else {
            ASSERT_LT(n.parent, n.id);
            EXPECT_EQ(n.depth, tree[n.parent].depth + 1);
            ++children[n.parent];
        }
    }
    for (std::size_t k = 0; k < tree.size(); ++k) EXPECT_EQ(tree[k].children, children[k]);
}

// No two dots overlap and every dot lies inside the region (up to rounding).
void expect_dots_fit(const std::vector<Node>& tree, const Region& region) {
    const auto dots = dots_of(tree);
    const double tol = 1e-9 * std::max(region.bounds().width(), region.bounds().height());
    for (std::size_t a = 0; a < dots.size(); ++a) {
        ASSERT_TRUE(region.contains(dots[a].center)) << "dot " << a;
        ASSERT_GE(region.distance_to_boundary(dots[a].center), dots[a].radius - tol) << "dot " << a;
        for (std::size_t b = a + 1; b < dots.size(); ++b)
            ASSERT_GE(distance(dots[a].center, dots[b].center),
                      dots[a].radius + dots[b].radius - tol)
                << "dots " << a << " and " << b << " overlap";
    }
}

GrowthOptions small_options(bool reference = false) {
    GrowthOptions o;
    o.resolution = 96;
    o.reference_engine = reference;
    return o;
}

}  // namespace

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

TEST(Growth, SameInputsGiveTheSameTree) {
    const Region region = Region::from_spec("ellipse:50,30");
    EXPECT_EQ(grow(dots::pattern(), region, small_options()),
              grow(dots::pattern(), region, small_options()));
}

TEST(RegionParts, TwoSeparatePartsAndASquareWithAHole) {
    const Region two = Region::from_svg_file(ACANTHUS_SOURCE_DIR "/examples/panels/two-parts.svg");
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
        Region::from_svg_file(ACANTHUS_SOURCE_DIR "/examples/panels/two-parts.svg");
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

TEST(Growth, StopsAtMaxElements) {
    GrowthOptions o = small_options();
    o.max_elements = 40;
    acanthus::GrowthStats stats;
    const auto tree = grow(dots::pattern(), Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(tree.size(), 40u);
    EXPECT_EQ(stats.stop_reason, "max-elements");
}

TEST(Growth, StopsAtMaxIterations) {
    GrowthOptions o = small_options();
    o.max_iterations = 25;
    acanthus::GrowthStats stats;
    grow(dots::pattern(), Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(stats.iterations, 25);
    EXPECT_EQ(stats.stop_reason, "max-iterations");
}

TEST(Growth, StopsAtTimeLimit) {
    GrowthOptions o;
    o.resolution = 512;
    o.time_limit = 1e-9;
    acanthus::GrowthStats stats;
    const auto tree = grow(dots::pattern(), Region::from_spec("rect:1000,1000"), o, &stats);
    EXPECT_EQ(stats.stop_reason, "time-limit");
    EXPECT_LT(tree.size(), 10u);
}

// --- Variants of the dots pattern for the exclude list and %exhausted -------------------------

namespace variant {

int phase = 0;
int exhausted_calls = 0;

// dot --> dot that refuses the left half of the panel until phase 1.
Result shy_dot(RuleCall& call_) {
    if (acanthus::body::goal().center.x < 50 && phase == 0) return acanthus::FAILURE;
    return dots::rule_dot_dot(call_);
}

Pattern shy_pattern() {
    Pattern p = dots::pattern();
    p.rules[1].body = &shy_dot;
    return p;
}

}  // namespace variant

TEST(Growth, FailedCirclesJoinTheExcludeList) {
    variant::phase = 0;
    GrowthOptions o = small_options();
    o.seeds = {{75, 30}};
    acanthus::GrowthStats stats;
    const Pattern p = variant::shy_pattern();
    const auto tree = grow(p, Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(stats.stop_reason, "exhausted");
    EXPECT_GT(stats.exclude_points, 0);
    // Every dot lies in a circle C centred in the right half, of radius at most 30.
    for (const Circle& c : dots_of(tree)) EXPECT_GE(c.center.x - c.radius, 20.0 - 1e-9);
    EXPECT_GT(stats.rules[1].failures, 0);
    // The reference engine agrees, exclude list included.
    o.reference_engine = true;
    acanthus::GrowthStats ref;
    variant::phase = 0;
    EXPECT_EQ(grow(p, Region::from_spec("rect:100,60"), o, &ref), tree);
    EXPECT_EQ(ref.exclude_points, stats.exclude_points);
}

TEST(Growth, ExhaustedContinueClearsTheExcludeList) {
    Pattern p = variant::shy_pattern();
    p.exhausted = [] {
        ++variant::exhausted_calls;
        if (variant::phase == 0) {
            variant::phase = 1;
            return acanthus::CONTINUE;
        }
        return acanthus::STOP;
    };
    GrowthOptions o = small_options();
    o.seeds = {{75, 30}};
    acanthus::GrowthStats stats;
    variant::phase = 0;
    variant::exhausted_calls = 0;
    const auto tree = grow(p, Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(variant::exhausted_calls, 2);
    EXPECT_EQ(stats.stop_reason, "exhausted");
    bool left = false;
    for (const Circle& c : dots_of(tree)) left = left || c.center.x < 20;
    EXPECT_TRUE(left) << "after CONTINUE the left half grows";
    expect_dots_fit(tree, Region::from_spec("rect:100,60"));
}

namespace variant {

double drawn = -1;
int regions_seen = 0;

// %exhausted using the support library: random numbers and clearing the exclude list.
acanthus::Flow exhausted_with_library() {
    ++exhausted_calls;
    drawn = acanthus::body::rng.uniform(0, 1);
    if (acanthus::Environment::current() && acanthus::Environment::current()->region())
        ++regions_seen;
    if (phase != 0) return acanthus::STOP;
    phase = 1;
    acanthus::body::clear_exclude_list();
    return acanthus::CONTINUE;
}

}  // namespace variant

TEST(Growth, ExhaustedRunsWithTheEnvironmentInstalled) {
    Pattern p = variant::shy_pattern();
    p.exhausted = &variant::exhausted_with_library;
    GrowthOptions o = small_options();
    o.seeds = {{75, 30}};
    variant::phase = 0;
    variant::exhausted_calls = 0;
    variant::regions_seen = 0;
    variant::drawn = -1;
    acanthus::GrowthStats stats;
    const auto tree = grow(p, Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(variant::exhausted_calls, 2);
    EXPECT_EQ(variant::regions_seen, 2);
    EXPECT_GE(variant::drawn, 0.0);
    EXPECT_LT(variant::drawn, 1.0);
    bool left = false;
    for (const Circle& c : dots_of(tree)) left = left || c.center.x < 20;
    EXPECT_TRUE(left) << "after CONTINUE the left half grows";
    // The reference engine agrees.
    o.reference_engine = true;
    variant::phase = 0;
    EXPECT_EQ(grow(p, Region::from_spec("rect:100,60"), o), tree);
}

TEST(Growth, ExhaustedThatAlwaysContinuesStillStops) {
    Pattern p = variant::shy_pattern();
    p.exhausted = [] {
        ++variant::exhausted_calls;
        return acanthus::CONTINUE;
    };
    GrowthOptions o = small_options();
    o.seeds = {{75, 30}};
    variant::phase = 0;
    variant::exhausted_calls = 0;
    acanthus::GrowthStats stats;
    grow(p, Region::from_spec("rect:100,60"), o, &stats);
    EXPECT_EQ(stats.stop_reason, "exhausted");
    EXPECT_GT(variant::exhausted_calls, 1);
    EXPECT_LE(variant::exhausted_calls, 20);
}

// --- Rule bodies using the environment ---------------------------------------------------------

namespace scatter {

// dot --> dot: a random dot somewhere in C, kept only when it overlaps nothing.
Result random_dot(RuleCall& call_) {
    auto* c0_ = call_.make_static<dots::dot>();
    const Circle g = acanthus::body::goal();
    const double r = acanthus::body::rng.uniform(0.5, std::min(4.0, g.radius));
    const Point at = g.center.offset(acanthus::body::rng.uniform(0, 2 * M_PI),
                                     acanthus::body::rng.uniform(0, g.radius));
    c0_->p0.set(at, r);
    if (acanthus::body::intersection(c0_)) return acanthus::FAILURE;
    return acanthus::SUCCESS;
}

Pattern pattern() {
    Pattern p = dots::pattern();
    p.rules[1].body = &random_dot;
    return p;
}

}  // namespace scatter

TEST(Growth, RulesUsingIntersectionAndRandomNumbersAreDeterministic) {
    const Region region = Region::from_spec("circle:30");
    GrowthOptions o = small_options();
    o.max_iterations = 400;
    o.rng_seed = 11;
    const Pattern p = scatter::pattern();
    const auto a = grow(p, region, o);
    const auto b = grow(p, region, o);
    EXPECT_EQ(a, b);
    EXPECT_GT(a.size(), 20u);
    expect_dots_fit(a, region);
    o.reference_engine = true;
    EXPECT_EQ(grow(p, region, o), a);
    o.reference_engine = false;
    o.rng_seed = 12;
    EXPECT_NE(grow(p, region, o), a);
}

namespace broken {
Result unset_child(RuleCall& call_) {
    call_.make_static<dots::dot>();
    return acanthus::SUCCESS;
}
Result throwing(RuleCall& call_) {
    call_.make_static<dots::dot>();
    throw std::runtime_error("boom");
}
}  // namespace broken

TEST(Growth, RuleFailuresPropagate) {
    for (auto body : {&broken::unset_child, &broken::throwing}) {
        Pattern p = dots::pattern();
        p.rules[0].body = body;
        GrowthEngine engine(p, Region::from_spec("rect:50,50"), small_options());
        try {
            engine.run();
            FAIL() << "expected RuleFailure";
        } catch (const acanthus::RuleFailure& e) {
            EXPECT_EQ(e.rule(), "seed --> dot");
            EXPECT_EQ(e.line(), 18);
        }
    }
}

TEST(Growth, DebugFrameDescribesTheAskedIteration) {
    const Region region = Region::from_spec("rect:100,60");
    const Pattern p = dots::pattern();
    dots::dot_count = 0;
    GrowthEngine engine(p, region, small_options());
    int calls = 0;
    DebugFrame got;
    engine.on_debug_frame(30, [&](const DebugFrame& f) {
        ++calls;
        got = f;
    });
    long frames = 0;
    engine.on_frame(10, [&](long iteration, const std::vector<const Element*>& placed) {
        EXPECT_EQ(iteration % 10, 0);
        EXPECT_FALSE(placed.empty());
        ++frames;
    });
    engine.run();
    ASSERT_EQ(calls, 1);
    EXPECT_EQ(got.iteration, 30);
    EXPECT_EQ(frames, engine.stats().iterations / 10);
    EXPECT_EQ(got.grid.width, engine.grid().width);
    EXPECT_EQ(got.occupancy.size(), static_cast<std::size_t>(got.grid.width * got.grid.height));
    ASSERT_TRUE(got.chosen.has_value());
    EXPECT_FALSE(got.eligible.empty());
    // C is the largest eligible circle, drawn among the eligible ones (up to its refinement).
    double largest = 0;
    for (const Circle& c : got.eligible) largest = std::max(largest, c.radius);
    EXPECT_GE(got.chosen->radius, largest - 1e-9);
    ASSERT_FALSE(got.candidates.empty());
    EXPECT_EQ(got.added.size(), 1u);
    EXPECT_EQ(got.added[0]->parent, got.candidates[0]);
    EXPECT_EQ(got.added[0]->id, static_cast<int>(got.placed.size()));
    int boundary = 0, element = 0;
    for (auto o : got.occupancy) {
        boundary += o == 1;
        element += o == 2;
    }
    EXPECT_GT(boundary, 0);
    EXPECT_GT(element, 0);
}
