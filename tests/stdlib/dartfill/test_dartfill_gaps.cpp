// The fill-gap machinery: shape rasterization, the incrementally updated gap field, and the
// candidate sampler (Q of Sakurai & Miyata section 4.3) against brute-force references.
#include <gtest/gtest.h>

#include <acanthus/stdlib/dartfill.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "candidate_sampler.hpp"
#include "container.hpp"
#include "dartfill_oracle.hpp"
#include "gap_field.hpp"
#include "layout.hpp"
#include "shape_list.hpp"

using namespace acanthus;
using namespace acanthus::dartfill;

namespace {

ShapeSet shapes() {
    ShapeSet set;
    set.add_points("c", {{0, 0}, {12, 0}, {12, 3}, {3, 3}, {3, 9}, {12, 9}, {12, 12}, {0, 12}});
    set.add_path("bean",
                 "M 0 7 C 0 0 8 -2 12 2 C 14 4 16 4 18 2 C 22 -1 27 4 25 10 C 23 16 4 17 0 7 Z");
    return set;
}

RingContainer square(double size) {
    return RingContainer({{{0, 0}, {size, 0}, {size, size}, {0, size}}}, false);
}

// Shapes at poses that leave gaps of many sizes, placed without overlap.
std::vector<PlacedShape> scattered(const ShapeSet& set) {
    const auto& list = set.list().shapes;
    std::vector<PlacedShape> out;
    Layout layout(1e-6);
    Random random(4);
    for (int k = 0; out.size() < 24 && k < 2000; ++k) {
        int s = k % 2;
        PlacedShape p(list[s], s,
                      {{random.uniform(15, 185), random.uniform(15, 185)},
                       random.uniform(0, 2 * M_PI),
                       random.uniform(0.8, 1.6)});
        if (layout.collides(p)) continue;
        layout.add(p);
        out.push_back(p);
    }
    return out;
}

}  // namespace

TEST(DartfillGaps, ShapePixelsAreThePixelCentresInsideTheOutline) {
    ShapeSet set = shapes();
    RingContainer panel = square(100);
    GridFrame grid = make_grid(panel.bounds(), 120);
    Random random(2);
    for (int k = 0; k < 40; ++k) {
        int s = k % 2;
        PlacedShape p(set.list().shapes[s], s,
                      {{random.uniform(20, 80), random.uniform(20, 80)},
                       random.uniform(0, 2 * M_PI),
                       random.uniform(0.3, 2.0)});
        std::vector<int> got;
        shape_pixels(grid, p, got);
        std::set<int> unique(got.begin(), got.end());
        std::set<int> expected;
        for (int j = 0; j < grid.height; ++j)
            for (int i = 0; i < grid.width; ++i)
                if (dartfill_oracle::in_ring(p.outline(), grid.center_of(i, j)))
                    expected.insert(j * grid.width + i);
        ASSERT_FALSE(expected.empty());
        // Every centre inside is found; the only extra is the one pixel under an interior point.
        for (int e : expected) EXPECT_TRUE(unique.count(e)) << "shape " << k << " misses " << e;
        std::size_t extra = 0;
        for (int u : unique) extra += expected.count(u) == 0;
        EXPECT_LE(extra, 1u) << "shape " << k;
    }
}

TEST(DartfillGaps, IncrementalFieldEqualsARecomputedOne) {
    ShapeSet set = shapes();
    RingContainer panel = square(200);
    std::vector<PlacedShape> placed = scattered(set);
    ASSERT_GE(placed.size(), 20u);

    Layout first(1e-6), all(1e-6);
    for (std::size_t k = 0; k < placed.size(); ++k) {
        all.add(placed[k]);
        if (k < 4) first.add(placed[k]);
    }
    GapField grown(panel, first, 160);
    CandidateSampler sampler(grown);
    std::vector<int> changed;
    for (std::size_t k = 4; k < placed.size(); ++k) {
        changed.clear();
        grown.add(placed[k], &changed);
        sampler.update(changed);
    }
    GapField fresh(panel, all, 160);
    CandidateSampler fresh_sampler(fresh);
    ASSERT_EQ(grown.size(), fresh.size());
    for (int i = 0; i < fresh.size(); ++i) {
        ASSERT_EQ(grown.squared_distance(i), fresh.squared_distance(i)) << "pixel " << i;
        ASSERT_EQ(grown.free(i), fresh.free(i)) << "pixel " << i;
        ASSERT_EQ(sampler.filed_group(i), fresh_sampler.filed_group(i)) << "pixel " << i;
    }
    EXPECT_EQ(sampler.free_pixels(), fresh_sampler.free_pixels());
    EXPECT_EQ(sampler.max_squared_distance(), fresh.max_squared_distance());
}

