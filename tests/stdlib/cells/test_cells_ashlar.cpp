// Ashlar: the paper's random merge (terminates, every stone within the maximum, no two stones
// left that could merge, the stones tile the free units, seeded) and the joint-rules variant.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <iostream>
#include <map>
#include <tuple>

#include "ashlar_merge.hpp"
#include "cells_oracle.hpp"

using namespace cells_test;
using acanthus::cells::detail::merge_ashlar;
using acanthus::cells::detail::Stone;

namespace {

// A rows x units grid with a few blocked rectangles (openings, cells placed by others).
std::vector<char> free_units(int rows, int units) {
    std::vector<char> f(static_cast<std::size_t>(rows * units), 1);
    auto block = [&](int r0, int u0, int r1, int u1) {
        for (int r = r0; r < r1; ++r)
            for (int u = u0; u < u1; ++u) f[static_cast<std::size_t>(r * units + u)] = 0;
    };
    block(5, 7, 17, 15);
    block(20, 30, 23, 31);
    block(0, 0, 1, 3);
    block(31, 40, 40, 60);
    return f;
}

std::vector<std::tuple<int, int, int, int>> as_tuples(const std::vector<Stone>& s) {
    std::vector<std::tuple<int, int, int, int>> out;
    for (const Stone& x : s) out.emplace_back(x.row, x.unit, x.h, x.w);
    return out;
}

}  // namespace

TEST(CellsAshlar, MergeTilesWithinMaximumUntilNothingMerges) {
    const int rows = 40, units = 60;
    std::vector<char> free = free_units(rows, units);
    for (auto [mw, mh] : {std::pair{4, 2}, std::pair{1, 1}, std::pair{3, 3}, std::pair{60, 40}})
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            acanthus::Random random(seed);
            std::vector<Stone> stones = merge_ashlar(free, rows, units, mw, mh, random);
            std::vector<int> owner(free.size(), -1);
            for (std::size_t i = 0; i < stones.size(); ++i) {
                const Stone& s = stones[i];
                ASSERT_GE(s.w, 1);
                ASSERT_GE(s.h, 1);
                EXPECT_LE(s.w, mw);
                EXPECT_LE(s.h, mh);
                for (int r = s.row; r < s.row + s.h; ++r)
                    for (int u = s.unit; u < s.unit + s.w; ++u) {
                        auto k = static_cast<std::size_t>(r * units + u);
                        ASSERT_TRUE(free[k]) << "a stone on a blocked unit";
                        ASSERT_EQ(owner[k], -1) << "two stones on one unit";
                        owner[k] = static_cast<int>(i);
                    }
            }
            for (std::size_t k = 0; k < free.size(); ++k)
                EXPECT_EQ(free[k] != 0, owner[k] >= 0) << "every free unit in exactly one stone";
            // The merge ran until no two neighbours sharing a whole side fit the maximum.
            for (const Stone& a : stones)
                for (const Stone& b : stones) {
                    bool beside = b.row == a.row && b.h == a.h && b.unit == a.unit + a.w;
                    bool below = b.unit == a.unit && b.w == a.w && b.row == a.row + a.h;
                    EXPECT_FALSE(beside && a.w + b.w <= mw) << "stones left that could merge";
                    EXPECT_FALSE(below && a.h + b.h <= mh) << "stones left that could merge";
                }
            if (mw == 1 && mh == 1) {  // nothing can merge
                EXPECT_EQ(static_cast<long>(stones.size()),
                          std::count(free.begin(), free.end(), 1));
            }
            if (mw == 4 && mh == 2) {  // merging happened, with stones of several sizes
                std::map<std::pair<int, int>, int> sizes;
                for (const Stone& s : stones) ++sizes[{s.w, s.h}];
                EXPECT_GE(sizes.size(), 5u);
                EXPECT_LT(stones.size(), free.size() / 3);
            }
        }
}

TEST(CellsAshlar, MergeIsSeeded) {
    std::vector<char> free = free_units(40, 60);
    acanthus::Random a(7), b(7), c(8);
    auto sa = as_tuples(merge_ashlar(free, 40, 60, 4, 2, a));
    EXPECT_EQ(sa, as_tuples(merge_ashlar(free, 40, 60, 4, 2, b)));
    EXPECT_NE(sa, as_tuples(merge_ashlar(free, 40, 60, 4, 2, c)));
    acanthus::Random d(1);
    EXPECT_TRUE(merge_ashlar({}, 0, 0, 4, 2, d).empty());
}

// Face stones of a texture, as boxes (mortar 0: cells are their claims).
static std::vector<acanthus::Rect> face_stones(const Texture& t) {
    std::vector<acanthus::Rect> out;
    for (const Cell& c : t.cells)
        if (c.generator == "ashlar" && c.feature == FeatureKind::face && c.polygon.size() == 4) {
            acanthus::Rect r{1e300, 1e300, -1e300, -1e300};
            for (Point p : c.polygon)
                r = {std::min(r.x0, p.x), std::min(r.y0, p.y), std::max(r.x1, p.x),
                     std::max(r.y1, p.y)};
            out.push_back(r);
        }
    return out;
}

