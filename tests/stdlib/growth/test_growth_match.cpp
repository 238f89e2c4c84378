// Neighbourhood matching (section 5.2) against a brute-force oracle: every injective pairing of
// the target with the reference ring is enumerated and only those that keep counter-clockwise
// order without skipping are allowed; rotation is found by a fine scan instead of closed form.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "neighbourhood_match.hpp"

using namespace acanthus;
using namespace acanthus::growth::detail;

namespace {

std::vector<RingEntry> random_ring(Random& random, int n, int symbols, int subs) {
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(random.uniform(-M_PI, M_PI));
    std::sort(angles.begin(), angles.end());
    std::vector<RingEntry> ring;
    for (double a : angles) {
        double r = random.uniform(0.7, 1.3);
        ring.push_back({{r * std::cos(a), r * std::sin(a)},
                        static_cast<int>(random.uniform_int(0, symbols - 1)),
                        static_cast<int>(random.uniform_int(-1, subs - 1))});
    }
    return ring;
}

double pair_cost(const RingEntry& t, const RingEntry& r, double rotation, const Weights& w) {
    double c =
        w.w1 *
        std::hypot(
            t.offset.x - (std::cos(rotation) * r.offset.x - std::sin(rotation) * r.offset.y),
            t.offset.y - (std::sin(rotation) * r.offset.x + std::cos(rotation) * r.offset.y));
    if (t.symbol >= 0 && t.symbol != r.symbol) c += w.w2;
    if (t.sub >= 0 && t.sub == r.sub) c += w.w3;
    return c;
}

// Least-squares rotation by a scan and a golden-section refinement.
double scanned_rotation(const std::vector<RingEntry>& t, const std::vector<RingEntry>& r,
                        const std::vector<int>& map) {
    auto sq = [&](double th) {
        double s = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
            Vector v = r[map[i]].offset.rotated(th);
            s += std::pow(t[i].offset.x - v.x, 2) + std::pow(t[i].offset.y - v.y, 2);
        }
        return s;
    };
    double best = 0, best_v = INFINITY;
    for (int k = 0; k < 3600; ++k) {
        double th = -M_PI + 2 * M_PI * k / 3600;
        if (double v = sq(th); v < best_v) best_v = v, best = th;
    }
    double lo = best - 0.002, hi = best + 0.002;
    for (int it = 0; it < 100; ++it) {
        double m1 = lo + (hi - lo) * 0.382, m2 = lo + (hi - lo) * 0.618;
        (sq(m1) < sq(m2) ? hi : lo) = sq(m1) < sq(m2) ? m2 : m1;
    }
    return (lo + hi) / 2;
}

// The minimum error over every allowed injective pairing, enumerated by brute force.
double oracle(const std::vector<RingEntry>& t, const std::vector<RingEntry>& r, const Weights& w,
              bool rotate) {
    const int n = static_cast<int>(t.size()), m = static_cast<int>(r.size());
    if (n > m) return INFINITY;
    double best = INFINITY;
    std::vector<int> map(n);
    std::vector<bool> used(m, false);
    std::function<void(int)> place = [&](int i) {
        if (i == n) {
            // Allowed: consecutive in the ring, in the same turning order (no skip, no flip).
            for (int k = 0; k + 1 < n; ++k)
                if (map[k + 1] != (map[k] + 1) % m) return;
            double th = rotate ? scanned_rotation(t, r, map) : 0.0;
            double e = 0;
            for (int k = 0; k < n; ++k) e += pair_cost(t[k], r[map[k]], th, w);
            best = std::min(best, e);
            return;
        }
        for (int j = 0; j < m; ++j) {
            if (used[j]) continue;
            used[j] = true;
            map[i] = j;
            place(i + 1);
            used[j] = false;
        }
    };
    if (n == 0) return 0;
    place(0);
    return best;
}

class GrowthMatch : public ::testing::TestWithParam<bool> {};

TEST_P(GrowthMatch, AgreesWithBruteForce) {
    const bool rotate = GetParam();
    Random random(rotate ? 11 : 5);
    Weights w{1.0, 1.0, 100.0};
    int compared = 0;
    for (int trial = 0; trial < 300; ++trial) {
        int m = static_cast<int>(random.uniform_int(1, 7));
        int n = static_cast<int>(random.uniform_int(0, 7));
        auto ref = random_ring(random, m, 2, 3);
        auto target = random_ring(random, n, 2, 3);
        if (trial % 3 == 0) w = {random.uniform(0, 2), random.uniform(0, 2), random.uniform(0, 5)};
        RingMatch got = match_ring(target, ref, w, rotate);
        double want = oracle(target, ref, w, rotate);
        if (!std::isfinite(want)) {
            EXPECT_FALSE(got.found()) << "trial " << trial;
            continue;
        }
        ASSERT_TRUE(got.found()) << "trial " << trial;
        EXPECT_NEAR(got.error, want, 1e-6 * (1 + want)) << "trial " << trial;
        EXPECT_NEAR(alignment_error(target, ref, got.shift, got.rotation, w), got.error, 1e-9);
        ++compared;
    }
    EXPECT_GT(compared, 100);
}

INSTANTIATE_TEST_SUITE_P(Modes, GrowthMatch, ::testing::Values(false, true));

TEST(GrowthMatchRules, NoSkippingAndNoFlipping) {
    std::vector<RingEntry> ref;
    for (int k = 0; k < 4; ++k) ref.push_back({Vector{1, 0}.rotated(k * M_PI / 2), 0, -1});
    Weights w;
    // Entries 0 and 2 of the ring exist exactly, but pairing them would skip entry 1.
    auto skip = match_ring({ref[0], ref[2]}, ref, w, false);
    EXPECT_GT(skip.error, 1.0);
    // Clockwise order would be a flip: 0, 3 listed as target in that order fits only 3, 0.
    auto consecutive = match_ring({ref[3], ref[0]}, ref, w, false);
    EXPECT_NEAR(consecutive.error, 0, 1e-12);
    EXPECT_EQ(consecutive.shift, 3);
}

