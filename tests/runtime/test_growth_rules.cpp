// GrowthEngine with hand-written patterns: stop conditions, the exclude list, %exhausted,
// rules using the environment and random numbers, rule failures, debug frames.
#include <gtest/gtest.h>

#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fixtures/growth_tree.hpp"

using namespace acanthus;

using namespace acanthus::test;

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

TEST(Growth, IterationCallbackComesEveryKthIterationBesideTheFrames) {
    const Region region = Region::from_spec("rect:100,60");
    const Pattern p = dots::pattern();
    dots::dot_count = 0;
    GrowthEngine engine(p, region, small_options());
    std::vector<long> frames, ticks;
    std::vector<std::size_t> frame_sizes, tick_sizes;
    engine.on_frame(6, [&](long iteration, const std::vector<const Element*>& placed) {
        frames.push_back(iteration);
        frame_sizes.push_back(placed.size());
    });
    engine.on_iteration(4, [&](long iteration) {
        EXPECT_EQ(iteration % 4, 0);
        ticks.push_back(iteration);
        tick_sizes.push_back(engine.elements().size());
    });
    engine.run();
    ASSERT_GT(engine.stats().iterations, 12);
    EXPECT_EQ(static_cast<long>(ticks.size()), engine.stats().iterations / 4);
    EXPECT_EQ(static_cast<long>(frames.size()), engine.stats().iterations / 6);
    // At an iteration both see, the elements are the same.
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const auto at = std::find(ticks.begin(), ticks.end(), frames[i]);
        if (at == ticks.end()) continue;
        EXPECT_EQ(frame_sizes[i], tick_sizes[static_cast<std::size_t>(at - ticks.begin())]);
    }
    EXPECT_LT(tick_sizes.front(), tick_sizes.back());  // the elements as they are then
}

TEST(Growth, DebugFrameDrawsOneCirclePerEmptyRegionAndTheExcludedOnes) {
    // The shy pattern fails on the left half: late frames have circles on the exclude list.
    variant::phase = 0;
    const Region region = Region::from_spec("rect:100,60");
    GrowthOptions o = small_options();
    o.seeds = {{75, 30}};
    acanthus::GrowthStats stats;
    const Pattern p = variant::shy_pattern();
    grow(p, region, o, &stats);
    ASSERT_GT(stats.iterations, 20);
    variant::phase = 0;
    GrowthEngine engine(p, region, o);
    DebugFrame got;
    engine.on_debug_frame(stats.iterations - 5, [&](const DebugFrame& f) { got = f; });
    engine.run();
    EXPECT_FALSE(got.excluded.empty());
    EXPECT_FALSE(got.eligible.empty());
    for (const Circle& c : got.excluded) EXPECT_LT(c.center.x - c.radius, 50.0);
    std::vector<Circle> all = got.eligible;
    all.insert(all.end(), got.excluded.begin(), got.excluded.end());
    for (std::size_t i = 0; i < all.size(); ++i)
        for (std::size_t j = i + 1; j < all.size(); ++j)
            EXPECT_GE(distance(all[i].center, all[j].center), all[i].radius + all[j].radius)
                << "circles " << i << " and " << j << " overlap";
}