// Straight joints between face stones (stones on both sides along them): the most stones along
// one, and how many run along more than `max_seam`. Bed joints when `bed`, else side joints.
static std::pair<int, int> seams(const std::vector<acanthus::Rect>& stones, int max_seam,
                                 bool bed) {
    auto k = [](double v) { return std::lround(v * 8); };
    std::map<long, std::vector<std::pair<long, long>>> ends, starts;  // by the joint's line
    for (const acanthus::Rect& s : stones) {
        ends[k(bed ? s.y1 : s.x1)].push_back(bed ? std::pair{k(s.x0), k(s.x1)}
                                                 : std::pair{k(s.y0), k(s.y1)});
        starts[k(bed ? s.y0 : s.x0)].push_back(bed ? std::pair{k(s.x0), k(s.x1)}
                                                   : std::pair{k(s.y0), k(s.y1)});
    }
    int longest = 0, over = 0;
    for (auto& [line, along] : ends) {
        std::vector<std::pair<long, long>>& other = starts[line];
        std::sort(along.begin(), along.end());
        std::sort(other.begin(), other.end());
        auto backed = [&](std::pair<long, long> iv) {  // stones on the far side all along
            long at = iv.first;
            for (auto [a, b] : other)
                if (a <= at && b > at) at = b;
            return at >= iv.second;
        };
        int run = 0;
        long end = -1;
        for (auto iv : along) {
            run = !backed(iv) ? 0 : iv.first == end ? run + 1 : 1;
            end = run ? iv.second : -1;
            longest = std::max(longest, run);
            over += run == max_seam + 1;
        }
    }
    return {longest, over};
}

TEST(CellsAshlar, PaperMergeOnAFacade) {
    Facade f = row_house();
    Options o;
    o.bond = Bond::ashlar;
    EXPECT_EQ(o.ashlar_method, AshlarMethod::rules);  // the joint rules are the default
    o.ashlar_method = AshlarMethod::merge;
    o.ashlar_unit = 100;
    for (double mortar : {0.0, 10.0}) {
        o.mortar = mortar;
        Texture t = texture(f, tree_for(o), o, 11);
        Report r = check_texture(f, t, mortar);
        EXPECT_LT(r.overlap, 1.0);
        EXPECT_LT(r.over_openings, 1.0);
        EXPECT_LT(r.outside, 1.0);
        EXPECT_GE(r.coverage, 0.99);
        if (mortar > 0) continue;
        auto stones = face_stones(t);
        EXPECT_GT(stones.size(), 300u);
        for (const acanthus::Rect& s : stones) {
            EXPECT_LE(s.width(), 4 * 100 * 1.5 + 1e-6);  // four units, stretched by the grid tool
            EXPECT_LE(s.height(), 2 * 100 * 1.5 + 1e-6);
        }
        Texture again = texture(f, tree_for(o), o, 11), other = texture(f, tree_for(o), o, 12);
        auto polygons = [](const Texture& x) {
            std::vector<std::vector<Point>> p;
            for (const Cell& c : x.cells) p.push_back(c.polygon);
            return p;
        };
        EXPECT_EQ(polygons(t), polygons(again));
        EXPECT_NE(polygons(t), polygons(other));
    }
    EXPECT_EQ(parse_ashlar_method("rules"), AshlarMethod::rules);
    EXPECT_THROW(parse_ashlar_method("random"), acanthus::InputError);
}

TEST(CellsAshlar, RulesVariantJoints) {
    Facade f = row_house();
    Options o;
    o.bond = Bond::ashlar;
    o.ashlar_method = AshlarMethod::rules;
    o.ashlar_unit = 100;
    o.mortar = 0;  // claims are drawn as they are, so joints can be read off exactly
    Texture t = texture(f, tree_for(o), o, 11);
    Report r = check_texture(f, t, 0);
    EXPECT_LT(r.overlap, 1.0);
    EXPECT_GE(r.coverage, 0.99);
    auto stones = face_stones(t);
    std::map<std::pair<long, long>, int> corners;  // grid points where stone corners meet
    for (const acanthus::Rect& s : stones) {
        EXPECT_LE(s.width(), 4 * 100 * 1.5 + 1e-6);
        EXPECT_LE(s.height(), 2 * 100 * 1.5 + 1e-6);
        for (double x : {s.x0, s.x1})
            for (double y : {s.y0, s.y1}) ++corners[{std::lround(x * 8), std::lround(y * 8)}];
    }
    EXPECT_GT(stones.size(), 300u);
    // Not exact: a stone laid where every size faults takes the fewest faults (docs/stdlib/
    // cells.md says when). No stone on end (but at jambs), few single units and the wall's edges
    // in the layout leave fewer sizes that break a bed joint: seed 11 here, 0 four-way joints,
    // 15 bed joints along more than 4 stones (the longest 9); `merge` has about 50 and 20. The
    // issue's rules (four-way joints, stones on end, unit squares) come first.
    int four_way = 0;
    for (auto& [p, n] : corners) four_way += n >= 4;
    EXPECT_LE(four_way, static_cast<int>(stones.size()) / 100) << "four-way joints";
    auto [bed_longest, bed_over] = seams(stones, o.ashlar_max_seam, true);
    auto [side_longest, side_over] = seams(stones, o.ashlar_max_seam, false);
    std::cout << stones.size() << " stones, four-way " << four_way << ", bed joints over "
              << bed_over << " (longest " << bed_longest << "), side " << side_over << " ("
              << side_longest << ")\n";
    EXPECT_LE(bed_longest, 2 * o.ashlar_max_seam + 2);
    EXPECT_LE(bed_over, static_cast<int>(stones.size()) / 25) << "long bed joints";
    EXPECT_LE(side_longest, o.ashlar_max_seam + 2);
    EXPECT_LE(side_over, static_cast<int>(stones.size()) / 100) << "long side joints";
    o.ashlar_method = AshlarMethod::merge;  // the measure finds what the rules avoid
    auto merged = face_stones(texture(f, tree_for(o), o, 11));
    EXPECT_GT(seams(merged, o.ashlar_max_seam, true).second, 3);
}
