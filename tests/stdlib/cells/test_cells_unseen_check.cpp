// The "How it will be checked", run as an outside expert runs it: on facades made up for it
// and not tuned on (examples/facades/unseen/), in every bond and tree, the mason's checker
// (mason_check.hpp) and the arch rules it does not read: odd rings, a keystone with real width at
// a pointed apex, rings symmetrical about the crown, and no whole brick larger than nominal;
// with the mason's piece rule (mason_check.hpp: every piece a brick, header or standard bat or
// closer, head joints within the tolerance). What it still finds is allowed by name: Known.
// Straight joints are printed, not counted here. Each rule is shown to fail on a broken layout.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells/cut_list.hpp>
#include <chrono>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cells_oracle.hpp"
#include "mason_check.hpp"

using namespace cells_test;

namespace {

const MasonSpec kCm{21.5, 6.5, 1, 0.3};

Options centimetres() {  // as rules/facade.acr lays them
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1, o.joint_tolerance = 0.3;
    return o;
}

const Bond kBrickBonds[] = {Bond::running, Bond::english, Bond::flemish, Bond::header, Bond::stack};

std::string unseen(const std::string& name) {
    return std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/unseen/" + name + ".svg";
}

bool arch_cell(const Cell& c) {
    return c.generator == "arch_stones" || c.generator == "arch_bricks";
}

std::string joined(const std::vector<std::string>& labels) {
    std::string s;
    for (const std::string& l : labels) s += (s.empty() ? "" : " ") + l;
    return s;
}

Point centroid(const std::vector<Point>& p) {
    double a = 0, x = 0, y = 0;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
        const double cr = p[j].x * p[i].y - p[i].x * p[j].y;
        a += cr, x += (p[j].x + p[i].x) * cr, y += (p[j].y + p[i].y) * cr;
    }
    return {x / (3 * a), y / (3 * a)};
}

// A ring stone's width at the intrados: the chord between its points on the intrados circle of
// any of `arcs` (a keystone lies on two).
double intrados_width(const Cell& c, const std::vector<const Edge*>& arcs, double mortar) {
    std::vector<Point> in;
    for (const Edge* e : arcs) {
        const Segment& sg = e->segments.front();
        for (Point p : c.polygon)
            if (std::abs(std::hypot(p.x - sg.center.x, p.y - sg.center.y) - sg.radius) <
                0.75 * mortar)
                in.push_back(p);
    }
    double w = 0;
    for (Point a : in)
        for (Point b : in) w = std::max(w, std::hypot(a.x - b.x, a.y - b.y));
    return w;
}

// What the mason's checker does not read: each arch's ring (its cells grouped by the opening's
// labels) odd, symmetrical about the opening's axis, its pointed keystone wide at the intrados;
// whole bricks not larger than nominal.
struct ArchReport {
    long rings = 0, rings_even = 0;
    long ring_cells = 0, asymmetric = 0;
    long keystones = 0, knife_keystones = 0;
    long stretched = 0;  // coursed bricks over a stretcher's length or height by more than 1 mm
    std::vector<std::string> faults;
};

ArchReport arch_check(const Facade& f, const std::vector<Cell>& cells, const MasonSpec& s,
                      bool symmetric_drawing = true) {
    ArchReport r;
    // Each opening's box, by its labels: the axis a symmetrical arch is set out about.
    std::map<std::string, Rect> box;
    for (const Edge& e : f.edges()) {
        if (!e.opening) continue;
        auto [it, fresh] = box.try_emplace(joined(e.labels), e.bounds);
        if (fresh) continue;
        Rect& b = it->second;
        b = {std::min(b.x0, e.bounds.x0), std::min(b.y0, e.bounds.y0), std::max(b.x1, e.bounds.x1),
             std::max(b.y1, e.bounds.y1)};
    }
    auto is_apex = [&](int corner) {
        const Corner& k = f.corners()[static_cast<std::size_t>(corner)];
        return k.edge_in >= 0 && k.edge_out >= 0 &&
               f.edges()[static_cast<std::size_t>(k.edge_in)].arc &&
               f.edges()[static_cast<std::size_t>(k.edge_out)].arc;
    };
    std::map<std::string, std::vector<const Cell*>> rings;  // voussoirs and keystones
    for (const Cell& c : cells) {
        if (!arch_cell(c) || c.feature_index < 0) continue;
        std::string name;
        if (c.feature == FeatureKind::edge) {
            const Edge& e = f.edges()[static_cast<std::size_t>(c.feature_index)];
            if (!e.opening) continue;
            name = joined(e.labels);
            rings[name].push_back(&c);
        } else if (c.feature == FeatureKind::corner) {
            const Corner& k = f.corners()[static_cast<std::size_t>(c.feature_index)];
            if (!k.opening) continue;
            name = joined(k.labels);
            if (is_apex(c.feature_index)) {
                rings[name].push_back(&c);
                ++r.keystones;
            } else {
                continue;  // a skewback: its outer side steps with the bond, either side its own
            }
        } else {
            continue;
        }
    }
    // A pointed arch's keystone has real width at the intrados: no narrower there than the
    // narrowest voussoir of its ring (a knife edge is none).
    for (const auto& [name, ring] : rings) {
        double narrowest = 1e300;
        for (const Cell* c : ring)
            if (c->feature == FeatureKind::edge)
                narrowest = std::min(
                    narrowest,
                    intrados_width(*c, {&f.edges()[static_cast<std::size_t>(c->feature_index)]},
                                   s.mortar));
        for (const Cell* c : ring) {
            if (c->feature != FeatureKind::corner) continue;
            const Corner& k = f.corners()[static_cast<std::size_t>(c->feature_index)];
            const double w = intrados_width(*c,
                                            {&f.edges()[static_cast<std::size_t>(k.edge_in)],
                                             &f.edges()[static_cast<std::size_t>(k.edge_out)]},
                                            s.mortar);
            if (w < 0.9 * narrowest || w < 0.25 * s.height) {
                ++r.knife_keystones;
                r.faults.push_back(name + ": keystone " + std::to_string(w) +
                                   " wide at the intrados, voussoirs " + std::to_string(narrowest));
            }
        }
    }
    for (const auto& [name, ring] : rings) {
        ++r.rings;
        if (ring.size() % 2 == 0) {
            ++r.rings_even;
            r.faults.push_back(name + ": a ring of " + std::to_string(ring.size()) + " stones");
        }
    }
    if (symmetric_drawing)
        for (const auto& [name, ring] : rings) {
            const double axis = box.count(name) ? box.at(name).center().x : 0;
            for (const Cell* c : ring) {
                ++r.ring_cells;
                const Point p = centroid(c->polygon);
                const Point m{2 * axis - p.x, p.y};
                const double a = acanthus::cells::detail::area_of(c->polygon);
                bool mirrored = false;
                for (const Cell* d : ring) {
                    const Point q = centroid(d->polygon);
                    const double b = acanthus::cells::detail::area_of(d->polygon);
                    mirrored |= std::hypot(q.x - m.x, q.y - m.y) < 0.3 * s.mortar &&
                                std::abs(a - b) < 0.05 * std::max(a, b);
                }
                if (!mirrored) {
                    ++r.asymmetric;
                    r.faults.push_back(name + ": no stone mirrors the one at (" +
                                       std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
                }
            }
        }
    // No unit larger than the brick: a piece longer than a stretcher, or taller than a course's
    // brick, was stretched (a piece between a header and a stretcher is a bat cut from a brick).
    if (!s.stone) {
        for (const Cell& c : cells) {
            Rect b;
            if (!mason_detail::coursed(c) || !mason_detail::is_rect(c.polygon, b)) continue;
            const double w = b.width(), h = b.height();
            if (std::abs(h - s.height) > 0.12 * s.height) continue;
            const bool long_ = w > s.length + s.tolerance / 3 + 1e-6 && w < 1.12 * s.length;
            if (long_ || h > s.height + s.tolerance / 3 + 1e-6) {
                ++r.stretched;
                r.faults.push_back(c.generator + " piece " + std::to_string(w) + " x " +
                                   std::to_string(h) + " at (" + std::to_string(b.x0) + ", " +
                                   std::to_string(b.y0) + ")");
            }
        }
    }
    return r;
}

// What the check finds and this side does not own, allowed by name so that anything more fails.
// Shaved bricks: pieces within 12% of a stretcher's or header's length but more than 1 mm off
// it, in whole courses. Every one is a brick of the bond cut where a jamb or the wall's end
// falls between its head joints (the course's joints are not moved to bring the jamb onto one,
// nor a closer laid): on the wide opening the bricks tree cuts 10.7 cm headers along the cart
// door's right jamb and 19.9 cm stretchers along the first window's, the framed tree its jamb
// quoins to 19.5-20.5 cm on the gable. The most of any bond and tree at seed 1, per facade.
// Odd pieces (the mason's rule: a whole brick, a header or a standard bat or closer, within
// 1 mm): the same cut, read on every piece with plumb ends, not only those near a brick's
// length; 94% of them bricks and quoins cut at a jamb that falls between head joints, in every
// course beside it.
struct Known {
    long cut_courses = 1, courses_off_gauge = 0;
    double height_deviation = 0;
    long four_way_per_1000 = 10, stones_on_end = 0, unit_square_runs = 0;
    long shaved_bricks = 0;
    long odd_pieces = 0, joints_off = 0;
    long unforced_odd = 0;  // odd pieces the geometry does not force (mason_check.hpp)
};
Known known(const std::string& name, bool stone) {
    Known k;
    if (stone) return k;
    // Seed 1, perpends set out from the jambs, the bricks at them flush (before: shaved 60, 33,
    // 56, 7, 10, 39, 22; odd 94, 71, 182, 58, 35, 121, 85). Arched jambs set out too: the
    // segmental ends shaved 33 -> 18, odd 71 -> 41, not forced 51 -> 20; the door past the end
    // 8 -> 10, 32 -> 35, 17 -> 19, mended to 17 not forced (the set-out without arched jambs
    // kept where it leaves fewer: the door's jamb had cost the lines the hatch's; its odd pieces
    // stay 35, the extra ones in runs the geometry forces). The oculus under the
    // top and the off-gauge heads have piers whose head joints cannot take up their jambs'
    // difference with the bricks flush at both. The lancet over an arcade and the narrow pier: made
    // up later, at the most of any bond and tree (their jambs fall anywhere between quarter
    // bricks).
    // Run ends at jambs laid again with whole bricks and standard closers (fit_run_ends): shaved
    // 31 -> 9, 18 -> 17, 20 -> 15, 17 -> 9, 10 -> 8, 21 -> 10, 18 -> 14; odd pieces on the
    // oculus under the top 44 -> 42, not forced 35 -> 28; the segmental ends not forced 20 -> 12.
    // Taken again until a round lays nothing more: segmental ends 17 -> 10, oculus 9 -> 8.
    // A pier's far quoin cut where both cannot be whole, joints a quarter brick apart taking up
    // millimetres: 9 -> 0, 10 -> 5, 15 -> 6, 8 -> 2, 8 -> 6, 10 -> 4, 14 -> 0.
    static const std::map<std::string, long> shaved{
        {"gable-pointed-end", 0}, {"segmental-ends", 5}, {"wide-opening", 6},
        {"oculus-top", 2},        {"door-past-end", 6},  {"ashlar-arches", 4},
        {"off-gauge-heads", 0},   {"lancet-arcade", 61}, {"narrow-pier", 22}};
    static const std::map<std::string, long> odd{
        {"gable-pointed-end", 65}, {"segmental-ends", 41}, {"wide-opening", 142},
        {"oculus-top", 42},        {"door-past-end", 35},  {"ashlar-arches", 101},
        {"off-gauge-heads", 57},   {"lancet-arcade", 171}, {"narrow-pier", 107}};
    if (auto it = shaved.find(name); it != shaved.end()) k.shaved_bricks = it->second;
    if (auto it = odd.find(name); it != odd.end()) k.odd_pieces = it->second;
    // Of those, not forced by the geometry: runs of whole quarters between jambs the plumb unit
    // lines miss (docs/stdlib/cells.md, Limitations).
    static const std::map<std::string, long> unforced{
        {"gable-pointed-end", 17}, {"segmental-ends", 12}, {"wide-opening", 19},
        {"oculus-top", 28},        {"door-past-end", 17},  {"ashlar-arches", 47},
        {"off-gauge-heads", 29},   {"lancet-arcade", 119}, {"narrow-pier", 27}};
    if (auto it = unforced.find(name); it != unforced.end()) k.unforced_odd = it->second;
    return k;
}

// Every rule of the check on one laid wall; the faults found, empty when it passes.
std::vector<std::string> faults(const Facade& f, const std::vector<Cell>& cells, const MasonSpec& s,
                                MasonReport* out = nullptr, const Known& k = Known{}) {
    const MasonReport m = mason_check(f, cells, s);
    const ArchReport a = arch_check(f, cells, s);
    std::vector<std::string> v = a.faults;
    auto fault = [&](bool bad, const std::string& what) {
        if (bad) v.push_back(what);
    };
    fault(m.slivers > 0, std::to_string(m.slivers) + " pieces under 10% of a brick face");
    std::string clipped;
    for (Point p : m.clipped_at)
        clipped += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
    fault(m.voussoirs_clipped > 0,
          std::to_string(m.voussoirs_clipped) + " voussoirs clipped, off their arcs at" + clipped);
    fault(m.crowns_open > 0, std::to_string(m.crowns_open) + " crowns without a key");
    fault(m.openings_without_head > 0,
          std::to_string(m.openings_without_head) + " openings without a head");
    if (!s.stone) {
        fault(m.height_deviation > std::max(s.tolerance / 3, k.height_deviation) + 1e-9,
              "a whole brick " + std::to_string(m.height_deviation) + " off its height");
        fault(m.courses_off_gauge > k.courses_off_gauge,
              std::to_string(m.courses_off_gauge) + " courses off gauge (max " +
                  std::to_string(m.gauge_deviation) + ")");
        fault(m.cut_courses > k.cut_courses, std::to_string(m.cut_courses) + " cut courses");
        fault(m.shaved_bricks > k.shaved_bricks, std::to_string(m.shaved_bricks) +
                                                     " bricks shaved (off nominal by up to " +
                                                     std::to_string(m.length_deviation) + ")");
        fault(m.odd_pieces > k.odd_pieces,
              std::to_string(m.odd_pieces) + " pieces neither a brick nor a standard bat");
        if (m.odd_pieces > k.odd_pieces)
            for (const std::string& p : m.odd) v.push_back("  " + p);
        fault(m.unforced_odd > k.unforced_odd,
              std::to_string(m.unforced_odd) + " odd pieces the geometry does not force");
        if (m.unforced_odd > k.unforced_odd)
            for (const std::string& p : m.unforced) v.push_back("  " + p);
        fault(m.joints_off > k.joints_off, std::to_string(m.joints_off) +
                                               " head joints off by up to " +
                                               std::to_string(m.joint_deviation));
    } else {
        std::string at;
        for (Point p : m.four_way_at)
            at += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
        fault(m.four_way * 1000 > m.stones * k.four_way_per_1000,
              std::to_string(m.four_way) + " four-way joints in " + std::to_string(m.stones) +
                  " at" + at);
        fault(m.unit_square_runs > k.unit_square_runs,
              std::to_string(m.unit_square_runs) + " runs of unit squares");
        std::string on_end;
        for (Point p : m.on_end_at)
            on_end += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
        fault(m.stones_on_end > k.stones_on_end,
              std::to_string(m.stones_on_end) + " stones on end at" + on_end);
    }
    if (out) *out = m;
    return v;
}

std::string list(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size() && i < 12; ++i) s += "\n  " + v[i];
    if (v.size() > 12) s += "\n  ... " + std::to_string(v.size() - 12) + " more";
    return s;
}

