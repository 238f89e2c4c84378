// DistanceField: exact EDT against brute force; incremental add_sites against full compute.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "field/distance_field.hpp"
#include "field/witness.hpp"

using acanthus::Random;
using acanthus::detail::DistanceField;
using acanthus::detail::ObstacleKind;

namespace {

std::int64_t sq(std::int64_t v) { return v * v; }

// Squared distance from every pixel to its nearest site of any kind, and to the nearest boundary.
struct BruteForce {
    std::vector<std::int64_t> all, boundary;
};

BruteForce brute_force(int w, int h, const std::vector<std::uint8_t>& occ) {
    BruteForce out;
    out.all.assign(occ.size(), DistanceField::infinite);
    out.boundary.assign(occ.size(), DistanceField::infinite);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            for (int sj = 0; sj < h; ++sj)
                for (int si = 0; si < w; ++si) {
                    const std::uint8_t k = occ[sj * w + si];
                    if (!k) continue;
                    const std::int64_t d = sq(i - si) + sq(j - sj);
                    out.all[j * w + i] = std::min(out.all[j * w + i], d);
                    if (k == 1) out.boundary[j * w + i] = std::min(out.boundary[j * w + i], d);
                }
    return out;
}

std::int64_t site_distance(const DistanceField& f, int index) {
    const int s = f.nearest_site(index);
    const int w = f.width();
    return sq(index % w - s % w) + sq(index / w - s / w);
}

ObstacleKind expected_kind(const BruteForce& b, int index) {
    if (b.all[index] == DistanceField::infinite) return ObstacleKind::none;
    return b.boundary[index] == b.all[index] ? ObstacleKind::boundary : ObstacleKind::element;
}

void expect_matches(const DistanceField& f, const std::vector<std::uint8_t>& occ, int w, int h,
                    const char* what) {
    const BruteForce b = brute_force(w, h, occ);
    for (int p = 0; p < w * h; ++p) {
        ASSERT_EQ(f.squared_distance(p), b.all[p]) << what << " pixel " << p % w << "," << p / w;
        ASSERT_EQ(f.nearest_kind(p), expected_kind(b, p)) << what << " pixel " << p;
        if (b.all[p] == DistanceField::infinite) {
            ASSERT_EQ(f.nearest_site(p), -1);
        } else {
            ASSERT_GE(f.nearest_site(p), 0);
            ASSERT_NE(occ[f.nearest_site(p)], 0) << what << " nearest site is not a site";
            ASSERT_EQ(site_distance(f, p), b.all[p]) << what << " nearest site at wrong distance";
        }
    }
}

std::vector<std::uint8_t> random_scene(Random& rng, int w, int h, double density) {
    std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 0);
    for (auto& o : occ)
        if (rng.chance(density)) o = rng.chance(0.5) ? 1 : 2;
    return occ;
}

void compare_fields(const DistanceField& a, const DistanceField& b, const char* what, int step) {
    for (int p = 0; p < a.width() * a.height(); ++p) {
        ASSERT_EQ(a.squared_distance(p), b.squared_distance(p))
            << what << " step " << step << " pixel " << p;
        ASSERT_EQ(a.nearest_kind(p), b.nearest_kind(p))
            << what << " step " << step << " pixel " << p;
        ASSERT_EQ(a.occupancy(p), b.occupancy(p));
        if (a.nearest_site(p) >= 0) {
            ASSERT_EQ(site_distance(a, p), a.squared_distance(p)) << what << " step " << step;
        }
    }
}

