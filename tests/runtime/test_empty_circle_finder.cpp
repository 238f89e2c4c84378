// EmptyCircleFinder: medial-axis candidates, boundary-stopped and excluded circles, minimum
// radius, and the incremental search against the full scan; the lazy field's test of new sites.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "field/empty_circle_finder.hpp"
#include "field/pending_blocks.hpp"
#include "growth/exclude_list.hpp"  // the blocker the growth loop hands the finder

using acanthus::Circle;
using acanthus::GridFrame;
using acanthus::detail::DistanceField;
using acanthus::detail::EmptyCircle;
using acanthus::detail::EmptyCircleFinder;
using acanthus::detail::ExcludeList;
using acanthus::detail::ObstacleKind;

namespace {

GridFrame grid(int w, int h, double pixel = 1.0) {
    GridFrame g;
    g.width = w;
    g.height = h;
    g.pixel = pixel;
    return g;
}

// A w x h occupancy grid with a boundary frame all round.
std::vector<std::uint8_t> framed(int w, int h) {
    std::vector<std::uint8_t> occ(static_cast<std::size_t>(w) * h, 0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            if (i == 0 || j == 0 || i == w - 1 || j == h - 1) occ[j * w + i] = 1;
    return occ;
}

bool same(const std::optional<EmptyCircle>& a, const std::optional<EmptyCircle>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->pixel == b->pixel && a->d2 == b->d2);
}

}  // namespace

TEST(EmptyCircleFinder, CircleIsConservative) {
    const int w = 20, h = 10;
    auto occ = framed(w, h);
    occ[5 * w + 5] = 2;
    DistanceField f(w, h);
    f.compute(occ);
    EmptyCircleFinder finder(f, grid(w, h, 0.5), 0);
    const int p = 5 * w + 9;
    const Circle c = finder.circle_of(p);
    EXPECT_DOUBLE_EQ(c.center.x, 9.5 * 0.5);
    EXPECT_DOUBLE_EQ(c.center.y, 5.5 * 0.5);
    EXPECT_DOUBLE_EQ(c.radius, (4 - EmptyCircleFinder::kMargin) * 0.5);
}

TEST(EmptyCircleFinder, MedialAxisIsTheCrestBetweenObstacles) {
    const int w = 21, h = 11;
    std::vector<std::uint8_t> occ(w * h, 0);
    for (int j = 0; j < h; ++j) {
        occ[j * w + 0] = 2;
        occ[j * w + 20] = 2;
    }
    DistanceField f(w, h);
    f.compute(occ);
    EmptyCircleFinder finder(f, grid(w, h), 0);
    for (int j = 0; j < h; ++j) {
        EXPECT_TRUE(finder.on_medial_axis(j * w + 10)) << j;  // midway between the walls
        EXPECT_FALSE(finder.on_medial_axis(j * w + 4)) << j;  // on a slope
        EXPECT_FALSE(finder.on_medial_axis(j * w + 0));       // an obstacle
    }
}

TEST(EmptyCircleFinder, DiscardsCirclesStoppedByTheBoundary) {
    // A long box with one element pixel at the left: the largest free circles on the right are
    // stopped by the boundary and must not be chosen.
    const int w = 60, h = 15;
    auto occ = framed(w, h);
    occ[7 * w + 3] = 2;
    DistanceField f(w, h);
    f.compute(occ);
    EmptyCircleFinder finder(f, grid(w, h), 0);
    finder.rebuild();
    ExcludeList exclude;
    const auto found = finder.find(exclude);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(f.nearest_kind(found->pixel), ObstacleKind::element);
    EXPECT_LT(found->pixel % w, 12);
    std::int64_t global = 0;
    for (int p = 0; p < w * h; ++p) global = std::max(global, f.squared_distance(p));
    EXPECT_LT(found->d2, global);
    EXPECT_TRUE(same(found, finder.find_by_scan(exclude)));

    // Only the boundary: nothing is eligible.
    DistanceField empty(w, h);
    empty.compute(framed(w, h));
    EmptyCircleFinder none(empty, grid(w, h), 0);
    none.rebuild();
    EXPECT_FALSE(none.find(exclude).has_value());
    EXPECT_FALSE(none.find_by_scan(exclude).has_value());
}