const char* const kBrickFacades[] = {"gable-pointed-end", "segmental-ends", "wide-opening",
                                     "oculus-top",        "door-past-end",  "ashlar-arches",
                                     "off-gauge-heads"};

// Lays unseen facade `name` in every brick bond and tree at seed 1 and calls
// `check(bond, tree_name, report, faults)` on each wall.
template <class Check>
void each_brick_wall(const std::string& name, const Known& caps, Check&& check) {
    const Facade f = Facade::from_svg_file(unseen(name));
    Options o = centimetres();
    for (Bond bond : kBrickBonds)
        for (const auto& [tree_name, tree] : mason_trees()) {
            o.bond = bond;
            const Texture t = texture(f, tree, o, 1);
            MasonReport m;
            const std::vector<std::string> v = faults(f, t.cells, kCm, &m, caps);
            check(bond, tree_name, m, v);
        }
}

template <class Check>
void each_brick_wall(const std::string& name, Check&& check) {
    each_brick_wall(name, known(name, false), std::forward<Check>(check));
}

}  // namespace

// Brick walls: every unseen facade x every bond x every tree.
TEST(CellsUnseen, BrickWalls) {
    long straight = 0, compared = 0;
    for (const char* name : kBrickFacades) {
        each_brick_wall(name, [&](Bond bond, const std::string& tree_name, const MasonReport& m,
                                  const std::vector<std::string>& v) {
            std::cout << name << " " << to_string(bond) << " " << tree_name << ": " << m << "\n";
            EXPECT_TRUE(v.empty()) << name << " " << to_string(bond) << " " << tree_name << list(v);
            if (bond != Bond::stack) straight += m.straight_joints, compared += m.head_joints;
        });
    }
    // Not counted here (bonds and closers are checked in test_cells_mason): the straight joints.
    std::cout << "straight joints, all unseen facades, bonds but stack, all trees: " << straight
              << " / " << compared << "\n";
}

// Two facades made up for the jamb check and not tuned on (a terrace of windows on narrow piers,
// a corner shop), every bond and tree: what holds asserted, what the checker finds there capped
// at what it finds at seed 1 (docs/stdlib/cells.md, Limitations). The terrace: 266 odd pieces,
// bricks and quoins cut at jambs between head joints; one cut course (two read before lintels of
// whole courses were read as spanning them). The shop: 143 odd pieces; two cut courses (under the
// top, under the shop window's sill; three read before a lintel on two courses each within the
// tolerance of the gauge was read as spanning them); the
// segmental window's ring, 20 cm from the small window, with one voussoir clipped and its stones
// not mirrored about the axis; bricks over the pointed window's apex, 24 cm under the top, 1.1 mm
// longer than a stretcher. Ashlar: four-way joints and stones on end within the rules over seeds
// 1-12.
TEST(CellsUnseen, NewFacadesForTheJambCheck) {
    struct Caps {
        long odd, shaved, joints_off, cut_courses, clipped, unforced;
    };
    // Odd pieces were 266 and 144 before perpends were set out from the jambs; shaved bricks 87
    // and 32 (of the odd pieces, more now fall within 12% of a brick's length). The terrace's
    // narrow piers: few of their jambs are reached with the bricks flush at both.
    // Run ends laid again with whole bricks and closers (fit_run_ends): shaved 114 -> 87 and
    // 33 -> 24, the terrace's not forced 96 -> 88; taken again until a round lays nothing more:
    // the terrace's not forced 88 -> 87. A pier's far quoin cut where both cannot be whole,
    // joints a quarter brick apart taking up millimetres: shaved 87 -> 20 and 24 -> 1.
    const std::map<std::string, Caps> caps{{"terrace-piers", {247, 20, 0, 1, 0, 87}},
                                           {"shop-corner", {116, 1, 0, 2, 0, 18}}};
    Options o = centimetres();
    for (const auto& [name, cap] : caps) {
        const Facade f = Facade::from_svg_file(unseen(name));
        for (Bond bond : kBrickBonds)
            for (const auto& [tree_name, tree] : mason_trees()) {
                o.bond = bond;
                const Texture t = texture(f, tree, o, 1);
                const MasonReport m = mason_check(f, t.cells, kCm);
                std::cout << name << " " << to_string(bond) << " " << tree_name << ": " << m
                          << "\n";
                SCOPED_TRACE(name + " " + std::string(to_string(bond)) + " " + tree_name);
                if (bond != Bond::stack) {
                    EXPECT_EQ(m.straight_joints, 0);
                }
                EXPECT_EQ(m.slivers, 0);
                EXPECT_EQ(m.narrow_pieces, 0);
                EXPECT_EQ(m.crowns_open, 0);
                EXPECT_EQ(m.openings_without_head, 0);
                EXPECT_EQ(m.courses_off_gauge, 0);
                EXPECT_EQ(m.king_closers_misplaced, 0);
                EXPECT_LE(m.height_deviation, kCm.tolerance / 3);
                EXPECT_LE(m.odd_pieces, cap.odd);
                EXPECT_LE(m.unforced_odd, cap.unforced);
                EXPECT_LE(m.shaved_bricks, cap.shaved);
                EXPECT_LE(m.joints_off, cap.joints_off);
                EXPECT_LE(m.cut_courses, cap.cut_courses);
                EXPECT_LE(m.voussoirs_clipped, cap.clipped);
                EXPECT_EQ(arch_check(f, t.cells, kCm).rings_even, 0);
            }
        o.bond = Bond::ashlar;
        MasonSpec spec = kCm;
        spec.stone = true;
        for (int seed = 1; seed <= 12; ++seed) {
            const MasonReport m = mason_check(
                f, texture(f, ashlar_tree(), o, static_cast<std::uint64_t>(seed)).cells, spec);
            EXPECT_LE(m.four_way * 100, m.stones) << name << " seed " << seed;
            EXPECT_EQ(m.stones_on_end, 0) << name << " seed " << seed;
        }
    }
}