// A grid with a few sites, kept in a list for brute force.
struct SparseSites {
    int w, h;
    std::vector<std::uint8_t> occ;
    std::vector<std::pair<int, std::uint8_t>> sites;
    SparseSites(int width, int height)
        : w(width), h(height), occ(static_cast<std::size_t>(width) * height, 0) {}
    void add(int p, std::uint8_t kind) {
        if (occ[p]) return;
        occ[p] = kind;
        sites.emplace_back(p, kind);
    }
    // Squared distances from pixel p to the nearest site and to the nearest boundary site.
    std::pair<std::int64_t, std::int64_t> nearest(int p) const {
        std::int64_t all = DistanceField::infinite, boundary = DistanceField::infinite;
        for (const auto& [q, kind] : sites) {
            const std::int64_t d = sq(p % w - q % w) + sq(p / w - q / w);
            all = std::min(all, d);
            if (kind == 1) boundary = std::min(boundary, d);
        }
        return {all, boundary};
    }
};

}  // namespace

TEST(DistanceField, EmptyGridIsInfiniteEverywhere) {
    DistanceField f(7, 5);
    f.compute(std::vector<std::uint8_t>(35, 0));
    for (int p = 0; p < 35; ++p) {
        EXPECT_EQ(f.squared_distance(p), DistanceField::infinite);
        EXPECT_EQ(f.nearest_site(p), -1);
        EXPECT_EQ(f.nearest_kind(p), ObstacleKind::none);
    }
}

TEST(DistanceField, SingleSiteGivesEuclideanDistances) {
    DistanceField f(9, 6);
    std::vector<std::uint8_t> occ(54, 0);
    occ[2 * 9 + 3] = 2;
    f.compute(occ);
    EXPECT_EQ(f.squared_distance(2 * 9 + 3), 0);
    EXPECT_EQ(f.squared_distance(5 * 9 + 8), 3 * 3 + 5 * 5);
    EXPECT_DOUBLE_EQ(f.distance(8, 5), std::sqrt(34.0));
    EXPECT_EQ(f.nearest_site(0), 2 * 9 + 3);
    EXPECT_EQ(f.nearest_kind(0), ObstacleKind::element);
}

TEST(DistanceField, BoundaryWinsTies) {
    DistanceField f(5, 1);
    f.compute({1, 0, 0, 0, 2});
    EXPECT_EQ(f.nearest_kind(2), ObstacleKind::boundary);  // both at distance 2
    EXPECT_EQ(f.nearest_kind(3), ObstacleKind::element);
    EXPECT_EQ(f.nearest_kind(1), ObstacleKind::boundary);
}

TEST(DistanceField, FullComputeMatchesBruteForceOnRandomScenes) {
    Random rng(42);
    for (int scene = 0; scene < 40; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(1, 40));
        const int h = static_cast<int>(rng.uniform_int(1, 40));
        const double density = rng.uniform(0.0, 0.2);
        const auto occ = random_scene(rng, w, h, density);
        DistanceField f(w, h);
        f.compute(occ);
        expect_matches(f, occ, w, h, "compute");
    }
}

// Without a feature transform a few element sites (a seed and its images under a group) are
// measured one by one, each only over the runs of pixels it can come nearer to.
TEST(DistanceField, FewElementSitesWithoutSitesMatchBruteForce) {
    Random rng(7);
    for (int scene = 0; scene < 30; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(1, 300));
        const int h = static_cast<int>(rng.uniform_int(1, 120));
        std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 0);
        // A boundary frame (not always: then the sites alone decide) and up to 16 sites.
        if (scene % 3 != 0)
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i)
                    if (i == 0 || j == 0 || i == w - 1 || j == h - 1) occ[j * w + i] = 1;
        const int sites = static_cast<int>(rng.uniform_int(1, 16));
        for (int k = 0; k < sites; ++k)
            occ[rng.uniform_int(0, h - 1) * w + rng.uniform_int(0, w - 1)] = 2;
        std::vector<int> at;
        for (int p = 0; p < w * h; ++p)
            if (occ[p]) at.push_back(p);
        DistanceField f(w, h, false);
        f.compute(occ);
        for (int p = 0; p < w * h; ++p) {
            std::int64_t best = DistanceField::infinite;
            for (int q : at) best = std::min(best, sq(p % w - q % w) + sq(p / w - q / w));
            ASSERT_EQ(f.squared_distance(p), best) << "scene " << scene << " pixel " << p;
        }
    }
}