TEST(EmptyCircleFinder, ExcludedCirclesWaitUntilTheirPointIsRemoved) {
    const int w = 40, h = 40;
    auto occ = framed(w, h);
    occ[20 * w + 20] = 2;
    DistanceField f(w, h);
    f.compute(occ);
    EmptyCircleFinder finder(f, grid(w, h), 0);
    finder.rebuild();
    ExcludeList exclude;
    const auto first = finder.find(exclude);
    ASSERT_TRUE(first.has_value());
    // The same circle again while nothing changes.
    EXPECT_TRUE(same(finder.find(exclude), first));
    const int id = exclude.add(first->circle.center);
    const auto second = finder.find(exclude);
    ASSERT_TRUE(second.has_value());
    EXPECT_NE(second->pixel, first->pixel);
    EXPECT_FALSE(exclude.any_inside(second->circle));
    EXPECT_LE(second->d2, first->d2);
    EXPECT_TRUE(same(second, finder.find_by_scan(exclude)));
    std::vector<int> removed;
    exclude.remove_within(first->circle.center, 0.1, &removed);
    ASSERT_EQ(removed, std::vector<int>{id});
    finder.release(removed);
    EXPECT_TRUE(same(finder.find(exclude), first));
}

TEST(EmptyCircleFinder, RespectsTheMinimumRadius) {
    const int w = 30, h = 30;
    auto occ = framed(w, h);
    for (int j = 1; j < h - 1; j += 4)
        for (int i = 1; i < w - 1; i += 4) occ[j * w + i] = 2;  // small gaps everywhere
    DistanceField f(w, h);
    f.compute(occ);
    EmptyCircleFinder big(f, grid(w, h), 5.0);
    big.rebuild();
    ExcludeList exclude;
    EXPECT_FALSE(big.find(exclude).has_value());
    EmptyCircleFinder small(f, grid(w, h), 0.5);
    small.rebuild();
    const auto c = small.find(exclude);
    ASSERT_TRUE(c.has_value());
    EXPECT_GE(c->circle.radius, 0.5);
}

// The incremental search gives exactly the full scan's answer after every change of the field,
// the exclude list and the discarded set.
TEST(EmptyCircleFinder, IncrementalFindMatchesScan) {
    acanthus::Random rng(99);
    for (int scene = 0; scene < 6; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(20, 70));
        const int h = static_cast<int>(rng.uniform_int(20, 70));
        auto occ = framed(w, h);
        occ[(h / 2) * w + w / 2] = 2;
        DistanceField f(w, h);
        f.compute(occ);
        EmptyCircleFinder finder(f, grid(w, h, 0.7), rng.uniform(0, 1.5));
        finder.rebuild();
        ExcludeList exclude;
        for (int step = 0; step < 150; ++step) {
            const auto inc = finder.find(exclude);
            const auto ref = finder.find_by_scan(exclude);
            ASSERT_TRUE(same(inc, ref)) << "scene " << scene << " step " << step;
            if (!inc) {
                exclude.clear();
                finder.release_all();
                if (!finder.find(exclude)) break;
                continue;
            }
            const double action = rng.uniform();
            if (action < 0.5) {
                // "Success": a blob near the circle, exclude points near its centre go.
                const int ci = inc->pixel % w, cj = inc->pixel / w;
                std::vector<int> blob;
                const int r = static_cast<int>(rng.uniform_int(0, 2));
                const int oi = static_cast<int>(rng.uniform_int(-3, 3)),
                          oj = static_cast<int>(rng.uniform_int(-3, 3));
                for (int dj = -r; dj <= r; ++dj)
                    for (int di = -r; di <= r; ++di) {
                        const int i = ci + oi + di, j = cj + oj + dj;
                        if (i > 0 && j > 0 && i < w - 1 && j < h - 1) blob.push_back(j * w + i);
                    }
                std::vector<int> changed;
                f.add_sites(blob, ObstacleKind::element, &changed);
                finder.update(changed);
                std::vector<int> removed;
                exclude.remove_within(inc->circle.center, rng.uniform(0, 4), &removed);
                finder.release(removed);
            } else if (action < 0.9) {
                exclude.add(inc->circle.center);  // "failure"
            } else if (action < 0.95) {
                finder.discard(*inc);
            } else {
                exclude.clear();
                finder.release_all();
            }
        }
    }
}