// Rings close together, on a front made up for it and not tuned on (an oculus 28 cm over a round
// head, two segmental windows 30 cm apart, a flat-headed window 22 cm from one, a pointed window
// 36 cm from the other), every bond and tree and ashlar over seeds 1-12: the rings that would
// meet are half-brick rings, no voussoir clipped, every ring odd and mirrored about its axis.
TEST(CellsUnseen, ArchesClose) {
    const Facade f = Facade::from_svg_file(unseen("arches-close"));
    Options o = centimetres();
    auto ring_faults = [&](const Texture& t, const MasonSpec& spec) {
        const MasonReport m = mason_check(f, t.cells, spec);
        std::vector<std::string> v = arch_check(f, t.cells, spec).faults;
        if (m.voussoirs_clipped > 0)
            v.push_back(std::to_string(m.voussoirs_clipped) + " voussoirs clipped");
        if (m.crowns_open > 0) v.push_back(std::to_string(m.crowns_open) + " crowns without a key");
        if (m.openings_without_head > 0)
            v.push_back(std::to_string(m.openings_without_head) + " openings without a head");
        return v;
    };
    long half_rings = 0;
    for (Bond bond : kBrickBonds)
        for (const auto& [tree_name, tree] : mason_trees()) {
            o.bond = bond;
            const Texture t = texture(f, tree, o, 1);
            const std::vector<std::string> v = ring_faults(t, kCm);
            EXPECT_TRUE(v.empty()) << to_string(bond) << " " << tree_name << list(v);
            if (bond != Bond::stack) {
                EXPECT_EQ(mason_check(f, t.cells, kCm).straight_joints, 0)
                    << to_string(bond) << " " << tree_name;
            }
            // Half-brick rings: voussoirs no deeper than half a brick and its joint.
            for (const Cell& c : t.cells) {
                if (!arch_cell(c) || c.feature != FeatureKind::edge) continue;
                const Segment& sg =
                    f.edges()[static_cast<std::size_t>(c.feature_index)].segments.front();
                double reach = 0;
                for (Point p : c.polygon)
                    reach = std::max(
                        reach,
                        std::abs(std::hypot(p.x - sg.center.x, p.y - sg.center.y) - sg.radius));
                half_rings += reach < 11.3;
            }
        }
    EXPECT_GT(half_rings, 0);
    o.bond = Bond::ashlar;
    MasonSpec spec = kCm;
    spec.stone = true;
    for (int seed = 1; seed <= 12; ++seed) {
        const Texture t = texture(f, ashlar_tree(), o, static_cast<std::uint64_t>(seed));
        const std::vector<std::string> v = ring_faults(t, spec);
        EXPECT_TRUE(v.empty()) << "ashlar seed " << seed << list(v);
    }
}

// Two facades made up later and not tuned on, every rule of the check in every bond and tree
// and in ashlar (seeds 1-3): a lancet whose keystone's level top fell 2.8 mm over a bed joint
// (the header over it was cut to 6.22 cm, read as a brick off its height and a course 2.8 mm
// off gauge, in Flemish and header bond), and a 13.7 cm pier whose quoins left a 2.5 cm sliver
// in every other course (framed tree); and no straight joint: the two lintels whose bearings
// meet over that pier had butted there, their joint under a head joint of the course above
// (framed tree, running bond), and are one lintel over both windows.
TEST(CellsUnseen, KeyCoursedInAndNarrowPier) {
    Options o = centimetres();
    for (const char* name : {"lancet-arcade", "narrow-pier"}) {
        each_brick_wall(name, [&](Bond bond, const std::string& tree_name, const MasonReport& m,
                                  const std::vector<std::string>& v) {
            SCOPED_TRACE(std::string(name) + " " + std::string(to_string(bond)) + " " + tree_name);
            EXPECT_TRUE(v.empty()) << list(v);
            EXPECT_EQ(m.narrow_pieces, 0);
            EXPECT_EQ(m.courses_off_gauge, 0);
            if (bond != Bond::stack) {
                EXPECT_EQ(m.straight_joints, 0);
            }
        });
        const Facade f = Facade::from_svg_file(unseen(name));
        MasonSpec spec = kCm;
        spec.stone = true;
        o.bond = Bond::ashlar;
        for (int seed = 1; seed <= 3; ++seed) {
            const Texture t = texture(f, ashlar_tree(), o, static_cast<std::uint64_t>(seed));
            const std::vector<std::string> v = faults(f, t.cells, spec);
            EXPECT_TRUE(v.empty()) << name << " ashlar seed " << seed << list(v);
        }
    }
}

// Three facades made up after the arched jambs were set out, not tuned on: a gable whose
// segmental window springs 12.3 cm from the wall's end, a shop front with a 4.12 m window, an
// arcade of round heads on 24.7 cm piers. Every rule of the check in every bond and tree, odd
// pieces capped at what seed 1 leaves (the most of any bond and tree).
TEST(CellsUnseen, GableShopArcadeNotTunedOn) {
    struct Caps {
        long odd, shaved, unforced, cut_courses;
    };
    // The shop window's sill and head land on course lines; its lintel, two courses deep and
    // 64% of the wall's width, was read as a cut course (2-3 cut courses here before the checker
    // read lintels of whole courses as spanning them): one cut course, under the top.
    // Two more made up in a later session, not tuned on, caps at what they first measured: a
    // two-storey front whose upper jambs line up with none below (a segmental door, a 1.83 m
    // window, a relieving arch upstairs), a gable with a 2.63 m shop window off gauge, a pointed
    // door 13.6 cm from the end, a segmental window and an oculus.
    // Run ends laid again with whole bricks and closers (fit_run_ends): shaved 27 -> 16,
    // 14 -> 8, 8 -> 7, 36 -> 34; odd 85 -> 78; not forced 42 -> 24, 92 -> 66, 66 -> 65.
    const std::map<std::string, Caps> caps{{"gable-segmental-end", {78, 16, 24, 1}},
                                           {"shopfront-wide", {143, 8, 66, 1}},
                                           {"arcade-piers", {135, 7, 33, 1}},
                                           {"storeys-offset", {163, 34, 65, 1}},
                                           {"gable-shop-pointed", {75, 13, 25, 1}}};
    for (const auto& entry : caps) {
        const std::string& name = entry.first;  // a lambda below captures it
        const Caps& cap = entry.second;
        Known k;
        k.odd_pieces = cap.odd, k.shaved_bricks = cap.shaved, k.unforced_odd = cap.unforced;
        k.cut_courses = cap.cut_courses;
        each_brick_wall(
            name, k,
            [&](Bond bond, const std::string& tree_name, const MasonReport& m,
                const std::vector<std::string>& v) {
                std::cout << name << " " << to_string(bond) << " " << tree_name << ": " << m
                          << "\n";
                SCOPED_TRACE(name + " " + std::string(to_string(bond)) + " " + tree_name);
                EXPECT_TRUE(v.empty()) << list(v);
                EXPECT_EQ(m.narrow_pieces, 0);
                EXPECT_EQ(m.king_closers_misplaced, 0);
                if (bond != Bond::stack) {
                    EXPECT_EQ(m.straight_joints, 0);
                }
            });
    }
}

namespace {

// The unseen facades and two more made up for stone: a gable with a round-headed window between
// two narrow lights and a segmental door near its end, a bay with a wide pointed door near its
// end and windows one over the other.
std::vector<std::string> stone_facades() {
    std::vector<std::string> out;
    for (const char* n : kBrickFacades) out.push_back(unseen(n));
    for (const char* n : {"ashlar-gable-trio", "ashlar-pointed-bay"}) out.push_back(unseen(n));
    return out;
}

// Stone walls: the ashlar tree (the default joint rules) on `files` at seeds 1..`seeds`, each
// wall passing every rule of the check: four-way joints at most 1% over all stones (jamb, sill,
// lintel and corner stones too), no stone on end away from a jamb or the wall's end, no run of
// unit squares, heads and whole voussoirs. Returns the fewest stones a wall had.
long stone_walls(const std::vector<std::string>& files, int seeds, double unit = 0) {
    Options o = centimetres();
    o.bond = Bond::ashlar;
    o.ashlar_unit = unit;
    MasonSpec spec = kCm;
    spec.stone = true;
    spec.stone_unit = unit;
    long fewest = -1;
    for (const std::string& file : files) {
        const Facade f = Facade::from_svg_file(file);
        const std::string name = file.substr(file.rfind('/') + 1);
        long worst_on_end = 0, worst_runs = 0;
        double worst_four_way = 0;
        for (int seed = 1; seed <= seeds; ++seed) {
            const Texture t = texture(f, ashlar_tree(), o, static_cast<std::uint64_t>(seed));
            MasonReport m;
            const std::vector<std::string> v = faults(f, t.cells, spec, &m, known(name, true));
            EXPECT_TRUE(v.empty()) << name << " seed " << seed << list(v);
            worst_on_end = std::max(worst_on_end, m.stones_on_end);
            worst_runs = std::max(worst_runs, m.unit_square_runs);
            worst_four_way = std::max(worst_four_way, 100.0 * m.four_way / m.stones);
            fewest = fewest < 0 ? m.stones : std::min(fewest, m.stones);
        }
        std::cout << name << " ashlar, unit " << unit << ", seeds 1-" << seeds
                  << ": four-way at most " << worst_four_way << "%, on end at most " << worst_on_end
                  << ", unit-square runs at most " << worst_runs << "\n";
    }
    return fewest;
}

}  // namespace

// A brick laid whole against a reveal, its space a few millimetres short, keeps its head joint
// and reaches into the reveal's half joint (it closed the joint beside it to 6.6-6.9 mm, 0.1-0.4
// mm past the tolerance: 11-38 joints on each of these facades).
TEST(CellsUnseen, BrickAtARevealKeepsItsJointWithinTheTolerance) {
    Options o = centimetres();
    const std::string root = std::string(ACANTHUS_SOURCE_DIR);
    for (const std::string& path : {unseen("ashlar-arches"), unseen("terrace-piers"),
                                    root + "/tests/stdlib/cells/facades/chapel.svg",
                                    root + "/tests/stdlib/cells/facades/ashlar-front.svg"}) {
        const Facade f = Facade::from_svg_file(path);
        for (Bond bond : kBrickBonds)
            for (const auto& [tree_name, tree] : mason_trees()) {
                o.bond = bond;
                const MasonReport m = mason_check(f, texture(f, tree, o, 1).cells, kCm);
                std::string at;
                for (Point p : m.joints_off_at)
                    at += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
                EXPECT_EQ(m.joints_off, 0) << path << " " << to_string(bond) << " " << tree_name
                                           << ": off by up to " << m.joint_deviation << " at" << at;
                EXPECT_GT(m.head_joints, 500) << path;
            }
    }
}

