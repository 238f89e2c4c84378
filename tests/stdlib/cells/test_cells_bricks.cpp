// Bricks and bonds on a row-house front: no overlaps, nothing over openings or outside the
// wall, mortar-added coverage, running-bond head joints, window bottoms, corner cells, fewest
// cut bricks.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "brick_layout.hpp"
#include "cells_oracle.hpp"
#include "run_ends.hpp"

using namespace cells_test;

namespace {

Texture lay(const Facade& f, Bond bond, const Node& tree) {
    Options o;
    o.bond = bond;
    return texture(f, tree, o, 7);
}

}  // namespace

TEST(CellsBricks, EveryBondFillsTheWallWithoutOverlap) {
    Facade f = row_house();
    for (Bond b : {Bond::running, Bond::stack, Bond::english, Bond::flemish, Bond::header}) {
        for (const Node& tree : {brick_tree(), framed_tree()}) {
            Texture t = lay(f, b, tree);
            Report r = check_texture(f, t, 10);
            SCOPED_TRACE(std::string(to_string(b)));
            EXPECT_LT(r.overlap, 1.0);
            EXPECT_LT(r.over_openings, 1.0);
            EXPECT_LT(r.outside, 1.0);
            EXPECT_GE(r.coverage, 0.99);
        }
    }
}

TEST(CellsBricks, RunningBondHeadJointsStagger) {
    Facade f = row_house();
    Texture t = lay(f, Bond::running, brick_tree());
    // Head joints (left ends of face bricks) per course, away from openings and corners.
    std::map<int, std::vector<double>> joints;
    for (const Cell& c : t.cells) {
        if (c.generator != "bricks" || c.feature != FeatureKind::face || c.polygon.size() != 4)
            continue;
        double x0 = 1e300, y0 = 1e300, y1 = -1e300;
        for (Point p : c.polygon)
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        bool near_opening = false;
        for (const auto& o : f.openings())
            for (Point p : o)
                if (std::abs(p.x - x0) < 300 && p.y > y0 - 2000 && p.y < y1 + 2000)
                    near_opening = true;
        if (x0 < 300 || x0 > 5700 || near_opening) continue;
        joints[c.course].push_back(x0 - 5);  // the drawn brick starts half a joint in
    }
    const double quarter = 215.0 / 4;
    int compared = 0;
    for (auto& [course, xs] : joints) {
        auto next = joints.find(course + 1);
        if (next == joints.end()) continue;
        for (double x : xs)
            for (double y : next->second) {
                EXPECT_GE(std::abs(x - y), quarter) << "courses " << course << ", " << course + 1;
                ++compared;
            }
    }
    EXPECT_GT(compared, 100);
}

TEST(CellsBricks, WindowBottomsUnderEveryWindow) {
    Facade f = row_house();
    Texture t = lay(f, Bond::running, brick_tree());
    for (const char* id : {"w1", "w2", "w3"}) {
        double x0 = 1e300, x1 = -1e300, sill = 0;
        for (const Edge& e : f.edges())
            if (e.opening && e.part == Part::bottom &&
                std::find(e.labels.begin(), e.labels.end(), id) != e.labels.end())
                x0 = e.bounds.x0, x1 = e.bounds.x1, sill = e.bounds.y0;
        ASSERT_LT(x0, x1) << id;
        double covered = 0;
        for (const Cell& c : t.cells) {
            if (c.generator != "window_bottom") continue;
            double a = 1e300, b = -1e300, top = 1e300;
            for (Point p : c.polygon)
                a = std::min(a, p.x), b = std::max(b, p.x), top = std::min(top, p.y);
            // The row right under this sill, or the course under the strip of split bricks
            // when the sill leaves less than half a course below it.
            if (top < sill || top > sill + 75) continue;
            covered += std::max(0.0, std::min(b, x1) - std::max(a, x0));
        }
        EXPECT_GE(covered, 0.8 * (x1 - x0)) << id;
    }
}