// With a lazy field the finder puts off re-deciding the tiles it does not trust yet; it still
// finds what a full scan of the exact field finds, in both metrics.
TEST(EmptyCircleFinder, LazyFieldFindMatchesScanOfExactField) {
    for (const auto metric :
         {acanthus::DistanceMetric::euclidean, acanthus::DistanceMetric::manhattan}) {
        acanthus::Random rng(metric == acanthus::DistanceMetric::euclidean ? 5 : 6);
        for (int scene = 0; scene < 3; ++scene) {
            const int w = static_cast<int>(rng.uniform_int(130, 260));
            const int h = static_cast<int>(rng.uniform_int(130, 260));
            auto occ = framed(w, h);
            occ[(h / 2) * w + w / 2] = 2;
            DistanceField lazy(w, h, /*with_sites=*/false, metric);
            lazy.set_lazy(true);
            lazy.compute(occ);
            DistanceField exact(w, h, /*with_sites=*/true, metric);
            exact.compute(occ);
            const double min_radius = rng.uniform(0, 1.5);
            EmptyCircleFinder finder(lazy, grid(w, h), min_radius);
            EmptyCircleFinder scan(exact, grid(w, h), min_radius);
            finder.rebuild();
            scan.rebuild();
            ExcludeList exclude;
            for (int step = 0; step < 400; ++step) {
                const auto inc = finder.find(exclude);
                ASSERT_TRUE(same(inc, scan.find_by_scan(exclude)))
                    << "scene " << scene << " step " << step;
                if (!inc) break;
                if (rng.uniform() < 0.85) {
                    // A dot against the circle's edge, as the dots pattern places them.
                    const int ci = inc->pixel % w, cj = inc->pixel / w;
                    const double a = rng.uniform(0, 6.283), reach = std::sqrt(double(inc->d2));
                    const int di = static_cast<int>(std::lround(std::cos(a) * reach * 0.8));
                    const int dj = static_cast<int>(std::lround(std::sin(a) * reach * 0.8));
                    const int r = static_cast<int>(rng.uniform_int(0, 3));
                    std::vector<int> dot;
                    for (int j = cj + dj - r; j <= cj + dj + r; ++j)
                        for (int i = ci + di - r; i <= ci + di + r; ++i)
                            if (i > 0 && j > 0 && i < w - 1 && j < h - 1 &&
                                (i - ci - di) * (i - ci - di) + (j - cj - dj) * (j - cj - dj) <=
                                    r * r)
                                dot.push_back(j * w + i);
                    std::vector<int> changed;
                    lazy.add_sites(dot, ObstacleKind::element, &changed);
                    finder.update(changed);
                    exact.add_sites(dot, ObstacleKind::element, nullptr);
                    std::vector<int> removed;
                    exclude.remove_within(inc->circle.center, rng.uniform(0, 3), &removed);
                    finder.release(removed);
                } else {
                    exclude.add(inc->circle.center);  // "failure"
                }
            }
        }
    }
}