TEST(CellsUnseen, AshlarWalls) { EXPECT_GT(stone_walls(stone_facades(), 1), 200); }

// The two fronts made up in a later session (GableShopArcadeNotTunedOn) in stone, seeds 1-6.
TEST(CellsUnseen, AshlarStoreysAndShopGableNotTunedOn) {
    EXPECT_GT(stone_walls({unseen("storeys-offset"), unseen("gable-shop-pointed")}, 6), 200);
}

// Over seeds 1-24 on the unseen facades and the examples: the repairs hold whatever the random
// sizes, with nothing allowed by name.
TEST(CellsUnseen, AshlarWallsOverSeeds) {
    std::vector<std::string> files = stone_facades();
    for (const char* n : {"row-house", "gable", "oculus", "insets"})
        files.push_back(std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/" + n + ".svg");
    EXPECT_GT(stone_walls(files, 24), 100);
}

// The coarser grid of the pictures (15 cm units) held to the same rules, seeds 1-24 on every
// facade, with nothing allowed by name.
TEST(CellsUnseen, AshlarWallsCoarseGrid) {
    std::vector<std::string> files = stone_facades();
    for (const char* n : {"row-house", "gable", "oculus", "insets"})
        files.push_back(std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/" + n + ".svg");
    for (const char* n :
         {"shopfront", "chapel", "terrace", "gable-lancet", "warehouse", "ashlar-front", "mill"})
        files.push_back(std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/" + n +
                        ".svg");
    EXPECT_GT(stone_walls(files, 24, 15), 20);
}

// The repair rounds end: each repair is taken only where it lowers one order of faults (over 1%
// of four-way joints, stones on end, four-way joints, unit squares side by side), so none undoes
// another's. Walls where, at the 15 cm unit, a four-way joint was relaid into a stone on end and
// back, round after round, until the bound of 16 rounds stopped it (the best round then kept),
// and two where that was seen before (insets seed 2, the wide opening seed 15); both units.
TEST(CellsUnseen, AshlarRepairRoundsEnd) {
    const std::string examples = std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/";
    const std::string shop = std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/";
    const std::pair<std::string, int> walls[] = {
        {unseen("gable-pointed-end"), 4}, {unseen("gable-pointed-end"), 9},
        {examples + "gable.svg", 4},      {examples + "insets.svg", 23},
        {shop + "shopfront.svg", 3},      {examples + "insets.svg", 2},
        {unseen("wide-opening"), 15}};
    Options o = centimetres();
    o.bond = Bond::ashlar;
    MasonSpec spec = kCm;
    spec.stone = true;
    for (double unit : {15.0, 0.0})
        for (const auto& [file, seed] : walls) {
            o.ashlar_unit = spec.stone_unit = unit;
            const Facade f = Facade::from_svg_file(file);
            const Texture t = texture(f, ashlar_tree(), o, static_cast<std::uint64_t>(seed));
            SCOPED_TRACE(file + " seed " + std::to_string(seed) + " unit " + std::to_string(unit));
            EXPECT_GT(t.stats.ashlar_rounds, 0);
            EXPECT_LE(t.stats.ashlar_rounds, 16);
            const MasonReport m = mason_check(f, t.cells, spec);
            EXPECT_EQ(m.stones_on_end, 0);
            EXPECT_LE(m.four_way * 100, m.stones);
            EXPECT_EQ(m.unit_square_runs, 0);
        }
}

// Perpends set out from the jambs: a window whose jambs fall 0.95 cm and 1.0 cm off the
// quarter-brick lines from the wall's end, on a wall 0.1 cm off whole bricks. The head joints
// take up the differences (each within the tolerance), so both jambs and the wall's end fall on
// joints and no piece in any course is cut to an odd length (laid from the wall's end, the
// bricks beside both jambs were cut in every course). The brick at each jamb and wall end is
// laid flush with it (a half joint off, as on nominal units), not centred in its opened units.
TEST(CellsUnseen, JambsFallOnJoints) {
    const Facade f = Facade::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 297.1 150\">"
        "<rect id=\"w\" class=\"wall\" width=\"297.1\" height=\"150\"/>"
        "<rect id=\"win\" class=\"window\" x=\"100.3\" y=\"40\" width=\"61.8\" "
        "height=\"75\"/></svg>",
        "jambs.svg");
    Options o = centimetres();
    for (Bond bond : {Bond::running, Bond::english, Bond::flemish, Bond::header})
        for (const auto& [tree_name, tree] : mason_trees()) {
            o.bond = bond;
            const Texture t = texture(f, tree, o, 1);
            const MasonReport m = mason_check(f, t.cells, kCm);
            SCOPED_TRACE(std::string(to_string(bond)) + " " + tree_name);
            std::string odd;
            for (const std::string& p : m.odd) odd += "\n  " + p;
            EXPECT_EQ(m.odd_pieces, 0) << odd;
            EXPECT_EQ(m.straight_joints, 0);
            EXPECT_EQ(m.joints_off, 0) << "up to " << m.joint_deviation;
            EXPECT_EQ(m.narrow_pieces, 0);
            // Within the window's height, bricks near a plumb side stand a half joint off it.
            long flush = 0;
            for (const Cell& c : t.cells) {
                Rect b;
                if (!mason_detail::coursed(c) || !mason_detail::is_rect(c.polygon, b) ||
                    b.y0 < 40 || b.y1 > 115)
                    continue;
                for (double x : {0.0, 100.3, 162.1, 297.1}) {
                    const double off = std::min(std::abs(b.x0 - x), std::abs(b.x1 - x));
                    if (off > 2 * kCm.mortar) continue;
                    EXPECT_NEAR(off, kCm.mortar / 2, 1e-6)
                        << "brick at x " << b.x0 << ".." << b.x1 << ", y " << b.y0 << " by x " << x;
                    ++flush;
                }
            }
            EXPECT_GT(flush, 30);
        }
}

// A wall w x h with one window (x0, y0, x1, y1), drawn as an author draws it.
Facade one_window(double w, double h, Rect win, const std::string& name) {
    auto n = [](double v) { return std::to_string(v); };
    return Facade::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + n(w) + " " + n(h) +
            "\"><rect id=\"w\" class=\"wall\" width=\"" + n(w) + "\" height=\"" + n(h) +
            "\"/><rect id=\"win\" class=\"window\" x=\"" + n(win.x0) + "\" y=\"" + n(win.y0) +
            "\" width=\"" + n(win.width()) + "\" height=\"" + n(win.height()) + "\"/></svg>",
        name);
}

// A pier laid from its own jambs: a 120 cm window (21 1/3 quarter bricks, more than its head
// joints can take up) between two piers of 90 cm (16 quarters). Plumb unit lines reach the left
// pier's jambs and the wall's right end, not the window's right jamb, so the right pier was cut
// at that jamb in all 10 of its courses (an odd piece where whole bricks fit). Laid from its
// jambs: in stack bond one is left (the course the head falls within), in running bond six (the
// courses whose joints would come within a quarter brick of those over and under the window
// keep their units); the bricks at the jamb stand a half joint off it.
TEST(CellsUnseen, PierLaidFromItsJambs) {
    const Facade f = one_window(300, 150, {90, 40, 210, 115}, "pier.svg");
    for (Bond bond : {Bond::running, Bond::stack}) {
        SCOPED_TRACE(to_string(bond));
        Options o = centimetres();
        o.bond = bond;
        const std::vector<Cell> cells = texture(f, brick_tree(), o, 1).cells;
        const MasonReport m = mason_check(f, cells, kCm);
        const long left = bond == Bond::stack ? 1 : 6;
        EXPECT_LE(m.unforced_odd, left) << list(m.unforced);
        EXPECT_EQ(m.joints_off, 0) << "up to " << m.joint_deviation;
        EXPECT_EQ(m.narrow_pieces, 0);
        if (bond != Bond::stack) {
            EXPECT_EQ(m.straight_joints, 0);
        }
        long beside = 0, odd = 0;
        for (const Cell& c : cells) {
            Rect b;
            if (!mason_detail::coursed(c) || !mason_detail::is_rect(c.polygon, b) || b.y0 < 40 ||
                b.y1 > 115 || b.x1 < 210 || b.x0 > 300)
                continue;
            const double q = (kCm.length + kCm.mortar) / 4;
            const double k = std::round((b.width() + kCm.mortar) / q);
            odd += std::abs(b.width() - (k * q - kCm.mortar)) > kCm.tolerance / 3;
            if (std::abs(b.x0 - 210) < 2 * kCm.mortar) {
                EXPECT_NEAR(b.x0, 210 + kCm.mortar / 2, 1e-6);
                ++beside;
            }
        }
        EXPECT_LE(odd, left);
        EXPECT_GE(beside, 8);
    }
}

// A level top 2.2 cm past whole courses over a window head: one cut course under it, not two,
// the whole courses below closing their joints (within the tolerance) so it is half a course.
TEST(CellsUnseen, OneCutCourseUnderTheTop) {
    const Facade f = one_window(300, 200, {100, 47.2, 160, 107.2}, "top.svg");
    Options o = centimetres();
    for (Bond bond : {Bond::running, Bond::flemish}) {
        o.bond = bond;
        const Texture t = texture(f, brick_tree(), o, 1);
        const MasonReport m = mason_check(f, t.cells, kCm);
        EXPECT_EQ(m.cut_courses, 1) << m;
        EXPECT_EQ(m.courses_off_gauge, 0) << m;
        double lowest_top = 1e9;  // the cut course's bricks, along the top
        for (const Cell& c : t.cells) {
            Rect b;
            if (mason_detail::coursed(c) && mason_detail::is_rect(c.polygon, b) && b.y0 < 1)
                lowest_top = std::min(lowest_top, b.height());
        }
        EXPECT_GE(lowest_top, (6.5 + 1) / 2 - 1 - 1e-6);  // half a course, less its joint
        EXPECT_LT(lowest_top, 6.5 - 0.3);                 // and cut
    }
}