TEST(CellsBricks, ACornerCellAtEveryConvexCorner) {
    Facade f = row_house();
    Texture t = lay(f, Bond::running, brick_tree());
    for (std::size_t i = 0; i < f.corners().size(); ++i) {
        if (!f.corners()[i].convex) continue;
        bool found = false;
        for (const Cell& c : t.cells)
            found |= c.feature == FeatureKind::corner && c.feature_index == static_cast<int>(i);
        EXPECT_TRUE(found) << "corner " << i;
    }
}

TEST(CellsBricks, PhaseWithFewestCutBricks) {
    Facade f = row_house();
    for (Bond b : {Bond::running, Bond::flemish, Bond::english}) {
        Options o;
        o.bond = b;
        acanthus::cells::detail::BrickLayout layout =
            acanthus::cells::detail::make_brick_layout(f, 0, o);
        for (int phase = 0; phase < layout.bond.period(); ++phase)
            EXPECT_LE(layout.cut_pieces,
                      acanthus::cells::detail::cut_pieces(layout.grid, layout.bond, phase));
    }
    // A wall an even number of half bricks wide needs no cut brick in every other course.
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 225 * 8, 75 * 6), {"wall"}, "w"));
    Facade plain = Facade::from_shapes(std::move(s), "plain.svg");
    Options o;
    auto layout = acanthus::cells::detail::make_brick_layout(plain, 0, o);
    EXPECT_EQ(layout.cut_pieces, 6);  // one course in two starts and ends with a half bat
}

TEST(CellsBricks, Deterministic) {
    Facade f = row_house();
    Texture a = lay(f, Bond::flemish, brick_tree()), b = lay(f, Bond::flemish, brick_tree());
    ASSERT_EQ(a.cells.size(), b.cells.size());
    for (std::size_t i = 0; i < a.cells.size(); ++i)
        EXPECT_EQ(a.cells[i].polygon, b.cells[i].polygon);
}

// The ways of run ends kept in a memo and taken from it lay what finding them afresh lays; a
// course laid otherwise is not answered from the memo (its pieces are in the key).
TEST(CellsBricks, RunEndsMemoLaysAsFoundAfresh) {
    using namespace acanthus::cells::detail;
    Facade f = row_house();
    for (Bond b : {Bond::running, Bond::english, Bond::flemish, Bond::header}) {
        SCOPED_TRACE(std::string(to_string(b)));
        Options o;
        o.bond = b;
        const BrickLayout start = make_brick_layout(f, 0, o, true, false);
        auto same = [](const BrickLayout& x, const BrickLayout& y) {
            if (x.rows.size() != y.rows.size()) return false;
            for (std::size_t r = 0; r < x.rows.size(); ++r) {
                if (x.rows[r].size() != y.rows[r].size()) return false;
                for (std::size_t k = 0; k < x.rows[r].size(); ++k) {
                    const acanthus::Rect a = x.drawn(static_cast<int>(r), static_cast<int>(k)),
                                         b = y.drawn(static_cast<int>(r), static_cast<int>(k));
                    if (a.x0 != b.x0 || a.x1 != b.x1 || a.y0 != b.y0 || a.y1 != b.y1) return false;
                }
            }
            return true;
        };
        // Every course moved a little: the memo filled from `start` answers none of its ends.
        BrickLayout moved = start;
        for (auto& row : moved.shift)
            for (double& s : row) s += 0.25 * o.joint_tolerance;
        RunEndsMemo memo;
        BrickLayout warm = start;
        fit_run_ends(f, 0, o, warm, &memo);
        EXPECT_GT(memo.kept(), 0u);
        for (const BrickLayout* from : {&start, static_cast<const BrickLayout*>(&moved)}) {
            BrickLayout fresh = *from, memoised = *from;
            fit_run_ends(f, 0, o, fresh);
            const std::size_t hits = memo.hits();
            fit_run_ends(f, 0, o, memoised, &memo);
            EXPECT_TRUE(same(fresh, memoised));
            if (from == &start) {
                EXPECT_GT(memo.hits(), hits);
            }
        }
    }
}
