// DistanceField with the Manhattan metric (the paper's MAT): full transform against brute force,
// the brushfire update against a full transform after every step.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "field/distance_field.hpp"

using acanthus::DistanceMetric;
using acanthus::Random;
using acanthus::detail::DistanceField;
using acanthus::detail::ObstacleKind;

namespace {

constexpr auto kManhattan = DistanceMetric::manhattan;

std::int64_t city_block(int w, int a, int b) {
    return std::abs(a % w - b % w) + std::abs(a / w - b / w);
}

// Squared city-block distance to the nearest site of any kind and of the boundary kind.
void expect_brute_force(const DistanceField& f, const std::vector<std::uint8_t>& occ, int w,
                        const char* what) {
    const int n = static_cast<int>(occ.size());
    for (int p = 0; p < n; ++p) {
        std::int64_t all = DistanceField::infinite, boundary = DistanceField::infinite;
        for (int s = 0; s < n; ++s) {
            if (!occ[s]) continue;
            const std::int64_t d = city_block(w, p, s);
            all = std::min(all, d * d);
            if (occ[s] == 1) boundary = std::min(boundary, d * d);
        }
        ASSERT_EQ(f.squared_distance(p), all) << what << " pixel " << p % w << "," << p / w;
        ASSERT_EQ(f.boundary_squared_distance(p), boundary) << what << " pixel " << p;
        if (all == DistanceField::infinite) {
            ASSERT_EQ(f.nearest_site(p), -1);
            ASSERT_EQ(f.nearest_kind(p), ObstacleKind::none);
        } else {
            const int s = f.nearest_site(p);
            ASSERT_GE(s, 0);
            ASSERT_NE(occ[s], 0) << what << " nearest site is not a site";
            ASSERT_EQ(city_block(w, p, s) * city_block(w, p, s), all) << what << " pixel " << p;
            ASSERT_EQ(f.nearest_kind(p),
                      boundary == all ? ObstacleKind::boundary : ObstacleKind::element);
        }
    }
}

std::vector<std::uint8_t> random_scene(Random& rng, int w, int h, double density) {
    std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 0);
    for (auto& o : occ)
        if (rng.chance(density)) o = rng.chance(0.5) ? 1 : 2;
    return occ;
}

}  // namespace

TEST(ManhattanField, SingleSiteGivesCityBlockDistances) {
    DistanceField f(9, 6, true, kManhattan);
    std::vector<std::uint8_t> occ(54, 0);
    occ[2 * 9 + 3] = 2;
    f.compute(occ);
    EXPECT_EQ(f.metric(), kManhattan);
    EXPECT_EQ(f.squared_distance(5 * 9 + 8), (3 + 5) * (3 + 5));
    EXPECT_EQ(f.nearest_site(0), 2 * 9 + 3);
}

TEST(ManhattanField, FullComputeMatchesBruteForceOnRandomScenes) {
    Random rng(11);
    for (int scene = 0; scene < 40; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(1, 40));
        const int h = static_cast<int>(rng.uniform_int(1, 40));
        const auto occ = random_scene(rng, w, h, rng.uniform(0.0, 0.2));
        DistanceField f(w, h, true, kManhattan);
        f.compute(occ);
        expect_brute_force(f, occ, w, "compute");
    }
}

// After every add_sites the brushfire gives the full transform, and `changed` is exactly the
// pixels whose distance changed (element sites).
TEST(ManhattanField, BrushfireMatchesFullComputeAfterEveryStep) {
    Random rng(5);
    for (int scene = 0; scene < 12; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(8, 40));
        const int h = static_cast<int>(rng.uniform_int(8, 40));
        auto occ = random_scene(rng, w, h, rng.uniform(0.0, 0.01));
        DistanceField inc(w, h, true, kManhattan);
        inc.compute(occ);
        for (int step = 0; step < 40; ++step) {
            std::vector<int> blob;
            const int ci = static_cast<int>(rng.uniform_int(0, w - 1));
            const int cj = static_cast<int>(rng.uniform_int(0, h - 1));
            const int r = static_cast<int>(rng.uniform_int(0, 3));
            for (int dj = -r; dj <= r; ++dj)
                for (int di = -r; di <= r; ++di) {
                    const int i = ci + di * 2, j = cj + dj;
                    if (i < 0 || j < 0 || i >= w || j >= h || di * di + dj * dj > r * r) continue;
                    blob.push_back(j * w + i);
                }
            const ObstacleKind kind =
                rng.chance(0.15) ? ObstacleKind::boundary : ObstacleKind::element;
            std::vector<std::int64_t> before(occ.size());
            for (std::size_t p = 0; p < occ.size(); ++p)
                before[p] = inc.squared_distance(static_cast<int>(p));
            std::vector<int> changed;
            inc.add_sites(blob, kind, &changed);
            for (int p : blob)
                if (!occ[p]) occ[p] = static_cast<std::uint8_t>(kind);
            DistanceField full(w, h, true, kManhattan);
            full.compute(occ);
            for (int p = 0; p < w * h; ++p) {
                ASSERT_EQ(inc.squared_distance(p), full.squared_distance(p))
                    << "scene " << scene << " step " << step << " pixel " << p;
                ASSERT_EQ(inc.nearest_kind(p), full.nearest_kind(p)) << "step " << step;
            }
            if (kind == ObstacleKind::element) {
                std::vector<int> expected;
                for (std::size_t p = 0; p < occ.size(); ++p)
                    if (before[p] != inc.squared_distance(static_cast<int>(p)))
                        expected.push_back(static_cast<int>(p));
                std::sort(changed.begin(), changed.end());
                ASSERT_EQ(changed, expected) << "step " << step;
            }
        }
        expect_brute_force(inc, occ, w, "brushfire final");
    }
}