// Same seed, same bytes: the cells and the cut list of each unseen facade, laid twice.
TEST(CellsUnseen, SameSeedSameBytes) {
    Options o = centimetres();
    for (const char* name : kBrickFacades) {
        const Facade f = Facade::from_svg_file(unseen(name));
        for (Bond bond : {Bond::flemish, Bond::ashlar}) {
            o.bond = bond;
            const Node tree = bond == Bond::ashlar ? ashlar_tree() : framed_tree();
            const Texture a = texture(f, tree, o, 11), b = texture(f, tree, o, 11);
            ASSERT_EQ(a.cells.size(), b.cells.size()) << name;
            for (std::size_t i = 0; i < a.cells.size(); ++i) {
                ASSERT_EQ(a.cells[i].polygon.size(), b.cells[i].polygon.size());
                for (std::size_t j = 0; j < a.cells[i].polygon.size(); ++j) {
                    EXPECT_EQ(a.cells[i].polygon[j].x, b.cells[i].polygon[j].x);
                    EXPECT_EQ(a.cells[i].polygon[j].y, b.cells[i].polygon[j].y);
                }
                EXPECT_EQ(a.cells[i].generator, b.cells[i].generator);
            }
            EXPECT_EQ(cut_list_csv(cut_list(f, a.cells, o, 10)),
                      cut_list_csv(cut_list(f, b.cells, o, 10)))
                << name;
        }
    }
}

// A room forces a shaved brick where no way to fill it, in a course and the course over it, with
// pieces no narrower than a queen closer and no straight joint, avoids one.
TEST(MasonCheck, RoomForcesShavedOnlyWhereNoWayAvoidsOne) {
    // Beside a skewback, 10.15 cm reveal to reveal: one piece of 9.15 cm (a header less 1.1 cm);
    // two pieces would need 10.25 cm.
    EXPECT_TRUE(mason_detail::room_forces_shaved(10.15, kCm));
    // A 12.4 cm pier: one piece 11.4 cm, or two whose joint lies 5.1 to 6.3 cm from the reveal
    // in every course, a straight joint over the one below.
    EXPECT_TRUE(mason_detail::room_forces_shaved(12.4, kCm));
    // A header's room, a brick's, a brick and a header's: whole pieces.
    for (double w : {11.25, 22.5, 33.75})
        EXPECT_FALSE(mason_detail::room_forces_shaved(w, kCm)) << w;
    // 22.9 cm: a three-quarter bat and a 5 cm cut, by turns from each reveal.
    EXPECT_FALSE(mason_detail::room_forces_shaved(22.9, kCm));
    // 33.4 cm: two cuts of 16.4 and 15 cm by turns.
    EXPECT_FALSE(mason_detail::room_forces_shaved(33.4, kCm));
    // 16.9 cm: one three-quarter bat a course, no head joint.
    EXPECT_FALSE(mason_detail::room_forces_shaved(16.9, kCm));
    // Wider than two bricks and a header: never taken as forcing.
    EXPECT_FALSE(mason_detail::room_forces_shaved(80, kCm));
}

// The check fails on layouts broken as the issue describes them.
namespace {

// `cells` with the first whole stretcher's right end moved by `dx` (cm): a brick shaved or
// stretched, for the checks that must fail on it.
std::vector<Cell> with_stretcher_end_moved(std::vector<Cell> cells, double dx) {
    for (Cell& cell : cells) {
        Rect b;
        if (cell.generator == "bricks" && mason_detail::is_rect(cell.polygon, b) &&
            std::abs(b.width() - 21.5) < 1e-6) {
            for (Point& p : cell.polygon)
                if (p.x > b.center().x) p.x += dx;
            break;
        }
    }
    return cells;
}

}  // namespace

TEST(CellsUnseen, FailsOnBrokenLayouts) {
    Options o = centimetres();
    o.bond = Bond::flemish;
    const Facade f = Facade::from_svg_file(unseen("gable-pointed-end"));
    const Texture t = texture(f, brick_tree(), o, 1);
    const Known k = known("gable-pointed-end", false);
    ASSERT_TRUE(faults(f, t.cells, kCm, nullptr, k).empty())
        << list(faults(f, t.cells, kCm, nullptr, k));
    // A shaved brick: a stretcher drawn 2 mm short, one more than the wall has.
    {
        const std::vector<Cell> c = with_stretcher_end_moved(t.cells, -0.2);
        Known tight = k;
        tight.shaved_bricks = mason_check(f, t.cells, kCm).shaved_bricks;
        EXPECT_TRUE(faults(f, t.cells, kCm, nullptr, tight).empty());
        EXPECT_FALSE(faults(f, c, kCm, nullptr, tight).empty());
    }
    // An odd piece: a whole stretcher cut to 12 cm, no bat of any standard length; and a head
    // joint opened to 14 mm, its brick moved 4 mm along the course.
    {
        const MasonReport before = mason_check(f, t.cells, kCm);
        Known tight = k;
        tight.odd_pieces = before.odd_pieces;
        ASSERT_EQ(before.joints_off, 0);
        std::vector<Cell> cut = t.cells, moved = t.cells;
        for (std::size_t i = 0; i < cut.size(); ++i) {
            Rect b;
            if (cut[i].generator != "bricks" || !mason_detail::is_rect(cut[i].polygon, b) ||
                std::abs(b.width() - 21.5) > 1e-6 || b.x0 < 100)
                continue;
            for (Point& p : cut[i].polygon)
                if (p.x > b.center().x) p.x = b.x0 + 12;
            for (Point& p : moved[i].polygon) p.x += 0.4;
            break;
        }
        EXPECT_EQ(mason_check(f, cut, kCm).odd_pieces, before.odd_pieces + 1);
        EXPECT_FALSE(faults(f, cut, kCm, nullptr, tight).empty());
        EXPECT_GE(mason_check(f, moved, kCm).joints_off, 1);
        EXPECT_FALSE(faults(f, moved, kCm, nullptr, tight).empty());
    }
    // Odd pieces the geometry does not force: a whole stretcher split into pieces of 12 and 8.5
    // cm with a joint between, in a course whose run fits whole bricks as before.
    {
        const MasonReport before = mason_check(f, t.cells, kCm);
        Known tight = k;
        tight.odd_pieces = before.odd_pieces + 2;
        tight.unforced_odd = before.unforced_odd;
        ASSERT_TRUE(faults(f, t.cells, kCm, nullptr, tight).empty());
        std::vector<Cell> split = t.cells;
        for (std::size_t i = 0; i < split.size(); ++i) {
            Rect b;
            if (split[i].generator != "bricks" || !mason_detail::is_rect(split[i].polygon, b) ||
                std::abs(b.width() - 21.5) > 1e-6 || b.x0 < 100)
                continue;
            Cell rest = split[i];
            for (Point& p : split[i].polygon)
                if (p.x > b.center().x) p.x = b.x0 + 12;
            for (Point& p : rest.polygon)
                if (p.x < b.center().x) p.x = b.x0 + 13;
            split.push_back(rest);
            break;
        }
        const MasonReport after = mason_check(f, split, kCm);
        EXPECT_EQ(after.odd_pieces, before.odd_pieces + 2);
        EXPECT_GE(after.unforced_odd, before.unforced_odd + 1);
        EXPECT_FALSE(faults(f, split, kCm, nullptr, tight).empty());
    }
    // A stretched brick: a stretcher drawn 2 mm long.
    {
        const std::vector<Cell> c = with_stretcher_end_moved(t.cells, 0.2);
        EXPECT_EQ(arch_check(f, c, kCm).stretched, 1);
        EXPECT_FALSE(faults(f, c, kCm, nullptr, k).empty());
    }
    // The pointed window's keystone taken out: an even ring and an open crown.
    {
        std::vector<Cell> c = t.cells;
        long before = arch_check(f, c, kCm).keystones;
        ASSERT_EQ(before, 1);  // the window's: the door is flat, the eye round
        std::erase_if(c, [&](const Cell& cell) {
            return arch_cell(cell) && cell.feature == FeatureKind::corner &&
                   f.corners()[static_cast<std::size_t>(cell.feature_index)].edge_in >= 0 &&
                   f.edges()[static_cast<std::size_t>(
                                 f.corners()[static_cast<std::size_t>(cell.feature_index)].edge_in)]
                       .arc &&
                   f
                       .edges()[static_cast<std::size_t>(
                           f.corners()[static_cast<std::size_t>(cell.feature_index)].edge_out)]
                       .arc;
        });
        const ArchReport a = arch_check(f, c, kCm);
        EXPECT_GE(a.rings_even, 1);
        EXPECT_GE(mason_check(f, c, kCm).crowns_open, 1);
    }
    // A keystone cut to a knife edge at the intrados: its intrados points pulled to the apex.
    {
        std::vector<Cell> c = t.cells;
        for (Cell& cell : c) {
            if (!arch_cell(cell) || cell.feature != FeatureKind::corner) continue;
            const Corner& k = f.corners()[static_cast<std::size_t>(cell.feature_index)];
            if (k.edge_in < 0 || k.edge_out < 0 ||
                !f.edges()[static_cast<std::size_t>(k.edge_in)].arc ||
                !f.edges()[static_cast<std::size_t>(k.edge_out)].arc)
                continue;
            for (Point& p : cell.polygon)
                if (std::hypot(p.x - k.position.x, p.y - k.position.y) < 10)
                    p = k.position + (p - k.position) * 0.1;
        }
        EXPECT_GE(arch_check(f, c, kCm).knife_keystones, 1);
    }
    // A ring turned by a tenth of a stone about its centre: no longer symmetrical.
    {
        std::vector<Cell> c = t.cells;
        const Edge* eye = nullptr;  // the round window's (a circle, read as one or two arcs)
        for (const Edge& e : f.edges())
            if (e.arc && e.labels.back() == "eye") eye = &e;
        ASSERT_NE(eye, nullptr);
        const Point o2 = eye->segments.front().center;
        const double turn = 0.02, cs = std::cos(turn), sn = std::sin(turn);
        for (Cell& cell : c)
            if (arch_cell(cell) && cell.feature == FeatureKind::edge &&
                f.edges()[static_cast<std::size_t>(cell.feature_index)].labels.back() == "eye")
                for (Point& p : cell.polygon)
                    p = {o2.x + (p.x - o2.x) * cs - (p.y - o2.y) * sn,
                         o2.y + (p.x - o2.x) * sn + (p.y - o2.y) * cs};
        EXPECT_GT(arch_check(f, c, kCm).asymmetric, 2);
    }
    // A voussoir notched by the walling, and four stones meeting at a point in an ashlar wall.
    {
        std::vector<Cell> c = t.cells;
        for (Cell& cell : c)
            if (arch_cell(cell) && cell.feature == FeatureKind::edge) {
                Point a = cell.polygon[0], b = cell.polygon[1];
                cell.polygon.insert(cell.polygon.begin() + 1,
                                    midpoint(a, b) + (b - a).perp() * 0.3);
                break;
            }
        EXPECT_FALSE(faults(f, c, kCm, nullptr, k).empty());
    }
}