// Centres allowed only in a band (as a symmetry's fundamental domain allows only some): the lazy
// field then leaves out the 8 x 8 tiles more than one tile from the band
// (PendingBlocks::set_centre_tiles) and the changes there go undecided, as the incremental
// circle source does. C must still be the scan's over the exact field, which needs the tiles
// next to the band exact: a crest test on the band's edge reads them.
TEST(EmptyCircleFinder, LazyFieldLeavingOutTilesFarFromTheCentresMatchesScan) {
    for (const auto metric :
         {acanthus::DistanceMetric::euclidean, acanthus::DistanceMetric::manhattan}) {
        acanthus::Random rng(metric == acanthus::DistanceMetric::euclidean ? 11 : 12);
        for (int scene = 0; scene < 3; ++scene) {
            const int w = static_cast<int>(rng.uniform_int(330, 400));
            const int h = static_cast<int>(rng.uniform_int(200, 260));
            auto occ = framed(w, h);
            // Centres: pixels 128..255 of every row (tile columns 16 to 31).
            std::vector<std::uint8_t> centres(static_cast<std::size_t>(w) * h, 0);
            for (int j = 0; j < h; ++j)
                for (int i = 128; i < 256; ++i) centres[static_cast<std::size_t>(j * w + i)] = 1;
            for (int k = 0; k < 6; ++k) {  // a few dots all over, left and right of the band
                const int x = static_cast<int>(rng.uniform_int(5, w - 6));
                const int y = static_cast<int>(rng.uniform_int(5, h - 6));
                occ[static_cast<std::size_t>(y * w + x)] = 2;
            }
            DistanceField lazy(w, h, /*with_sites=*/false, metric);
            lazy.set_lazy(true);
            DistanceField exact(w, h, /*with_sites=*/true, metric);
            const double min_radius = rng.uniform(0, 1.5);
            EmptyCircleFinder finder(lazy, grid(w, h), min_radius);
            EmptyCircleFinder scan(exact, grid(w, h), min_radius);
            finder.set_centres(centres);
            scan.set_centres(centres);
            lazy.far_blocks().set_centre_tiles(finder.tile_centres());
            lazy.compute(occ);
            exact.compute(occ);
            finder.rebuild();
            scan.rebuild();
            ExcludeList exclude;
            for (int step = 0; step < 300; ++step) {
                const auto inc = finder.find(exclude);
                ASSERT_TRUE(same(inc, scan.find_by_scan(exclude)))
                    << "scene " << scene << " step " << step;
                if (!inc) break;
                // A dot against the circle's edge, and one mirrored across the band's left
                // edge (an image, most of them in tiles left out).
                const int ci = inc->pixel % w, cj = inc->pixel / w;
                const double a = rng.uniform(0, 6.283), reach = std::sqrt(double(inc->d2));
                const int di = static_cast<int>(std::lround(std::cos(a) * reach * 0.8));
                const int dj = static_cast<int>(std::lround(std::sin(a) * reach * 0.8));
                const int r = static_cast<int>(rng.uniform_int(0, 3));
                std::vector<int> dots;
                for (int mirrored = 0; mirrored < 2; ++mirrored) {
                    const int x0 = mirrored ? 255 - (ci + di) : ci + di, y0 = cj + dj;
                    for (int j = y0 - r; j <= y0 + r; ++j)
                        for (int i = x0 - r; i <= x0 + r; ++i)
                            if (i > 0 && j > 0 && i < w - 1 && j < h - 1 &&
                                (i - x0) * (i - x0) + (j - y0) * (j - y0) <= r * r)
                                dots.push_back(j * w + i);
                }
                std::vector<int> changed;
                lazy.add_sites(dots, ObstacleKind::element, &changed);
                std::erase_if(changed, [&](int p) { return !lazy.far_blocks().keeps(p); });
                finder.update(changed);
                exact.add_sites(dots, ObstacleKind::element, nullptr);
                std::vector<int> removed;
                exclude.remove_within(inc->circle.center, rng.uniform(0, 3), &removed);
                finder.release(removed);
            }
        }
    }
}