// After every add_sites, the incremental field equals a full computation and brute force.
// Wide blobs go through their row envelopes, or (no pieces allowed) through a window's EDT.
class IncrementalField : public ::testing::TestWithParam<std::size_t> {};

TEST_P(IncrementalField, MatchesFullComputeAfterEveryStep) {
    Random rng(7);
    for (int scene = 0; scene < 12; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(8, 48));
        const int h = static_cast<int>(rng.uniform_int(8, 48));
        auto occ = random_scene(rng, w, h, rng.uniform(0.0, 0.01));
        // A boundary frame like the render buffer's, sometimes.
        if (scene % 2 == 0)
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i)
                    if (i == 0 || j == 0 || i == w - 1 || j == h - 1) occ[j * w + i] = 1;
        DistanceField inc(w, h);
        inc.set_direct_pieces(GetParam());
        inc.compute(occ);
        for (int step = 0; step < 60; ++step) {
            // A blob of new sites (a disc or a scatter), as a placed element would add.
            std::vector<int> blob;
            const int ci = static_cast<int>(rng.uniform_int(0, w - 1));
            const int cj = static_cast<int>(rng.uniform_int(0, h - 1));
            const int r = static_cast<int>(rng.uniform_int(0, 3));
            const bool scatter = rng.chance(0.3);
            for (int dj = -r; dj <= r; ++dj)
                for (int di = -r; di <= r; ++di) {
                    const int i = ci + di * (scatter ? 3 : 1), j = cj + dj * (scatter ? 2 : 1);
                    if (i < 0 || j < 0 || i >= w || j >= h || di * di + dj * dj > r * r) continue;
                    blob.push_back(j * w + i);
                }
            // Sometimes a long slanted stroke across more columns than are measured directly.
            if (rng.chance(0.25)) {
                const int len = static_cast<int>(rng.uniform_int(20, 60));
                const double slope = rng.uniform(-0.7, 0.7);
                for (int k = 0; k < len; ++k) {
                    const int i = (ci + k) % w, j = static_cast<int>(cj + slope * k + 4 * h) % h;
                    blob.push_back(j * w + i);
                }
            }
            const ObstacleKind kind =
                rng.chance(0.15) ? ObstacleKind::boundary : ObstacleKind::element;
            const std::vector<std::int64_t> before = [&] {
                std::vector<std::int64_t> v(occ.size());
                for (std::size_t p = 0; p < occ.size(); ++p)
                    v[p] = inc.squared_distance(static_cast<int>(p));
                return v;
            }();
            std::vector<int> changed;
            inc.add_sites(blob, kind, &changed);
            for (int p : blob)
                if (!occ[p]) occ[p] = static_cast<std::uint8_t>(kind);

            DistanceField full(w, h);
            full.compute(occ);
            compare_fields(inc, full, "incremental", step);
            // `changed` is exactly the set of pixels whose distance changed.
            std::vector<int> expected;
            for (std::size_t p = 0; p < occ.size(); ++p)
                if (before[p] != inc.squared_distance(static_cast<int>(p)))
                    expected.push_back(static_cast<int>(p));
            std::sort(changed.begin(), changed.end());
            changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
            // Element sites report exactly the changed pixels; boundary sites may also report
            // pixels whose nearest kind changed at an unchanged distance.
            if (kind == ObstacleKind::element) {
                ASSERT_EQ(changed, expected) << "step " << step;
            } else {
                ASSERT_TRUE(std::includes(changed.begin(), changed.end(), expected.begin(),
                                          expected.end()));
            }
        }
        expect_matches(inc, occ, w, h, "incremental final");
    }
}