// Bad facades are refused with InputError naming the shapes, before any cell is laid.
TEST(CellsUnseen, BadFacadesRefused) {
    auto refused = [](const std::string& body, const std::vector<std::string>& names,
                      bool lay = false) {
        const std::string svg =
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 800 600\">" + body + "</svg>";
        try {
            const Facade f = Facade::from_svg_string(svg, "bad.svg");
            Options o = centimetres();
            if (lay) o.max_cells = 1000000;
            texture(f, brick_tree(), o, 1);
        } catch (const acanthus::InputError& e) {
            const std::string what = e.what();
            for (const std::string& n : names)
                EXPECT_NE(what.find(n), std::string::npos) << what << " does not name " << n;
            EXPECT_NE(what.find("bad.svg"), std::string::npos) << what;
            return;
        }
        ADD_FAILURE() << "accepted: " << body;
    };
    const std::string wall = "<rect id=\"w\" class=\"wall\" width=\"800\" height=\"600\"/>";
    // Overlapping openings: both named.
    refused(wall +
                "<rect id=\"left\" class=\"window\" x=\"100\" y=\"100\" width=\"90\" "
                "height=\"120\"/><path id=\"round\" class=\"window arch\" d=\"M 170 260 V 180 "
                "A 40 40 0 0 1 250 180 V 260 Z\"/>",
            {"left", "round"});
    // Zero-area shapes: a rect of no width, a circle of no radius, a path along a line.
    refused(wall +
                "<rect id=\"slot\" class=\"window\" x=\"100\" y=\"100\" width=\"0\" "
                "height=\"120\"/>",
            {"slot"});
    refused(wall + "<circle id=\"dot\" class=\"window\" cx=\"300\" cy=\"300\" r=\"0\"/>", {"dot"});
    refused(wall + "<path id=\"flat\" class=\"window\" d=\"M 100 100 L 300 100 Z\"/>", {"flat"});
    // Openings too small to leave in brickwork: a square of a micrometre (it was laid over
    // without a word), a slot narrower than a joint.
    refused(wall +
                "<path id=\"speck\" class=\"window\" d=\"M 100 100 h 0.0001 v 0.0001 h "
                "-0.0001 Z\"/>",
            {"speck"});
    refused(wall +
                "<rect id=\"slit\" class=\"window\" x=\"100\" y=\"100\" width=\"120\" "
                "height=\"0.4\"/>",
            {"slit"});
    // A wall thinner than a course (7.5 cm): a 6 cm strip.
    refused("<rect id=\"coping\" class=\"wall\" width=\"800\" height=\"6\"/>", {"coping"});
    // A wall thinner than a course between openings everywhere: a frame 3 cm wide.
    refused(
        "<path id=\"frame\" class=\"wall\" fill-rule=\"evenodd\" d=\"M 0 0 H 400 V 300 H 0 Z "
        "M 3 3 V 297 H 397 V 3 Z\"/>",
        {"frame"});
    // Too large: a kilometre of wall, refused at once with the estimate.
    const auto t0 = std::chrono::steady_clock::now();
    refused("<rect id=\"km\" class=\"wall\" width=\"100000\" height=\"3000\"/>", {"cells"});
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5);
    // A round-headed door 6 cm from the wall's end: not even a half-brick ring fits beside it.
    refused(wall +
                "<path id=\"squeezed\" class=\"door arch\" d=\"M 6 600 V 480 A 45 45 0 0 1 96 "
                "480 V 600 Z\"/>",
            {"squeezed"});
}

// The ring check takes a stone lintel as it will be laid on the ashlar grid: the round head of
// the docs' small wall, 80 cm from the flat head whose lintel bears one unit past its jambs,
// keeps its brick-deep ring at the pictures' 15 cm unit (it had been turned half-brick against
// the most a lintel may take), over seeds, with no voussoir clipped and no stone on end (the
// wall is too small, 53 stones, for the 1% rule on four-way joints to allow one).
TEST(CellsUnseen, RingBesideAStoneLintelAsLaid) {
    const Facade f =
        Facade::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) + "/docs/stdlib/cells-demo.svg");
    Options o = centimetres();
    o.bond = Bond::ashlar;
    o.ashlar_unit = 15;
    MasonSpec spec = kCm;
    spec.stone = true;
    spec.stone_unit = 15;
    for (int seed = 1; seed <= 6; ++seed) {
        const Texture t = texture(f, ashlar_tree(), o, static_cast<std::uint64_t>(seed));
        double deepest = 0;
        for (const Cell& c : t.cells) {
            if (!arch_cell(c) || c.feature != FeatureKind::edge) continue;
            const Segment& sg =
                f.edges()[static_cast<std::size_t>(c.feature_index)].segments.front();
            for (Point p : c.polygon)
                deepest =
                    std::max(deepest, std::hypot(p.x - sg.center.x, p.y - sg.center.y) - sg.radius);
        }
        EXPECT_GT(deepest, 20) << "seed " << seed << ": the round head's ring is half-brick";
        const MasonReport m = mason_check(f, t.cells, spec);
        EXPECT_EQ(m.voussoirs_clipped, 0) << "seed " << seed;
        EXPECT_EQ(m.crowns_open, 0) << "seed " << seed;
        EXPECT_EQ(m.stones_on_end, 0) << "seed " << seed;
    }
}

// Fresh facades, drawn in session 6 after the library's work on issue 28 and not tuned on
// (tests/stdlib/cells/facades/fresh/): every rule of the check in every bond and tree, odd and
// shaved pieces capped at what seed 1 left when they were first laid (the most of any bond and
// tree).
namespace {

std::string fresh(const std::string& name) {
    return std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/fresh/" + name + ".svg";
}

const char* const kFresh[] = {
    "gable-pointed-20", "gable-pointed-door-end", "segmental-doors-ends", "wide-2600",
    "three-storeys",    "ashlar-oculus",          "narrow-80-door",       "odd-sizes"};

struct Caps {
    long odd, shaved, unforced;
};

// Lays each facade of `caps` (read by `path`) in every brick bond and tree at seed 1 and checks
// every rule of the mason's check on each wall: what it still finds is allowed by the caps.
// Returns the shaved bricks over all walls; `arris_out`, the small pieces at an arris that the
// run does not force.
template <class Path>
long brick_walls(const std::map<std::string, Caps>& caps, Path&& path, long* arris_out = nullptr) {
    Options o = centimetres();
    long straight = 0, compared = 0, walls = 0, shaved = 0, arris = 0;
    for (const auto& [name, cap] : caps) {
        Known k;
        k.odd_pieces = cap.odd, k.shaved_bricks = cap.shaved, k.unforced_odd = cap.unforced;
        const Facade f = Facade::from_svg_file(path(name));
        for (Bond bond : kBrickBonds)
            for (const auto& [tree_name, tree] : mason_trees()) {
                o.bond = bond;
                const Texture t = texture(f, tree, o, 1);
                MasonReport m;
                const std::vector<std::string> v = faults(f, t.cells, kCm, &m, k);
                std::cout << name << " " << to_string(bond) << " " << tree_name << ": " << m
                          << "\n";
                SCOPED_TRACE(name + " " + std::string(to_string(bond)) + " " + tree_name);
                EXPECT_TRUE(v.empty()) << list(v);
                EXPECT_EQ(m.narrow_pieces, 0);
                EXPECT_EQ(m.courses_off_gauge, 0);
                EXPECT_EQ(m.king_closers_misplaced, 0);
                EXPECT_EQ(arch_check(f, t.cells, kCm).stretched, 0);
                EXPECT_EQ(m.soldiers_off, 0) << "up to " << m.soldier_deviation;
                if (bond != Bond::stack) {
                    EXPECT_EQ(m.straight_joints, 0);
                    straight += m.straight_joints, compared += m.head_joints;
                }
                shaved += m.shaved_bricks;
                arris += m.arris_small - m.arris_small_forced;
                ++walls;
            }
    }
    std::cout << walls << " walls: straight joints " << straight << " / " << compared
              << " (bonds but stack), shaved bricks " << shaved
              << ", small pieces at an arris not forced " << arris << "\n";
    if (arris_out) *arris_out = arris;
    return shaved;
}

}  // namespace

TEST(CellsFresh, BrickWalls) {
    // Shaved caps before a pier's far quoin could be the piece cut and the run ends took up
    // millimetres in joints a quarter brick apart: 7, 10, 4, 2, 9, 7, 0, 13. The three-storey
    // front's 9 were 4 before a shaved brick could give way to a cut the geometry does not force.
    const std::map<std::string, Caps> caps{
        {"gable-pointed-20", {70, 0, 28}},     {"gable-pointed-door-end", {72, 3, 39}},
        {"segmental-doors-ends", {72, 4, 28}}, {"wide-2600", {60, 2, 21}},
        {"three-storeys", {187, 4, 66}},       {"ashlar-oculus", {68, 7, 21}},
        {"narrow-80-door", {63, 0, 2}},        {"odd-sizes", {75, 1, 22}}};
    const long shaved = brick_walls(caps, fresh);
    // A run's end at a jamb laid with whole bricks and standard closers, the difference in its
    // joints or one piece cut clear of a brick's and a header's length (fit_run_ends): 1,121
    // shaved bricks over these 120 walls before, 481 after; what is left are piers whose courses
    // a quarter brick apart leave no closer a place clear of the joints over and under it. The
    // pass taken again until a round lays nothing more (a course judged against the one over it
    // before that one was laid again): 422. The courses whose runs end at one jamb decided
    // together, so that a closer in one finds a place where the courses over and under it move
    // their joints too, and up to four pieces from the jamb laid again where a course or one
    // beside it has a shaved brick: 246. A pier's far quoin may be the piece cut (a pier too
    // narrow for two whole quoins): 141. Ways whose joints stand a twentieth of a joint past a
    // quarter brick from those over and under them (not half the tolerance): 128. A shaved brick
    // traded for a cut the geometry does not force where no way keeps both whole: 114. A brick
    // whose units were set out a little short drawn at its nominal length when its corner is cut
    // (a gable's rake), not 1-3 mm short: 76. The runs a segmental arch's skewback cuts laid
    // again to end at its plumb side as at a jamb (fit_run_ends_at): 46; the runs ending at
    // jambs in the courses near it laid again too, the joints under the skewback out of their
    // way: 44. A king closer beside a shaved piece at a jamb laid again with it: 37. A
    // window-bottom row's ends moved a quarter brick where its courses beside the jamb keep a
    // shaved brick, and a jamb that stops a micrometre under a course line (an arch's
    // springing) taken to bound that course: 23.
    EXPECT_LE(shaved, 23);
}