// nonzero_tiles(): a tile is marked just when a byte of it is non-zero, for widths and heights
// that are not multiples of 8 and bytes other than 1.
TEST(EmptyCircleFinder, NonzeroTilesMarkTheTilesHoldingANonzeroByte) {
    acanthus::Random rng(5);
    for (const int w : {1, 7, 8, 9, 70})
        for (const int h : {1, 8, 13}) {
            std::vector<std::uint8_t> bytes(static_cast<std::size_t>(w) * h, 0);
            for (int k = 0; k < 3; ++k)
                bytes[static_cast<std::size_t>(rng.uniform_int(0, w * h - 1))] =
                    static_cast<std::uint8_t>(rng.uniform_int(1, 255));
            const int tw = (w + 7) / 8, th = (h + 7) / 8;
            std::vector<std::uint8_t> want(static_cast<std::size_t>(tw) * th, 0);
            for (int j = 0; j < h; ++j)
                for (int i = 0; i < w; ++i)
                    if (bytes[static_cast<std::size_t>(j) * w + i])
                        want[static_cast<std::size_t>(j / 8) * tw + i / 8] = 1;
            EXPECT_EQ(acanthus::detail::nonzero_tiles(bytes, w, h), want) << w << " x " << h;
        }
}

// PendingBlocks::may_lower() is true just when some block is nearer to the box than its bound
// (the largest of its tiles' bounds): with tiles left out (bound 0) a box far from the kept
// ones is told at once, and must be told as the walk over the blocks would.
TEST(PendingBlocks, MayLowerIsTrueJustWhenABlockIsNearerThanItsBound) {
    using acanthus::detail::PendingBlocks;
    using acanthus::detail::PixelBox;
    acanthus::Random rng(17);
    int near = 0, far = 0;
    for (int scene = 0; scene < 6; ++scene) {
        const int w = static_cast<int>(rng.uniform_int(300, 700));
        const int h = static_cast<int>(rng.uniform_int(200, 600));
        std::vector<std::int32_t> d2(static_cast<std::size_t>(w) * h);
        for (auto& v : d2) v = static_cast<std::int32_t>(rng.uniform_int(0, 900));
        const int tw = (w - 1) / 8 + 1, th = (h - 1) / 8 + 1;
        PendingBlocks blocks;
        if (scene % 3 != 0) {  // centre tiles: a band of tile columns (or none kept at all)
            std::vector<std::uint8_t> centres(static_cast<std::size_t>(tw) * th, 0);
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 8; ti < 16 && scene % 3 == 1; ++ti)
                    centres[static_cast<std::size_t>(tj * tw + ti)] = 1;
            blocks.set_centre_tiles(centres);
        }
        blocks.reset(w, h, d2.data(), acanthus::DistanceMetric::euclidean);
        const int bw = (w - 1) / 64 + 1, bh = (h - 1) / 64 + 1;
        for (int q = 0; q < 500; ++q) {
            PixelBox box;
            box.x0 = static_cast<int>(rng.uniform_int(-80, w + 80));
            box.y0 = static_cast<int>(rng.uniform_int(-80, h + 80));
            box.x1 = box.x0 + static_cast<int>(rng.uniform_int(0, 40));
            box.y1 = box.y0 + static_cast<int>(rng.uniform_int(0, 40));
            bool expected = false;
            for (int bj = 0; bj < bh; ++bj)
                for (int bi = 0; bi < bw; ++bi) {
                    std::int32_t bound = 0;
                    for (int tj = bj * 8; tj < std::min(th, bj * 8 + 8); ++tj)
                        for (int ti = bi * 8; ti < std::min(tw, bi * 8 + 8); ++ti)
                            bound = std::max(bound, blocks.tile_bound(ti, tj));
                    const int x0 = bi * 64, x1 = std::min(w, x0 + 64) - 1;
                    const int y0 = bj * 64, y1 = std::min(h, y0 + 64) - 1;
                    const long long dx = std::max({0, x0 - box.x1, box.x0 - x1});
                    const long long dy = std::max({0, y0 - box.y1, box.y0 - y1});
                    expected = expected || dx * dx + dy * dy < bound;
                }
            (expected ? near : far) += 1;
            EXPECT_EQ(blocks.may_lower(box), expected)
                << "scene " << scene << " box " << box.x0 << "," << box.y0;
        }
    }
    EXPECT_GT(near, 100);
    EXPECT_GT(far, 100);
}