INSTANTIATE_TEST_SUITE_P(Blobs, IncrementalField,
                         ::testing::Values(std::size_t{1} << 20, std::size_t{0}),
                         [](const auto& info) {
                             return info.param ? std::string("Envelopes") : std::string("Window");
                         });

// Dense point scatters are where propagating nearest sites through 8-neighbours classically
// goes wrong; the wavefront with exact window distances must still be exact.
TEST(DistanceField, IncrementalSingleSitesOnLargerGrid) {
    Random rng(2024);
    const int w = 96, h = 80;
    std::vector<std::uint8_t> occ(w * h, 0);
    DistanceField inc(w, h);
    inc.compute(occ);
    for (int step = 0; step < 400; ++step) {
        const int p = static_cast<int>(rng.uniform_int(0, w * h - 1));
        inc.add_sites({p}, ObstacleKind::element, nullptr);
        occ[p] = occ[p] ? occ[p] : 2;
        if (step % 20 == 19 || step < 5) {
            DistanceField full(w, h);
            full.compute(occ);
            compare_fields(inc, full, "single sites", step);
        }
    }
}

TEST(DistanceField, AddSitesIgnoresOccupiedAndOutOfRangePixels) {
    DistanceField f(4, 4);
    std::vector<std::uint8_t> occ(16, 0);
    occ[5] = 1;
    f.compute(occ);
    std::vector<int> changed;
    f.add_sites({5, -1, 16, 5}, ObstacleKind::element, &changed);
    EXPECT_TRUE(changed.empty());
    EXPECT_EQ(f.occupancy(5), ObstacleKind::boundary);
}

// Many small scenes of single sites: the Voronoi cell of a new site can hold pixels that are not
// 8-connected to it through improved pixels (seed 1 hits one in scene 366), which a plain
// brushfire misses.
TEST(DistanceField, IncrementalFindsDisconnectedVoronoiPixels) {
    Random rng(1);
    for (int scene = 0; scene < 400; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(10, 40));
        const int h = static_cast<int>(rng.uniform_int(10, 40));
        std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 0);
        DistanceField inc(w, h);
        inc.compute(occ);
        for (int step = 0; step < 30; ++step) {
            const int p = static_cast<int>(rng.uniform_int(0, w * h - 1));
            inc.add_sites({p}, ObstacleKind::element, nullptr);
            if (!occ[p]) occ[p] = 2;
            DistanceField full(w, h);
            full.compute(occ);
            for (int q = 0; q < w * h; ++q)
                ASSERT_EQ(inc.squared_distance(q), full.squared_distance(q))
                    << "scene " << scene << " step " << step << " pixel " << q;
        }
    }
}

// The lazy far field: values are upper bounds everywhere, exact in trusted tiles and their
// one-pixel rings, and exact everywhere once every block is tightened to 0; in both metrics.
class LazyField : public ::testing::TestWithParam<acanthus::DistanceMetric> {};