// Beside the three-storey front's windows in header bond, the course over a window-bottom row
// ended at the jamb in a header 0.55 cm long or 0.9 cm short: the row is centred on its
// opening, the courses beside the jamb are bonded to the wall above, and their joints missed
// the row's by less than a quarter brick, so no way at the run's end cleared both. With the
// row's ends moved a quarter brick each (sills_moved_for_shaved) the bricks there are whole and
// the row stays centred. Before: 3 shaved in each tree.
TEST(CellsFresh, SillRowMovedForTheCoursesBesideItsJamb) {
    const Facade f = Facade::from_svg_file(fresh("three-storeys"));
    Options o = centimetres();
    o.bond = Bond::header;
    for (const char* tree_name : {"bricks", "rowlock"}) {
        const MasonReport m =
            mason_check(f, texture(f, mason_trees().at(tree_name), o, 1).cells, kCm);
        EXPECT_EQ(m.shaved_bricks, 0) << tree_name << list(m.shaved);
        EXPECT_EQ(m.straight_joints, 0) << tree_name;
        EXPECT_EQ(m.sills, 6) << tree_name;
        EXPECT_EQ(m.sills_off_centre, 0) << tree_name;
    }
}

// A pier 38.9 cm wide (6.92 quarter bricks) in header bond beside the first floor's windows of
// the three-storey front: its courses are laid again from its jambs bottom first, each judged
// against the courses over and under it as they stood; one judged against a course not yet
// laid again kept its cut piece, whose joint came 5.36 cm (under a quarter brick) from the
// relaid course's: 18 straight joints up the pier. Judged again until none changes, and a joint
// beside a piece that is still to be laid whole against its reveal given the room it may move.
TEST(CellsFresh, HeaderBondPierKeepsItsStagger) {
    const Facade f = Facade::from_svg_file(fresh("three-storeys"));
    Options o = centimetres();
    o.bond = Bond::header;
    for (const auto& [tree_name, tree] : mason_trees()) {
        const MasonReport m = mason_check(f, texture(f, tree, o, 1).cells, kCm);
        std::string at;
        for (Point p : m.straight_at)
            at += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
        EXPECT_EQ(m.straight_joints, 0) << tree_name << " at" << at;
        EXPECT_GT(m.head_joints, 3000) << tree_name;
    }
}

// A pier 38.9 cm wide (6.92 quarter bricks) between the three-storey front's left end and its
// first-floor window, in running bond: set out from its jambs, every other course has a whole
// brick, a half bat and a queen closer, their joints opened 2.6 mm each; the courses between
// them, judged alone, find no closer whose joint clears those, and keep a brick shaved 4 mm.
// Chosen together (fit_run_ends), the relaid courses give way: no brick is shaved in the pier
// but in its top course, whose neighbour over the window's head does not move. Before: 11.
TEST(CellsFresh, PierCoursesChosenTogether) {
    const Facade f = Facade::from_svg_file(fresh("three-storeys"));
    Options o = centimetres();
    o.bond = Bond::running;
    for (const char* tree_name : {"bricks", "rowlock"}) {
        const Texture t = texture(f, mason_trees().at(tree_name), o, 1);
        std::vector<Cell> pier;  // bricks of the pier's courses, the window's sill to its head
        for (const Cell& c : t.cells) {
            Rect b;
            if (mason_detail::is_rect(c.polygon, b) && b.x1 <= 38.9 + 1e-6 && b.y0 >= 486.3 &&
                b.y1 <= 642.1)
                pier.push_back(c);
        }
        EXPECT_GT(pier.size(), 40u) << tree_name;
        const MasonReport m = mason_check(f, pier, kCm);
        EXPECT_LE(m.shaved_bricks, 1) << tree_name << list(m.shaved);
        EXPECT_EQ(m.narrow_pieces, 0) << tree_name;
    }
}

// Beside the right jamb of the three-storey front's segmental window in running bond, every
// other course ended in a header 0.9 cm short (9.36 cm): whole, the difference wants four joints
// of 2.2 mm, which bring a joint within a quarter brick of the courses over and under it; a
// clear cut (14.8 cm) with a queen closer at the jamb and a brick clears them, but the geometry
// does not force that odd piece (more joints could take the difference up), so no way was
// laid. A shaved brick now gives way to such a cut away from a quoin (fit_run_ends).
TEST(CellsFresh, ShavedBrickGivesWayToAClearCut) {
    const Facade f = Facade::from_svg_file(fresh("three-storeys"));
    Options o = centimetres();
    o.bond = Bond::running;
    for (const char* tree_name : {"bricks", "rowlock"}) {
        const Texture t = texture(f, mason_trees().at(tree_name), o, 1);
        std::vector<Cell> column;  // bricks from the jamb 39 cm in, springing to sill
        for (const Cell& c : t.cells) {
            Rect b;
            if (mason_detail::is_rect(c.polygon, b) && b.x0 >= 392.7 && b.x1 <= 432 &&
                b.y0 >= 176 && b.y1 <= 284)
                column.push_back(c);
        }
        EXPECT_GT(column.size(), 20u) << tree_name;
        const MasonReport m = mason_check(f, column, kCm);
        EXPECT_EQ(m.shaved_bricks, 0) << tree_name << list(m.shaved);
        EXPECT_EQ(m.narrow_pieces, 0) << tree_name;
        EXPECT_EQ(m.straight_joints, 0) << tree_name;
    }
    // The whole wall: fewer shaved, no more odd pieces than before (9 and 156).
    const MasonReport all = mason_check(f, texture(f, mason_trees().at("bricks"), o, 1).cells, kCm);
    EXPECT_LE(all.shaved_bricks, 2);
    EXPECT_LE(all.odd_pieces, 156);
}

// The pier between the odd-sizes front's door and the wall's right end, 32.2 cm: too narrow
// for two whole quoins (a brick and a header take 32.75 cm), so every other course holds a
// piece cut. Laid from one jamb to the other with both quoins whole, no way was found and the
// door's quoin stood shaved 1.7 cm in 12 courses in each bond; a mason cuts the far quoin
// clearly instead (a whole brick at the door, the wall's end quoin cut to 8.7 cm, as the
// courses between have a brick at the wall's end and the door's quoin cut to 8.4 cm), which
// fit_run_ends now lays: no shaved brick in the pier.
TEST(CellsFresh, NarrowPierCutsAQuoinNotShavesIt) {
    const Facade f = Facade::from_svg_file(fresh("odd-sizes"));
    Options o = centimetres();
    for (Bond bond : kBrickBonds) {
        o.bond = bond;
        const Texture t = texture(f, mason_trees().at("framed"), o, 1);
        std::vector<Cell> pier;  // the pieces beside the door, its head to the ground
        for (const Cell& c : t.cells) {
            Rect b;
            if (mason_detail::is_rect(c.polygon, b) && b.x0 >= 401.5 - 1e-6 && b.y0 >= 103.3)
                pier.push_back(c);
        }
        EXPECT_GT(pier.size(), 40u) << to_string(bond);
        const MasonReport m = mason_check(f, pier, kCm);
        EXPECT_EQ(m.shaved_bricks, 0) << to_string(bond) << list(m.shaved);
        EXPECT_EQ(m.narrow_pieces, 0) << to_string(bond);
        if (bond != Bond::stack) {
            EXPECT_EQ(m.straight_joints, 0) << to_string(bond);
        }
    }
}

// Same seed, same bytes on the fresh facades: cells and cut list, laid twice.
TEST(CellsFresh, SameSeedSameBytes) {
    Options o = centimetres();
    for (const char* name : kFresh) {
        const Facade f = Facade::from_svg_file(fresh(name));
        for (Bond bond : {Bond::english, Bond::ashlar}) {
            o.bond = bond;
            const Node tree = bond == Bond::ashlar ? ashlar_tree() : brick_tree();
            const Texture a = texture(f, tree, o, 5), b = texture(f, tree, o, 5);
            ASSERT_EQ(a.cells.size(), b.cells.size()) << name;
            for (std::size_t i = 0; i < a.cells.size(); ++i) {
                ASSERT_EQ(a.cells[i].polygon.size(), b.cells[i].polygon.size()) << name;
                for (std::size_t j = 0; j < a.cells[i].polygon.size(); ++j) {
                    EXPECT_EQ(a.cells[i].polygon[j].x, b.cells[i].polygon[j].x);
                    EXPECT_EQ(a.cells[i].polygon[j].y, b.cells[i].polygon[j].y);
                }
            }
            EXPECT_EQ(cut_list_csv(cut_list(f, a.cells, o, 10)),
                      cut_list_csv(cut_list(f, b.cells, o, 10)))
                << name;
        }
    }
}

// Stone walls on the fresh facades, the ashlar tree at the default unit, seeds 1-6.
TEST(CellsFresh, AshlarWalls) {
    std::vector<std::string> files;
    for (const char* n : kFresh) files.push_back(fresh(n));
    EXPECT_GT(stone_walls(files, 6), 50);
}

// The coarser grid of the pictures (15 cm units) on the fresh facades, seeds 1-6, nothing
// allowed by name. The gable's segmental window 31.4 cm from its end: its skewback took all but
// a strip 1.4 cm wide of the unit beside its springing, which the opening reaches into; laid
// alone, the strip stood on end (two a wall, one each side, every seed), now it joins the stone
// beside it, cut to the skewback. The three-storey front: the wall's end and the door's jamb at
// the ground each take a corner stone two units long, which left one unit between them in the
// bottom course (13 x 15.6 cm on this grid) laid as a stone on end, every seed; the left corner
// stone takes it.
TEST(CellsFresh, AshlarWallsCoarseGrid) {
    std::vector<std::string> files;
    for (const char* n : kFresh) files.push_back(fresh(n));
    EXPECT_GT(stone_walls(files, 6, 15), 20);
}