namespace {

// A grid for PendingBlocks: 300 to w_hi by 200 to h_hi pixels, each 8 x 8 tile with a cap of 0
// to 40 pixels squared, its pixels at the cap or (with `spread`) drawn up to it.
struct TileScene {
    int w = 0, h = 0, tw = 0, th = 0;
    std::vector<std::int32_t> caps, d2;
};
TileScene tile_scene(acanthus::Random& rng, int w_hi, int h_hi, bool spread) {
    TileScene s;
    s.w = static_cast<int>(rng.uniform_int(300, w_hi));
    s.h = static_cast<int>(rng.uniform_int(200, h_hi));
    s.tw = (s.w - 1) / 8 + 1, s.th = (s.h - 1) / 8 + 1;
    s.caps.resize(static_cast<std::size_t>(s.tw) * s.th);
    for (auto& c : s.caps) c = static_cast<std::int32_t>(rng.uniform_int(0, 1600));
    s.d2.resize(static_cast<std::size_t>(s.w) * s.h);
    for (int j = 0; j < s.h; ++j)
        for (int i = 0; i < s.w; ++i) {
            const std::int32_t cap = s.caps[static_cast<std::size_t>(j / 8) * s.tw + i / 8];
            s.d2[static_cast<std::size_t>(j) * s.w + i] =
                spread ? static_cast<std::int32_t>(rng.uniform_int(0, cap)) : cap;
        }
    return s;
}

}  // namespace

// A box whose pixels' centres all lie farther than centre_reach() from every pixel of a centre
// tile is near no tile (near() is not `tile`): kept tiles lie within one tile of a centre tile,
// the others' bounds are 0. Infinite without centre tiles (every tile kept).
TEST(PendingBlocks, CentreReachBoundsWhereABoxIsNearATile) {
    using acanthus::detail::PendingBlocks;
    using acanthus::detail::PixelBox;
    acanthus::Random rng(29);
    int beyond = 0;
    for (int scene = 0; scene < 6; ++scene) {
        const TileScene s = tile_scene(rng, 600, 500, false);
        const int w = s.w, h = s.h, tw = s.tw, th = s.th;
        const std::vector<std::int32_t>& d2 = s.d2;
        PendingBlocks blocks;
        std::vector<std::uint8_t> centres(static_cast<std::size_t>(tw) * th, 0);
        if (scene % 3 == 0) {  // a band of tile columns
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 10; ti < 14; ++ti)
                    centres[static_cast<std::size_t>(tj * tw + ti)] = 1;
        } else {  // a few tiles
            for (int k = 0; k < 2 * scene; ++k)
                centres[static_cast<std::size_t>(rng.uniform_int(0, tw * th - 1))] = 1;
        }
        blocks.set_centre_tiles(centres);
        blocks.reset(w, h, d2.data(), acanthus::DistanceMetric::euclidean);
        const double reach = blocks.centre_reach();
        ASSERT_TRUE(std::isfinite(reach));
        for (int q = 0; q < 600; ++q) {
            PixelBox box;
            box.x0 = static_cast<int>(rng.uniform_int(-80, w + 80));
            box.y0 = static_cast<int>(rng.uniform_int(-80, h + 80));
            box.x1 = box.x0 + static_cast<int>(rng.uniform_int(0, 20));
            box.y1 = box.y0 + static_cast<int>(rng.uniform_int(0, 20));
            double gap = INFINITY;
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 0; ti < tw; ++ti) {
                    if (!centres[static_cast<std::size_t>(tj * tw + ti)]) continue;
                    const int x0 = ti * 8, x1 = std::min(w, x0 + 8) - 1;
                    const int y0 = tj * 8, y1 = std::min(h, y0 + 8) - 1;
                    const double dx = std::max({0, x0 - box.x1, box.x0 - x1});
                    const double dy = std::max({0, y0 - box.y1, box.y0 - y1});
                    gap = std::min(gap, std::sqrt(dx * dx + dy * dy));
                }
            if (!(gap > reach)) continue;
            ++beyond;
            EXPECT_NE(blocks.near(box), PendingBlocks::Near::tile)
                << "scene " << scene << " box " << box.x0 << "," << box.y0 << " gap " << gap;
        }
    }
    EXPECT_GT(beyond, 300);
    PendingBlocks all;
    std::vector<std::int32_t> d2(100 * 80, 25);
    all.reset(100, 80, d2.data(), acanthus::DistanceMetric::euclidean);
    EXPECT_FALSE(std::isfinite(all.centre_reach()));
}