TEST_P(LazyField, IsExactWhereTrustedAndAfterSettling) {
    Random rng(77);
    const int w = 330, h = 230;  // blocks of 64 pixels, the last ones partial
    std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 0);
    for (int i = 0; i < w; ++i) occ[i] = occ[(h - 1) * w + i] = 1;
    for (int j = 0; j < h; ++j) occ[j * w] = occ[j * w + w - 1] = 1;
    DistanceField lazy(w, h, /*with_sites=*/false, GetParam());
    lazy.set_lazy(true);
    ASSERT_TRUE(lazy.lazy());
    lazy.compute(occ);
    auto& far = lazy.far_blocks();
    long untrusted_pixels = 0;
    for (int step = 0; step < 120; ++step) {
        // A dot of radius 0..3 pixels, as the growth engine places them.
        const int ci = static_cast<int>(rng.uniform_int(2, w - 3));
        const int cj = static_cast<int>(rng.uniform_int(2, h - 3));
        const int r = static_cast<int>(rng.uniform_int(0, 3));
        std::vector<int> dot;
        for (int j = std::max(1, cj - r); j <= std::min(h - 2, cj + r); ++j)
            for (int i = std::max(1, ci - r); i <= std::min(w - 2, ci + r); ++i)
                if (sq(i - ci) + sq(j - cj) <= sq(r)) dot.push_back(j * w + i);
        lazy.add_sites(dot, ObstacleKind::element, nullptr);
        for (int p : dot) occ[p] = occ[p] ? occ[p] : 2;
        if (step % 7 == 3) {
            const int p = static_cast<int>(rng.uniform_int(0, w * h - 1));
            lazy.trust_tile(far.tile_of(p), nullptr);
            EXPECT_TRUE(far.tile_trusted(far.tile_of(p)));
        }
        if (step % 11 == 5) {
            // Tightening a block to a threshold leaves it trusted or with a smaller reach.
            const int b = static_cast<int>(rng.uniform_int(0, far.count() - 1));
            const std::int64_t threshold = rng.uniform_int(1, 2000);
            lazy.tighten(b, threshold, nullptr);
            if (!far.trusted(b)) {
                EXPECT_LT(far.reach(b), threshold);
            }
        }
        DistanceField full(w, h, /*with_sites=*/false, GetParam());
        full.compute(occ);
        for (int p = 0; p < w * h; ++p) {
            ASSERT_GE(lazy.squared_distance(p), full.squared_distance(p)) << "step " << step;
            // A tile's bound holds every value it will have once measured (a waiting tile's
            // bound may already be below values it has not measured).
            ASSERT_GE(far.tile_bound(far.tile_of(p)), full.squared_distance(p))
                << "step " << step << " pixel " << p;
            if (!far.tile_trusted(far.tile_of(p))) {
                ++untrusted_pixels;
                continue;
            }
            const int i = p % w, j = p / w;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= w || b >= h) continue;
                    ASSERT_EQ(lazy.squared_distance(b * w + a), full.squared_distance(b * w + a))
                        << "step " << step << " trusted pixel " << i << "," << j;
                }
        }
    }
    EXPECT_GT(untrusted_pixels, 0) << "the far field was never left pending";
    std::vector<acanthus::detail::TileChange> changed;
    for (int b = 0; b < far.count(); ++b)
        if (!far.trusted(b)) lazy.tighten(b, 0, &changed);
    DistanceField full(w, h, /*with_sites=*/false, GetParam());
    full.compute(occ);
    for (int p = 0; p < w * h; ++p) {
        ASSERT_EQ(lazy.squared_distance(p), full.squared_distance(p)) << "pixel " << p;
        ASSERT_EQ(lazy.nearest_kind(p), full.nearest_kind(p)) << "pixel " << p;
    }
}

INSTANTIATE_TEST_SUITE_P(Metrics, LazyField,
                         ::testing::Values(acanthus::DistanceMetric::euclidean,
                                           acanthus::DistanceMetric::manhattan),
                         [](const auto& info) {
                             return info.param == acanthus::DistanceMetric::euclidean ? "Euclidean"
                                                                                      : "Manhattan";
                         });