TEST(GrowthMatchRules, SymbolAndSubIdTerms) {
    std::vector<RingEntry> ref{{{1, 0}, 0, 4}, {{0, 1}, 1, 5}, {{-1, 0}, 0, 6}};
    Weights w{1, 1, 100};
    EXPECT_NEAR(alignment_error({{{1, 0}, 1, -1}}, ref, 0, 0, w), 1.0, 1e-12);   // id differs
    EXPECT_NEAR(alignment_error({{{1, 0}, 0, 4}}, ref, 0, 0, w), 100.0, 1e-12);  // same sub
    EXPECT_NEAR(alignment_error({{{1, 0}, -1, 7}}, ref, 0, 0, w), 0.0, 1e-12);   // id-less seed
    EXPECT_NEAR(alignment_error({{{0, 1}, 1, 5}}, ref, 0, 0, w), 1 + std::sqrt(2.0), 1e-12);
}

TEST(GrowthMatchRules, RotationRecoversATurnedRing) {
    Random random(3);
    auto ref = random_ring(random, 6, 1, 0);
    std::vector<RingEntry> target;
    for (int i = 0; i < 4; ++i) {
        RingEntry e = ref[(2 + i) % 6];
        e.offset = e.offset.rotated(0.4);
        target.push_back(e);
    }
    auto m = match_ring(target, ref, Weights{}, true);
    EXPECT_EQ(m.shift, 2);
    EXPECT_NEAR(m.rotation, 0.4, 1e-9);
    EXPECT_NEAR(m.error, 0, 1e-9);
    EXPECT_GT(match_ring(target, ref, Weights{}, false).error, 0.1);
}

TEST(GrowthMatchRules, TargetStartsAfterTheWidestGap) {
    auto deg = [](double d) { return Vector{std::cos(d * M_PI / 180), std::sin(d * M_PI / 180)}; };
    EXPECT_EQ(ccw_from_widest_gap({deg(150), deg(-150), deg(10)}), (std::vector<int>{2, 0, 1}));
    EXPECT_EQ(ccw_from_widest_gap({deg(-100), deg(100), deg(170), deg(-170)}),
              (std::vector<int>{1, 2, 3, 0}));
}

}  // namespace

TEST(GrowthTwoRing, OuterTermCountsSymbolMismatchesAndMisses) {
    Weights w{1.0, 2.0, 100.0};
    std::vector<OuterEntry> ref{{{2, 0}, 0}, {{0, 2}, 1}, {{-2, 0}, 0}};
    // Paired by nearest offset: a match, a symbol mismatch, an unknown symbol, a miss.
    std::vector<OuterEntry> target{{{2.1, 0}, 0}, {{0, 1.9}, 0}, {{-2, 0.1}, -1}, {{0, -2}, 0}};
    EXPECT_DOUBLE_EQ(outer_ring_error(target, ref, 0.0, 0.5, w), 2 * 2.0);
    // Turned a quarter, the reference's (0, 2) lands on (-2, 0) and (2, 0) on (0, 2).
    EXPECT_DOUBLE_EQ(outer_ring_error({{{0, 2}, 0}, {{-2, 0}, 1}}, ref, M_PI / 2, 0.5, w), 0.0);
    EXPECT_DOUBLE_EQ(outer_ring_error({}, ref, 0.0, 0.5, w), 0.0);
    EXPECT_DOUBLE_EQ(outer_ring_error(target, {}, 0.0, 0.5, w), 4 * 2.0);
}

TEST(GrowthTwoRing, PruningKeepsTheExhaustiveMinimum) {
    // Every alignment scored in full (1-ring error at its rotation plus the 2-ring term) against
    // the pruned search.
    Random random(23);
    Weights w{1.0, 1.0, 100.0};
    int compared = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const bool rotate = trial % 2 == 1;
        int m = static_cast<int>(random.uniform_int(1, 7));
        int n = static_cast<int>(random.uniform_int(0, m));
        auto ref = random_ring(random, m, 2, 3);
        auto target = random_ring(random, n, 2, 3);
        std::vector<OuterEntry> ref_outer, target_outer;
        for (const RingEntry& e : random_ring(random, 10, 2, 1))
            ref_outer.push_back({e.offset * 2, e.symbol});
        for (const RingEntry& e :
             random_ring(random, static_cast<int>(random.uniform_int(0, 8)), 2, 1))
            target_outer.push_back({e.offset * 2, e.symbol});
        double want = INFINITY;
        for (int k = 0; k < (target.empty() ? 1 : m); ++k) {
            double turn = rotate && !target.empty() ? best_fit_rotation(target, ref, k) : 0.0;
            want = std::min(want, alignment_error(target, ref, k, turn, w) +
                                      outer_ring_error(target_outer, ref_outer, turn, 0.6, w));
        }
        RingMatch got =
            match_two_ring(target, ref, target_outer, ref_outer, w, rotate, 0.0, 0.6, INFINITY);
        ASSERT_TRUE(got.found()) << "trial " << trial;
        EXPECT_NEAR(got.error, want, 1e-9 * (1 + want)) << "trial " << trial;
        // A bound above the minimum changes nothing.
        EXPECT_NEAR(
            match_two_ring(target, ref, target_outer, ref_outer, w, rotate, 0.0, 0.6, want + 1)
                .error,
            want, 1e-9 * (1 + want));
        ++compared;
    }
    EXPECT_EQ(compared, 300);
}