// PendingBlocks::near() is `tile` just when some tile is nearer to the box than its own
// bound, else `block` just when may_lower() is true, else `none`: against a brute force over
// the tiles (bounds that vary from tile to tile, grids not multiples of 8, boxes beyond them).
TEST(PendingBlocks, NearTellsATileNearerThanItsBoundFromABlock) {
    using acanthus::detail::PendingBlocks;
    using acanthus::detail::PixelBox;
    acanthus::Random rng(23);
    int counts[3] = {0, 0, 0};
    for (int scene = 0; scene < 6; ++scene) {
        // Each tile's values up to its own cap.
        const TileScene s = tile_scene(rng, 700, 600, true);
        const int w = s.w, h = s.h, tw = s.tw, th = s.th;
        const std::vector<std::int32_t>& d2 = s.d2;
        PendingBlocks blocks;
        if (scene % 2 == 1) {  // centre tiles: a band of tile columns
            std::vector<std::uint8_t> centres(static_cast<std::size_t>(tw) * th, 0);
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 8; ti < 16; ++ti) centres[static_cast<std::size_t>(tj * tw + ti)] = 1;
            blocks.set_centre_tiles(centres);
        }
        blocks.reset(w, h, d2.data(), acanthus::DistanceMetric::euclidean);
        for (int q = 0; q < 500; ++q) {
            PixelBox box;
            box.x0 = static_cast<int>(rng.uniform_int(-80, w + 80));
            box.y0 = static_cast<int>(rng.uniform_int(-80, h + 80));
            box.x1 = box.x0 + static_cast<int>(rng.uniform_int(0, 40));
            box.y1 = box.y0 + static_cast<int>(rng.uniform_int(0, 40));
            bool tile = false;
            for (int tj = 0; tj < th; ++tj)
                for (int ti = 0; ti < tw; ++ti) {
                    const int x0 = ti * 8, x1 = std::min(w, x0 + 8) - 1;
                    const int y0 = tj * 8, y1 = std::min(h, y0 + 8) - 1;
                    const long long dx = std::max({0, x0 - box.x1, box.x0 - x1});
                    const long long dy = std::max({0, y0 - box.y1, box.y0 - y1});
                    tile = tile || dx * dx + dy * dy < blocks.tile_bound(ti, tj);
                }
            const PendingBlocks::Near expected = tile ? PendingBlocks::Near::tile
                                                 : blocks.may_lower(box)
                                                     ? PendingBlocks::Near::block
                                                     : PendingBlocks::Near::none;
            counts[static_cast<int>(expected)] += 1;
            EXPECT_EQ(blocks.near(box), expected)
                << "scene " << scene << " box " << box.x0 << "," << box.y0;
        }
    }
    EXPECT_GT(counts[0], 50);
    EXPECT_GT(counts[1], 50);
    EXPECT_GT(counts[2], 50);
}