// The witness test of the lazy field's deferral: when it says a site outranks a box of new
// sites over a rectangle, no pixel of the rectangle is nearer to a point of the box, in either
// metric; and it says so often enough to matter.
TEST(Witness, OutranksOnlyWhenEveryPixelIsAtLeastAsNear) {
    using acanthus::detail::outranks;
    using acanthus::detail::PixelBox;
    for (const auto metric :
         {acanthus::DistanceMetric::euclidean, acanthus::DistanceMetric::manhattan}) {
        const auto dist = [&](long dx, long dy) {
            return metric == acanthus::DistanceMetric::manhattan ? std::abs(dx) + std::abs(dy)
                                                                 : dx * dx + dy * dy;
        };
        Random rng(metric == acanthus::DistanceMetric::euclidean ? 31 : 32);
        int said = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const int si = static_cast<int>(rng.uniform_int(0, 60));
            const int sj = static_cast<int>(rng.uniform_int(0, 60));
            const int bx = static_cast<int>(rng.uniform_int(0, 60));
            const int by = static_cast<int>(rng.uniform_int(0, 60));
            const PixelBox box{bx, by, bx + static_cast<int>(rng.uniform_int(0, 6)),
                               by + static_cast<int>(rng.uniform_int(0, 6))};
            const int rx = static_cast<int>(rng.uniform_int(0, 60));
            const int ry = static_cast<int>(rng.uniform_int(0, 60));
            const PixelBox r{rx, ry, rx + static_cast<int>(rng.uniform_int(0, 15)),
                             ry + static_cast<int>(rng.uniform_int(0, 15))};
            if (!outranks(si, sj, box, r, metric)) continue;
            ++said;
            for (int y = r.y0; y <= r.y1; ++y)
                for (int x = r.x0; x <= r.x1; ++x)
                    for (int v = box.y0; v <= box.y1; ++v)
                        for (int u = box.x0; u <= box.x1; ++u)
                            ASSERT_LE(dist(x - si, y - sj), dist(x - u, y - v))
                                << "trial " << trial << " pixel " << x << "," << y << " site " << u
                                << "," << v;
        }
        EXPECT_GT(said, 200) << "the test never outranks";
    }
}

// Grids of a million pixels and more are transformed by two threads; a start with a few element
// sites folds them into the boundary's transform; recompute_elements() after sites were added
// to the occupancy equals a full compute. All against brute force over the sparse sites.
TEST(DistanceField, LargeGridsMatchBruteForce) {
    const int w = 1201, h = 901;  // over 2^20 pixels, odd sizes to split unevenly
    Random rng(7);
    SparseSites grid(w, h);
    const std::vector<std::uint8_t>& occ = grid.occ;
    auto add = [&](int p, std::uint8_t kind) { grid.add(p, kind); };
    for (int k = 0; k < 40; ++k)  // boundary sites
        add(static_cast<int>(rng.uniform_int(0, w * h - 1)), 1);
    for (int k = 0; k < 3; ++k)  // a few element sites: the seeds of a start
        add(static_cast<int>(rng.uniform_int(0, w * h - 1)), 2);
    auto check = [&](const DistanceField& f, const char* what) {
        for (int p = 0; p < w * h; ++p) {
            const auto [all, boundary] = grid.nearest(p);
            ASSERT_EQ(f.squared_distance(p), all) << what << " pixel " << p;
            ASSERT_EQ(f.boundary_squared_distance(p), boundary) << what << " pixel " << p;
            if (f.nearest_site(p) >= 0) {
                ASSERT_EQ(site_distance(f, p), all) << what;
            }
        }
    };
    DistanceField few(w, h, /*with_sites=*/false);
    few.compute(occ);
    check(few, "few element sites");
    for (int k = 0; k < 40; ++k) add(static_cast<int>(rng.uniform_int(0, w * h - 1)), 2);
    DistanceField full(w, h, /*with_sites=*/true);
    full.compute(occ);
    check(full, "two threads with the feature transform");
    few.recompute_elements(occ);
    check(few, "recompute_elements");
}

