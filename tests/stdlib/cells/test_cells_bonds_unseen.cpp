// Bonds on facades made up here and nowhere else (seeded, so the same walls every run): rows of
// windows with jambs anywhere between quarter bricks, windows near the wall's ends, windows
// stacked storey over storey, wide openings and doors on the ground. Every bond and tree: the
// mason's checker finds no straight joint.
#include <gtest/gtest.h>

#include <acanthus/stdlib/cells/cut_list.hpp>
#include <cstdint>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cells_oracle.hpp"
#include "mason_check.hpp"

using namespace cells_test;

namespace {

const MasonSpec kCm{21.5, 6.5, 1, 0.3};

// A small generator of our own, so the walls are the same on every standard library.
struct Lcg {
    std::uint64_t s;
    double next() {  // [0, 1)
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

struct Opening {
    double x, y, w, h;
    bool door;
};

// A front of `storeys` storeys: per storey a row of windows of random widths (60-200 cm, one in
// four up to 320) and random piers (25-120 cm, the first and last from 8 cm), stacked over the
// storey below when `stacked`, doors standing on the ground in the lowest storey. Millimetres are
// not kept: every size is random to a tenth of a centimetre, so jambs fall anywhere.
Facade made_up(std::uint64_t seed, bool stacked) {
    Lcg r{seed * 2654435761ULL + 17};
    const int storeys = 1 + static_cast<int>(r.next() * 3);
    const double storey = r.in(230, 320);
    const double height = storeys * storey + r.in(20, 90);
    std::vector<Opening> openings;
    std::vector<std::pair<double, double>> columns;  // x, w of the lowest storey, for stacking
    double width = 0;
    {
        double x = r.in(8, 120);
        while (true) {
            double w = r.next() < 0.25 ? r.in(130, 320) : r.in(60, 200);
            columns.push_back({x, w});
            x += w + r.in(25, 120);
            if (x > 900 || (columns.size() >= 2 && r.next() < 0.25)) break;
        }
        width = columns.back().first + columns.back().second + r.in(8, 120);
    }
    auto round1 = [](double v) { return std::round(v * 10) / 10; };
    for (int s = 0; s < storeys; ++s) {
        const double floor = height - s * storey;  // the storey's bottom (SVG y down)
        std::vector<std::pair<double, double>> row = columns;
        if (!stacked && s > 0) {
            row.clear();
            double x = r.in(8, 120);
            while (x < width - 60) {
                const double w = std::min(r.in(60, 220), width - 8 - x);
                if (w < 40) break;
                row.push_back({x, w});
                x += w + r.in(25, 120);
            }
        }
        for (auto [x, w] : row) {
            const bool door = s == 0 && r.next() < 0.3;
            const double sill = door ? floor : floor - r.in(60, 110);
            const double top = floor - storey + r.in(30, 60);
            openings.push_back({round1(x), round1(top), round1(w), round1(sill - top), door});
        }
    }
    std::vector<FacadeShape> shapes;
    shapes.push_back(shape(rect(0, 0, round1(width), round1(height)), {"wall"}, "front"));
    int k = 0;
    for (const Opening& o : openings) {
        const double bottom = o.y + o.h;
        shapes.push_back(shape(rect(o.x, o.y, o.w, o.door ? round1(height) - o.y : bottom - o.y),
                               {o.door ? "door" : "window"}, "o" + std::to_string(k++)));
    }
    return Facade::from_shapes(std::move(shapes), "made-up-" + std::to_string(seed) + ".svg");
}

Options centimetres() {
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1, o.joint_tolerance = 0.3;
    return o;
}

// Every bond a course is bonded in (not stack) and every tree of the checker, laid on `f` at seed
// 1 and read by the mason's checker: fn(options, tree name, texture, report), under a trace
// naming the wall, bond and tree.
template <class Fn>
void each_bond_and_tree(const Facade& f, Fn fn) {
    static const auto trees = mason_trees();
    Options o = centimetres();
    for (Bond bond : {Bond::running, Bond::english, Bond::flemish, Bond::header})
        for (const auto& [name, tree] : trees) {
            o.bond = bond;
            const Texture t = texture(f, tree, o, 1);
            const MasonReport r = mason_check(f, t.cells, kCm);
            SCOPED_TRACE(f.name() + " " + std::string(to_string(bond)) + " " + name);
            fn(o, name, t, r);
        }
}

// Straight joints on made-up walls `first`..`last`, every bond and tree; each wall's count against
// `allowed` (by seed; 0 where not named), the total returned.
long straight_on_walls(std::uint64_t first, std::uint64_t last,
                       const std::map<std::uint64_t, long>& allowed = {}) {
    long total = 0;
    for (std::uint64_t seed = first; seed <= last; ++seed) {
        Facade f = made_up(seed, seed % 2 == 0);
        const long allowance = allowed.count(seed) ? allowed.at(seed) : 0;
        each_bond_and_tree(f, [&](const Options& o, const std::string& name, const Texture&,
                                  const MasonReport& r) {
            std::string where;
            for (Point p : r.straight_at)
                where += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
            if (r.straight_joints > 0)
                std::cout << f.name() << " " << to_string(o.bond) << " " << name << ": "
                          << r.straight_joints << " straight joints at" << where << "\n";
            total += r.straight_joints;
            EXPECT_LE(r.straight_joints, allowance) << "at" << where;
            // Bearings moved a quarter brick shorter stay at 10 cm or more.
            EXPECT_EQ(r.short_bearings, 0) << "shortest " << r.shortest_bearing;
            if (name == "framed") {
                EXPECT_GT(r.lintels, 0);
            }
        });
    }
    return total;
}

}  // namespace

// Framed: quoins and lintels bonded in, closers and re-cut pieces against their ends (119
// straight joints on these twelve walls before), and where two fixed ends still met over each
// other (a window-bottom row or a narrow pier's quoins over the quoins of a jamb below, 12 on these
// walls), a bearing, a row's end or a quoin moved a quarter brick (framed_moves.hpp).
TEST(CellsBondsUnseen, NoStraightJoints) {
    const long total = straight_on_walls(1, 12);
    std::cout << "straight joints on all walls: " << total << "\n";
    EXPECT_EQ(total, 0);
}

// Walls made up after the framed tree's fixed ends were moved, seeds nothing was tuned on. (Two
// of them, 29 and 35, had 17-24 straight joints up a pier between two openings in every tree: a
// jamb brick drawn whole against the reveal reached into the head joint beside it by half a
// joint, on units the joints squeezed to fit the wall; context.cpp now lets it reach only as
// far as the joint stays a quarter brick clear.)
TEST(CellsBondsUnseen, NoStraightJointsOnWallsNotTunedOn) {
    const long total = straight_on_walls(13, 36);
    std::cout << "straight joints on all walls: " << total << "\n";
    EXPECT_EQ(total, 0);
}

// King closers (docs/stdlib/cells.md, Closers): in Flemish bond a header against a reveal or a
// quoin with its queen closer is one king closer, three quarters on the face, a stretcher beside
// it; other bonds lay none. The checker finds each where the bond calls for it, and the cut list
// counts them apart from the three-quarter bats they look like.
TEST(CellsBondsUnseen, KingClosersInFlemishBond) {
    const std::string examples = std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/";
    std::vector<Facade> walls;
    walls.push_back(Facade::from_svg_file(examples + "row-house.svg"));
    for (std::uint64_t seed = 1; seed <= 6; ++seed) walls.push_back(made_up(seed, seed % 2 == 0));
    long kings = 0;
    for (const Facade& f : walls)
        each_bond_and_tree(
            f, [&](const Options& o, const std::string&, const Texture& t, const MasonReport& r) {
                if (o.bond != Bond::flemish) {
                    EXPECT_EQ(r.king_closers, 0);
                    return;
                }
                kings += r.king_closers;
                std::string where;
                for (Point p : r.misplaced_kings)
                    where += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
                EXPECT_EQ(r.king_closers_misplaced, 0) << "at" << where;
                EXPECT_EQ(r.slivers, 0);
                // Smallest piece: a king closer is wider than the queen closer it replaces.
                EXPECT_GE(r.smallest_piece, 0.1);
                long listed = 0;
                for (const CutListItem& item : cut_list(f, t.cells, o, 10))
                    if (item.kind == "king closer") {
                        listed += item.count;
                        EXPECT_EQ(item.generator, "bricks");
                        EXPECT_NEAR(item.width, 159, 1);  // three quarters less a joint
                    }
                EXPECT_EQ(listed, r.king_closers);
            });
    std::cout << "king closers in Flemish bond, all walls and trees: " << kings << "\n";
    EXPECT_GT(kings, 50);
}

// The checker finds a king closer laid where no reveal is, on every made-up wall and tree, and
// one with a header laid beyond it where the bond calls for a stretcher.
TEST(CellsBondsUnseen, FindsAMisplacedKingCloser) {
    Options o = centimetres();
    o.bond = Bond::flemish;
    const double three_quarters = 3 * (21.5 + 1) / 4 - 1, header = (21.5 - 1) / 2;
    long tried = 0, headers_tried = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed)
        for (const auto& [name, tree] : mason_trees()) {
            Facade f = made_up(seed, seed % 2 == 0);
            Texture t = texture(f, tree, o, 1);
            MasonReport r = mason_check(f, t.cells, kCm);
            SCOPED_TRACE("made-up " + std::to_string(seed) + " " + name);
            EXPECT_EQ(r.king_closers_misplaced, 0);
            // Name a stretcher in the middle of the wall, away from every reveal, a king closer.
            const double x_mid = f.bounds().x0 + f.bounds().width() / 2;
            std::vector<Cell> cells = t.cells;
            Point laid{-1, -1};
            for (Cell& c : cells) {
                Rect b;
                if (c.generator != "bricks" || !c.piece.empty() || !is_rect(c.polygon, b)) continue;
                if (std::abs(b.width() - 21.5) > 0.1 || std::abs(b.center().x - x_mid) > 30)
                    continue;
                c.piece = "king closer";
                c.polygon = {{b.x0, b.y0},
                             {b.x0 + three_quarters, b.y0},
                             {b.x0 + three_quarters, b.y1},
                             {b.x0, b.y1}};
                laid = {b.x0 + three_quarters / 2, b.center().y};
                ++tried;
                break;
            }
            // It, and a king closer at a pier's reveal whose stretcher it was.
            const MasonReport mid = mason_check(f, cells, kCm);
            EXPECT_GE(mid.king_closers_misplaced, 1);
            bool found = false;
            for (Point p : mid.misplaced_kings)
                found |= std::abs(p.x - laid.x) < 0.01 && std::abs(p.y - laid.y) < 0.01;
            EXPECT_TRUE(found);
            // A king closer at a reveal with the stretcher beyond it cut to a header, the rest of
            // the course still running on.
            cells = t.cells;
            for (Cell& k : cells) {
                Rect b;
                if (k.piece != "king closer" || !is_rect(k.polygon, b)) continue;
                bool done = false;
                for (Cell& c : cells) {
                    Rect n;
                    if (c.generator != "bricks" || !is_rect(c.polygon, n) ||
                        std::abs(n.width() - 21.5) > 0.1 || std::abs(n.y0 - b.y0) > 0.05)
                        continue;
                    if (std::abs(n.x0 - b.x1 - 1) < 0.2)
                        c.polygon = {{n.x0, n.y0},
                                     {n.x0 + header, n.y0},
                                     {n.x0 + header, n.y1},
                                     {n.x0, n.y1}};
                    else if (std::abs(b.x0 - n.x1 - 1) < 0.2)
                        c.polygon = {{n.x1 - header, n.y0},
                                     {n.x1, n.y0},
                                     {n.x1, n.y1},
                                     {n.x1 - header, n.y1}};
                    else
                        continue;
                    done = true;
                    break;
                }
                if (!done) continue;
                ++headers_tried;  // it, and any other king closer that stretcher went on from
                EXPECT_GE(mason_check(f, cells, kCm).king_closers_misplaced, 1);
                break;
            }
        }
    EXPECT_GT(tried, 12);
    EXPECT_GT(headers_tried, 10);
}

// The checker finds a lintel bearing under 10 cm: a framed wall's first lintel cut back to 5 cm
// past its left jamb.
TEST(CellsBondsUnseen, FindsAShortBearing) {
    Options o = centimetres();
    Facade f = made_up(3, false);
    Texture t = texture(f, framed_tree(), o, 1);
    MasonReport r = mason_check(f, t.cells, kCm);
    ASSERT_GT(r.lintels, 0);
    EXPECT_EQ(r.short_bearings, 0);
    EXPECT_GE(r.shortest_bearing, 10);
    for (Cell& c : t.cells) {
        Rect b;
        if (c.generator != "lintel" || !is_rect(c.polygon, b)) continue;
        for (const auto& e : f.edges())
            if (e.opening && !e.arc && e.part == acanthus::cells::Part::top &&
                std::abs(e.bounds.y0 - b.y1) < 1.5 && e.bounds.x0 > b.x0 && e.bounds.x1 < b.x1) {
                const double x = e.bounds.x0 - 5;
                for (Point& p : c.polygon)
                    if (p.x < x) p.x = x;
            }
        break;
    }
    r = mason_check(f, t.cells, kCm);
    EXPECT_EQ(r.short_bearings, 1);
    EXPECT_NEAR(r.shortest_bearing, 5, 1e-6);
}