TEST(DartfillGaps, GroupsCoverEverySquaredDistanceOnce) {
    for (std::int64_t d2 = 1; d2 < 300000; ++d2) {
        int g = CandidateSampler::group_of(d2);
        ASSERT_LT(d2, CandidateSampler::group_end(g)) << d2;
        if (g > 1) {
            ASSERT_GE(d2, CandidateSampler::group_end(g - 1)) << d2;
        }
        // Within one group the squared distance varies by less than 9/8 (alpha by 2.6 at n=16).
        std::int64_t first = g > 1 ? CandidateSampler::group_end(g - 1) : 1;
        ASSERT_LE(8 * (CandidateSampler::group_end(g) - 1), 9 * first) << d2;
    }
}

// Q is exact: each pixel joins with probability d^n. Over many draws, the number of members of
// each distance class must match the sum of d^n over its pixels (a brute-force reference).
TEST(DartfillGaps, SamplerDrawsEachPixelWithProbabilityDToTheN) {
    ShapeSet set = shapes();
    RingContainer panel = square(200);
    Layout layout(1e-6);
    for (const PlacedShape& p : scattered(set)) layout.add(p);
    GapField gaps(panel, layout, 200);
    CandidateSampler sampler(gaps);
    const std::int64_t max = gaps.max_squared_distance();
    for (double exponent : {16.0, 4.0, 2.5}) {
        // Classes by normalized distance: [0.5, 0.6), ..., [0.9, 1.0].
        double expected[5] = {0, 0, 0, 0, 0};
        double seen[5] = {0, 0, 0, 0, 0};
        auto bin = [&](std::int64_t d2) {
            double d = std::sqrt(static_cast<double>(d2) / static_cast<double>(max));
            return d < 0.5 ? -1 : std::min(4, static_cast<int>((d - 0.5) * 10));
        };
        for (int i = 0; i < gaps.size(); ++i) {
            if (!gaps.free(i)) continue;
            std::int64_t d2 = gaps.squared_distance(i);
            int b = bin(d2);
            if (b >= 0)
                expected[b] +=
                    std::pow(static_cast<double>(d2) / static_cast<double>(max), exponent / 2);
        }
        const int draws = 400;
        Random random(17);
        std::vector<int> q;
        for (int k = 0; k < draws; ++k) {
            q.clear();
            sampler.draw_q(exponent, random, q);
            std::set<int> unique(q.begin(), q.end());
            ASSERT_EQ(unique.size(), q.size()) << "a pixel joined Q twice";
            for (int p : q) {
                ASSERT_TRUE(gaps.free(p));
                int b = bin(gaps.squared_distance(p));
                if (b >= 0) seen[b] += 1;
            }
        }
        for (int b = 0; b < 5; ++b) {
            double mean = expected[b] * draws;
            if (mean < 50) continue;
            // Counts are sums of independent Bernoullis: within 5 standard deviations.
            EXPECT_NEAR(seen[b], mean, 5 * std::sqrt(mean) + 1)
                << "n = " << exponent << ", class " << b;
        }
    }
}

TEST(DartfillGaps, PIsDrawnFromQWithoutRepeats) {
    ShapeSet set = shapes();
    RingContainer panel = square(200);
    Layout layout(1e-6);
    for (const PlacedShape& p : scattered(set)) layout.add(p);
    GapField gaps(panel, layout, 200);
    CandidateSampler sampler(gaps);
    Random random(3);
    // n = 0 puts every free pixel in Q: P is then exactly |P| distinct free pixels.
    std::vector<int> p = sampler.draw(0, 100, random);
    ASSERT_EQ(p.size(), 100u);
    EXPECT_EQ(std::set<int>(p.begin(), p.end()).size(), 100u);
    for (int i : p) EXPECT_TRUE(gaps.free(i));
    // A huge exponent leaves only the farthest pixels: P is all of Q, at the maximum.
    std::vector<int> far = sampler.draw(4000, 100, random);
    ASSERT_FALSE(far.empty());
    EXPECT_LT(far.size(), 100u);
    for (int i : far) EXPECT_EQ(gaps.squared_distance(i), gaps.max_squared_distance());
}