// A lazy field with tiles left out (far from every pixel that may centre a circle, as under a
// symmetry group) is exact on the tiles it keeps from the start, and transforms no row that
// has none: those stay infinite. Small grids and one large enough for two threads; a seed's
// few element sites, many, and recompute_elements().
TEST(DistanceField, LazyFieldIsExactOnTheTilesItKeeps) {
    struct Scene {
        int w, h;
        int elements;
    };
    Random rng(31);
    for (const Scene& s : {Scene{330, 230, 3}, Scene{330, 230, 40}, Scene{1401, 1403, 5}}) {
        const int w = s.w, h = s.h;
        SparseSites grid(w, h);
        auto add = [&](int p, std::uint8_t kind) { grid.add(p, kind); };
        for (int k = 0; k < 30; ++k) add(static_cast<int>(rng.uniform_int(0, w * h - 1)), 1);
        for (int k = 0; k < s.elements; ++k)
            add(static_cast<int>(rng.uniform_int(0, w * h - 1)), 2);
        // Centre tiles below a slanted line and the first rows: a wedge's rows begin and end
        // anywhere, and some rows have none.
        const int tw = (w + 7) / 8, th = (h + 7) / 8;
        std::vector<std::uint8_t> centres(static_cast<std::size_t>(tw) * th, 0);
        for (int tj = 0; tj < th; ++tj)
            for (int ti = 0; ti < tw; ++ti)
                centres[static_cast<std::size_t>(tj * tw + ti)] =
                    tj > th / 8 && ti + tj > (tw + th) * 3 / 10;
        DistanceField lazy(w, h, /*with_sites=*/false);
        lazy.set_lazy(true);
        lazy.far_blocks().set_centre_tiles(centres);
        auto check = [&](const char* what) {
            long long kept = 0;
            for (int j = 0; j < h; ++j) {
                bool row_kept = false;
                for (int i = 0; i < w; ++i)
                    row_kept = row_kept || lazy.far_blocks().keeps(j * w + i);
                for (int i = 0; i < w; ++i) {
                    const int p = j * w + i;
                    if (!row_kept) {
                        ASSERT_EQ(lazy.squared_distance(p), DistanceField::infinite) << what;
                        ASSERT_EQ(lazy.boundary_squared_distance(p), DistanceField::infinite);
                        continue;
                    }
                    if (!lazy.far_blocks().keeps(p)) continue;
                    ++kept;
                    const auto [all, bnd] = grid.nearest(p);
                    ASSERT_EQ(lazy.squared_distance(p), all) << what << " pixel " << i << "," << j;
                    ASSERT_EQ(lazy.boundary_squared_distance(p), bnd) << what << " pixel " << p;
                }
            }
            ASSERT_GT(kept, 0);
            ASSERT_LT(kept, static_cast<long long>(w) * h);
        };
        lazy.compute(grid.occ);
        check("compute");
        for (int k = 0; k < 30; ++k) add(static_cast<int>(rng.uniform_int(0, w * h - 1)), 2);
        lazy.recompute_elements(grid.occ);
        check("recompute_elements");
    }
}

// A narrow wedge of kept tiles across half the grid's height (as under d8 or d12): the kept
// pixels are transformed column by column (few kept columns, many kept rows), with the values
// of the whole field; so after recompute_elements() with many element sites. Kept columns that
// reach the grid's right edge, and widths not multiples of 8.
TEST(DistanceField, LazyFieldOverANarrowWedgeMatchesTheWholeField) {
    Random rng(11);
    for (const int w : {203, 330, 517})
        for (const bool right_edge : {false, true}) {
            const int h = w * 5 / 4;
            std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 1);
            const double cx = right_edge ? w * 0.6 : w / 2.0, cy = h / 2.0;
            const double rx = w * 0.45, ry = h * 0.45;
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    const double u = (i + 0.5 - cx) / rx, v = (j + 0.5 - cy) / ry;
                    if (u * u + v * v < 1) occ[static_cast<std::size_t>(j) * w + i] = 0;
                }
            // A row of boundary sites across the wedge, and a few element sites.
            for (int i = 0; i < w; ++i) occ[static_cast<std::size_t>(h / 3) * w + i] = 1;
            for (int k = 0; k < 3; ++k) {
                const int p = static_cast<int>(rng.uniform_int(0, w * h - 1));
                if (occ[p] == 0) occ[p] = 2;
            }
            const int tw = (w + 7) / 8, th = (h + 7) / 8;
            std::vector<std::uint8_t> centres(static_cast<std::size_t>(tw) * th, 0);
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 0; ti < tw; ++ti) {
                    const double x = ti - tw * (right_edge ? 0.9 : 0.5), y = th / 2.0 - tj;
                    centres[static_cast<std::size_t>(tj * tw + ti)] =
                        y >= 0 && x >= 0 && x <= 0.4 * y;
                }
            DistanceField lazy(w, h, /*with_sites=*/false);
            lazy.set_lazy(true);
            lazy.far_blocks().set_centre_tiles(centres);
            auto check = [&](const char* what) {
                DistanceField whole(w, h, /*with_sites=*/false);
                whole.compute(occ);
                long long kept = 0;
                for (int p = 0; p < w * h; ++p) {
                    if (!lazy.far_blocks().keeps(p)) continue;
                    ++kept;
                    ASSERT_EQ(lazy.squared_distance(p), whole.squared_distance(p))
                        << what << ", width " << w << ", pixel " << p % w << "," << p / w;
                    ASSERT_EQ(lazy.boundary_squared_distance(p),
                              whole.boundary_squared_distance(p));
                }
                ASSERT_GT(kept, 0);
                ASSERT_LT(kept, static_cast<long long>(w) * h / 4);
            };
            lazy.compute(occ);
            check("compute");
            for (int k = 0; k < 60; ++k) {
                const int p = static_cast<int>(rng.uniform_int(0, w * h - 1));
                if (occ[p] == 0) occ[p] = 2;
            }
            lazy.recompute_elements(occ);
            check("recompute_elements");
        }
}