// Bad facades drawn for the fresh check, each refused naming its shapes: two windows that
// overlap by a course, a pointed door whose apex reaches into a round window, one window inside
// another, an ellipse of no height, a polygon along a line, a post 5 cm wide.
TEST(CellsFresh, BadFacadesRefused) {
    auto refused = [](const std::string& body, const std::vector<std::string>& names) {
        const std::string svg =
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 800 600\">" + body + "</svg>";
        try {
            const Facade f = Facade::from_svg_string(svg, "bad.svg");
            texture(f, brick_tree(), centimetres(), 1);
        } catch (const acanthus::InputError& e) {
            const std::string what = e.what();
            for (const std::string& n : names)
                EXPECT_NE(what.find("id=\"" + n + "\""), std::string::npos)
                    << what << " does not name " << n;
            EXPECT_NE(what.find("bad.svg"), std::string::npos) << what;
            return;
        }
        ADD_FAILURE() << "accepted: " << body;
    };
    const std::string wall = "<rect id=\"w\" class=\"wall\" width=\"800\" height=\"600\"/>";
    refused(wall +
                "<rect id=\"over\" class=\"window\" x=\"100\" y=\"100\" width=\"100\" "
                "height=\"100\"/><rect id=\"under\" class=\"window\" x=\"120\" y=\"192.5\" "
                "width=\"60\" height=\"100\"/>",
            {"over", "under"});
    refused(wall +
                "<path id=\"door\" class=\"door arch pointed\" d=\"M 300 600 V 450 A 100 100 0 0 "
                "1 350 363.4 A 100 100 0 0 1 400 450 V 600 Z\"/><circle id=\"eye\" "
                "class=\"window\" cx=\"350\" cy=\"340\" r=\"40\"/>",
            {"door", "eye"});
    refused(wall +
                "<rect id=\"big\" class=\"window\" x=\"100\" y=\"100\" width=\"200\" "
                "height=\"200\"/><rect id=\"small\" class=\"window\" x=\"150\" y=\"150\" "
                "width=\"50\" height=\"50\"/>",
            {"big", "small"});
    refused(wall +
                "<ellipse id=\"flat\" class=\"window\" cx=\"300\" cy=\"300\" rx=\"40\" "
                "ry=\"0\"/>",
            {"flat"});
    refused(wall + "<polygon id=\"line\" class=\"window\" points=\"100,100 200,200 300,300\"/>",
            {"line"});
    refused("<rect id=\"post\" class=\"wall\" width=\"5\" height=\"600\"/>", {"post"});
    // Apart by a joint's width: a pier, accepted.
    const Facade apart = Facade::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 800 600\">" + wall +
            "<rect id=\"a\" class=\"window\" x=\"100\" y=\"100\" width=\"100\" height=\"100\"/>"
            "<rect id=\"b\" class=\"window\" x=\"223.5\" y=\"100\" width=\"100\" "
            "height=\"100\"/></svg>",
        "apart.svg");
    EXPECT_GT(texture(apart, brick_tree(), centimetres(), 1).cells.size(), 100u);
}

// A run's end at the wall's end or a jamb that falls between head joints: the mason takes the
// difference up in the head joints, and beyond that lays a standard closer or one bat cut a
// little, never a brick shaved to fit (fit_run_ends). Walls of widths that are no whole number
// of quarter bricks with a window whose jambs fall between quarters (its left jamb 33.9 or
// 41.3 cm from the wall's left end), every bond and tree at seed 1: 226 shaved bricks over the
// 120 walls before, 78 with run ends laid course by course, 41 with a column's courses decided
// together, 28 with a pier's far quoin cut where both cannot be whole and joints a quarter brick
// apart taking up millimetres (what is left: piers whose courses, a quarter brick apart, leave
// no closer a place clear of the joints over and under it); and still no straight joint, no
// narrow piece, no head joint off, and fewer odd pieces (836 before, 799, 749, now 695).
TEST(CellsFresh, RunEndsTakeUpTheDifferenceInJointsAndClosers) {
    Options o = centimetres();
    long walls = 0, shaved = 0, odd = 0;
    for (double width : {147.37, 169.48, 198.96, 228.44})
        for (double window : {41.3, 33.9}) {
            std::vector<FacadeShape> s;
            s.push_back(shape(rect(0, 0, width, 90), {"wall"}, "w"));
            s.push_back(shape(rect(window, 20, 57.7, 45), {"window"}, "win"));
            const Facade f = Facade::from_shapes(std::move(s), "run-ends.svg");
            for (Bond bond : kBrickBonds)
                for (const auto& [tree_name, tree] : mason_trees()) {
                    o.bond = bond;
                    const MasonReport m = mason_check(f, texture(f, tree, o, 1).cells, kCm);
                    SCOPED_TRACE(std::to_string(width) + " " + std::to_string(window) + " " +
                                 std::string(to_string(bond)) + " " + tree_name);
                    if (bond != Bond::stack) {
                        EXPECT_EQ(m.straight_joints, 0);
                    }
                    EXPECT_EQ(m.narrow_pieces, 0);
                    EXPECT_EQ(m.joints_off, 0);
                    shaved += m.shaved_bricks, odd += m.odd_pieces, ++walls;
                }
        }
    EXPECT_EQ(walls, 8 * 5 * 3);
    std::cout << walls << " walls, shaved bricks " << shaved << ", odd pieces " << odd << "\n";
    // 78 before the pass was taken again until a round lays none more, 41 before a pier's far
    // quoin could be cut and joints a quarter brick apart take up millimetres; 28 and 695 odd
    // pieces before a shaved brick could give way to a cut the geometry does not force; 26 and
    // 678 before the cheapest few ways of each zone were kept for a run's end (two shaved bricks
    // gave way to a closer and a cut); 24 and 680 before a king closer could be laid again with
    // a shaved piece at the jamb.
    EXPECT_LE(shaved, 21);
    EXPECT_LE(odd, 678);
}

namespace {

std::string outside(const std::string& name) {
    return std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/outside/" + name +
           ".svg";
}

const char* const kOutside[] = {
    "gable-steep-segmental", "shop-wide-lancets", "pointed-ends", "segmental-cart", "tower",
    "front-round-ends"};

}  // namespace

// Facades drawn for the outside check of session 10 and not tuned on (facades/outside/): a
// steep gable with a segmental window 14.6 cm from its end, a shop front with a 3.43 m window,
// a drop-pointed window and a lancet near a wall's ends, a coach house with a 1.86 m segmental
// cart door near its end, a tower 213 cm wide, a front with round-headed windows near its ends.
// Found on them first: a voussoir of the drop-pointed window beside its key read as clipped (a
// vertex the booleans left on its radial joint, 6 um off the line; clip.cpp's shrink() now drops
// such vertices). Shaved bricks are what fit_run_ends still leaves (201 over the 90 walls).
TEST(CellsOutside, BrickWalls) {
    const std::map<std::string, Caps> caps{{"gable-steep-segmental", {38, 6, 8}},
                                           {"shop-wide-lancets", {70, 1, 36}},
                                           {"pointed-ends", {80, 1, 46}},
                                           {"segmental-cart", {73, 14, 38}},
                                           {"tower", {118, 0, 1}},
                                           {"front-round-ends", {88, 9, 43}}};
    long arris = 0;
    // 201 before a brick whose units were set out a little short was drawn at its nominal
    // length where a gable's rake cuts its corner, 136 before the runs a skewback cuts were laid
    // again to end at its plumb side (118 before the courses near it were laid again too); 111
    // before the cheapest few ways of each zone were kept for a run's end (the round-ended front
    // in Flemish bond: a stretcher 7 mm short in every other course beside the upper window,
    // now a queen closer at the jamb and a cut).
    // 95 before a king closer beside a shaved piece at a jamb could be laid again with it.
    EXPECT_LE(brick_walls(caps, outside, &arris), 88);
    // Closers and cuts set back from the arrises (fit_arrises): 2,350 before; 437 before the
    // courses beside a skewback were laid again as it is set (three shaved bricks there gave way
    // to a small piece at an arris), 440 before the round-ended front's 16 did, 456 before a
    // king closer could be laid again with a shaved piece at the jamb.
    EXPECT_LE(arris, 449);
}

// Beside a segmental arch's skewback the courses run to its plumb side: each run it cuts is laid
// again to end there as at a jamb (fit_run_ends_at), so the piece against it is cut clear of a
// brick's and a header's length, and the runs ending at jambs in the courses near it are laid
// again with the joints under the skewback out of their way. Four facades with segmental arches
// near a wall's end or a door, the bricks tree in every bond: 34 shaved bricks before, 15 with
// the runs it cuts laid again, 11 with the courses near it too (none where the room between the
// wall's end and the skewback forces one).
TEST(CellsUnseen, RunsEndAtASkewbacksSide) {
    Options o = centimetres();
    long shaved = 0, forced = 0, straight = 0;
    for (const std::string& file :
         {unseen("segmental-ends"), fresh("segmental-doors-ends"),
          std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/warehouse.svg",
          std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/chapel.svg"}) {
        const Facade f = Facade::from_svg_file(file);
        for (Bond b : {Bond::running, Bond::english, Bond::flemish, Bond::header, Bond::stack}) {
            o.bond = b;
            const MasonReport m = mason_check(f, texture(f, brick_tree(), o, 1).cells, kCm);
            shaved += m.shaved_bricks, forced += m.shaved_forced;
            if (b != Bond::stack) straight += m.straight_joints;
        }
    }
    EXPECT_EQ(straight, 0);
    EXPECT_EQ(forced, 0);
    EXPECT_LE(shaved, 11);
}

// The chapel's round-headed window springs at 310 cm, a course line; read from the outline's
// arc, its jamb starts a micrometre under it, and the course under the springing ended at no
// jamb: none of its run ends was laid again, and a header stood 0.9 cm long at the reveal
// (11.18 cm) in every bond but header and stack. Jambs are compared with course lines at the
// outline's precision (jamb_at).
TEST(CellsUnseen, CourseUnderASpringingEndsAtItsJamb) {
    const Facade f = Facade::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) +
                                           "/tests/stdlib/cells/facades/chapel.svg");
    Options o = centimetres();
    for (Bond b : {Bond::running, Bond::english, Bond::flemish}) {
        o.bond = b;
        std::vector<Cell> beside;  // the course under the springing, left of the window
        for (const Cell& c : texture(f, brick_tree(), o, 1).cells) {
            Rect r;
            if (mason_detail::is_rect(c.polygon, r) && r.y0 > 310 && r.y1 < 317.5 && r.x1 < 157.4)
                beside.push_back(c);
        }
        ASSERT_GT(beside.size(), 4u) << to_string(b);
        const MasonReport m = mason_check(f, beside, kCm);
        EXPECT_EQ(m.shaved_bricks, 0) << to_string(b) << list(m.shaved);
        EXPECT_EQ(m.narrow_pieces, 0) << to_string(b);
    }
}

// Stone walls on the same facades: the default unit and the pictures' 15 cm grid, seeds 1-3.
TEST(CellsOutside, AshlarWalls) {
    std::vector<std::string> files;
    for (const char* n : kOutside) files.push_back(outside(n));
    EXPECT_GT(stone_walls(files, 3), 500);
    EXPECT_GT(stone_walls(files, 3, 15), 150);
}

TEST(CellsOutside, SameSeedSameBytes) {
    Options o = centimetres();
    for (const char* name : kOutside) {
        const Facade f = Facade::from_svg_file(outside(name));
        for (Bond bond : {Bond::flemish, Bond::ashlar}) {
            o.bond = bond;
            const Node tree = bond == Bond::ashlar ? ashlar_tree() : brick_tree();
            const Texture a = texture(f, tree, o, 7), b = texture(f, tree, o, 7);
            EXPECT_EQ(cut_list_csv(cut_list(f, a.cells, o, 10)),
                      cut_list_csv(cut_list(f, b.cells, o, 10)))
                << name;
            ASSERT_EQ(a.cells.size(), b.cells.size()) << name;
            for (std::size_t i = 0; i < a.cells.size(); ++i)
                EXPECT_TRUE(a.cells[i].polygon == b.cells[i].polygon) << name << " cell " << i;
        }
    }
}