// The lazy field over a region as growth has it (everything outside an ellipse a boundary
// site, the inside free): on the tiles it keeps, the values of a field computed over the whole
// grid. Rows of sites, free rows and rows partly both test the column pass's eight bytes at a
// time; the row pass leaves out columns far from the kept ones. Widths not multiples of 8.
TEST(DistanceField, LazyFieldOverARegionMatchesTheWholeField) {
    Random rng(7);
    for (const int w : {203, 330, 517})
        for (const int elements : {2, 40}) {
            const int h = w * 3 / 4;
            std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 1);
            const double cx = w / 2.0, cy = h / 2.0, rx = w * 0.45, ry = h * 0.4;
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i) {
                    const double u = (i + 0.5 - cx) / rx, v = (j + 0.5 - cy) / ry;
                    if (u * u + v * v < 1) occ[static_cast<std::size_t>(j) * w + i] = 0;
                }
            for (int k = 0; k < elements; ++k) {
                const int p = static_cast<int>(rng.uniform_int(0, w * h - 1));
                if (occ[p] == 0) occ[p] = 2;
            }
            // A wedge of centre tiles from the middle, as under a rosette.
            const int tw = (w + 7) / 8, th = (h + 7) / 8;
            std::vector<std::uint8_t> centres(static_cast<std::size_t>(tw) * th, 0);
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 0; ti < tw; ++ti) {
                    const double x = ti - tw / 2.0, y = th / 2.0 - tj;
                    centres[static_cast<std::size_t>(tj * tw + ti)] = y >= 0 && x >= 0 && y <= x;
                }
            DistanceField whole(w, h, /*with_sites=*/false);
            whole.compute(occ);
            DistanceField lazy(w, h, /*with_sites=*/false);
            lazy.set_lazy(true);
            lazy.far_blocks().set_centre_tiles(centres);
            lazy.compute(occ);
            long long kept = 0;
            for (int p = 0; p < w * h; ++p) {
                if (!lazy.far_blocks().keeps(p)) continue;
                ++kept;
                ASSERT_EQ(lazy.squared_distance(p), whole.squared_distance(p))
                    << "width " << w << ", pixel " << p % w << "," << p / w;
                ASSERT_EQ(lazy.boundary_squared_distance(p), whole.boundary_squared_distance(p));
            }
            ASSERT_GT(kept, 0);
            ASSERT_LT(kept, static_cast<long long>(w) * h / 4);
        }
}
