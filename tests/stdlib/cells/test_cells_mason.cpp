// The mason's checker: it finds what it should on deliberately broken walls, and it reads every
// example facade in every bond and tree (centimetres, as rules/facade.acr lays them).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <set>

#include "cells_oracle.hpp"
#include "mason_check.hpp"

using namespace cells_test;

namespace {

const MasonSpec kCm{21.5, 6.5, 1, 0.3};

Cell brick(double x0, double y0, double x1, double y1, int course,
           const char* generator = "bricks") {
    const double h = kCm.mortar / 2;
    Cell c;
    c.polygon = {{x0 + h, y0 + h}, {x1 - h, y0 + h}, {x1 - h, y1 - h}, {x0 + h, y1 - h}};
    c.generator = generator;
    c.course = course;
    return c;
}

// Courses of stretchers on a plain wall, each course shifted by `shift`.
std::vector<Cell> stretchers(double shift, int courses, double length = 22.5) {
    std::vector<Cell> cells;
    for (int k = 0; k < courses; ++k) {
        double y1 = 100 - 7.5 * k, y0 = y1 - 7.5;
        double x = k % 2 ? -shift : 0;
        for (; x < 200; x += length)
            if (x + length > 0) cells.push_back(brick(std::max(0.0, x), y0, x + length, y1, k));
    }
    return cells;
}

Facade plain_wall() {
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 200, 100), {"wall"}, "w"));
    return Facade::from_shapes(std::move(s), "plain.svg");
}

}  // namespace

TEST(CellsMason, HalfBrickBondHasNoStraightJoint) {
    MasonReport r = mason_check(plain_wall(), stretchers(11.25, 6), kCm);
    EXPECT_GT(r.head_joints, 30);
    EXPECT_EQ(r.straight_joints, 0);
    EXPECT_NEAR(r.length_deviation, 0, 1e-9);
    EXPECT_EQ(r.courses_off_gauge, 0);
}

TEST(CellsMason, FindsStraightJoints) {
    // Courses shifted by 2 cm: every joint runs on into the next course.
    MasonReport r = mason_check(plain_wall(), stretchers(2, 6), kCm);
    EXPECT_GT(r.straight_joints, 30);
    EXPECT_EQ(r.straight_joints, static_cast<long>(r.straight_at.size()));
}

// The library's rule the straight-joint map draws (head_joints.hpp): each pair is a joint and
// the one right above it, within a quarter brick; a joint moved a quarter brick away is not one.
TEST(CellsMason, StraightJointPairs) {
    using acanthus::cells::straight_joints;
    auto pairs = straight_joints(stretchers(2, 6), kCm.length, kCm.mortar);
    ASSERT_GT(pairs.straight.size(), 30u);
    for (const auto& sj : pairs.straight) {
        EXPECT_LT(std::abs(sj.upper.x - sj.lower.x), kCm.length / 4);
        EXPECT_NEAR(sj.lower.y0 - sj.upper.y1, kCm.mortar, 1e-9);  // the course right above
        EXPECT_NEAR(sj.lower.y1 - sj.lower.y0, kCm.height, 1e-9);
    }
    auto offset = straight_joints(stretchers(22.5 / 4 + 0.01, 6), kCm.length, kCm.mortar);
    EXPECT_GT(offset.compared, 30);
    EXPECT_TRUE(offset.straight.empty());
    // A stone course is not read: ashlar cells are not coursed bricks.
    std::vector<Cell> stones = stretchers(2, 6);
    for (Cell& c : stones) c.generator = "ashlar";
    EXPECT_EQ(straight_joints(stones, kCm.length, kCm.mortar).compared, 0);
}

TEST(CellsMason, FindsStretchedBricksAndCourses) {
    std::vector<Cell> cells = stretchers(11.25, 4, 24);  // 23 cm bricks
    // A course 9 cm high across the wall (bricks drawn 8 cm): a cut course.
    for (double x = 0; x < 200; x += 22.5) cells.push_back(brick(x, 61, x + 22.5, 70, 4));
    MasonReport r = mason_check(plain_wall(), cells, kCm);
    EXPECT_NEAR(r.length_deviation, 1.5, 1e-9);
    EXPECT_EQ(r.cut_courses, 1);
    EXPECT_EQ(r.courses_off_gauge, 0);
    // Whole bricks with bed joints 4 mm too thick: every course off gauge.
    std::vector<Cell> open;
    for (int k = 0; k < 4; ++k)
        for (double x = 0; x < 200; x += 22.5) {
            const double y1 = 100 - 7.9 * k - 0.5, y0 = y1 - 6.5;
            Cell c = brick(x, 0, x + 22.5, 10, k);
            c.polygon = {{x + 0.5, y0}, {x + 22, y0}, {x + 22, y1}, {x + 0.5, y1}};
            open.push_back(c);
        }
    r = mason_check(plain_wall(), open, kCm);
    EXPECT_EQ(r.courses_off_gauge, 3);
    EXPECT_NEAR(r.gauge_deviation, 0.4, 1e-9);
    EXPECT_EQ(r.cut_courses, 0);
}

// A lintel two courses deep across the wall spans its courses; one cut to 9 cm is a cut course.
TEST(CellsMason, ALintelOfWholeCoursesIsNoCutCourse) {
    std::vector<Cell> cells = stretchers(11.25, 4);
    cells.push_back(brick(0, 55, 200, 70, 4, "lintel"));  // 15 cm: two courses, drawn 14
    EXPECT_EQ(mason_check(plain_wall(), cells, kCm).cut_courses, 0);
    cells.back() = brick(0, 61, 200, 70, 4, "lintel");  // 9 cm: within a course
    EXPECT_EQ(mason_check(plain_wall(), cells, kCm).cut_courses, 1);
    // Two courses each 2.25 mm over gauge (within the tolerance): the courses' pitch, no cut.
    cells.back() = brick(0, 54.55, 200, 70, 4, "lintel");
    EXPECT_EQ(mason_check(plain_wall(), cells, kCm).cut_courses, 0);
    // Each 3.5 mm over: past the tolerance, a cut course.
    cells.back() = brick(0, 54.3, 200, 70, 4, "lintel");
    EXPECT_EQ(mason_check(plain_wall(), cells, kCm).cut_courses, 1);
}

TEST(CellsMason, FindsSliversAndNarrowPieces) {
    std::vector<Cell> cells = stretchers(11.25, 2);
    cells.push_back(brick(0, 50, 2.5, 57.5, 7));  // 1.5 x 6.5 drawn: 7% of a face
    MasonReport r = mason_check(plain_wall(), cells, kCm);
    EXPECT_EQ(r.slivers, 1);
    EXPECT_EQ(r.narrow_pieces, 1);
    EXPECT_LT(r.smallest_piece, 0.1);
    // A quoin 4 cm wide notched by a skewback (six sides, plumb and level) is narrow too; one
    // with a lug of 3 cm round a sill's horn is a whole header, and one cut to a curve is not
    // read.
    Cell quoin = brick(0, 60, 5, 67.5, 8, "quoins");
    quoin.polygon = {{0.5, 60.5}, {4.5, 60.5}, {4.5, 64}, {3, 64}, {3, 67}, {0.5, 67}};
    Cell lugged = brick(0, 70, 11.25, 77.5, 9);
    lugged.polygon = {{0.5, 70.5}, {10.75, 70.5}, {10.75, 77}, {3.5, 77}, {3.5, 72.5}, {0.5, 72.5}};
    Cell curved = brick(0, 80, 5, 87.5, 10);
    curved.polygon = {{0.5, 80.5}, {4.5, 80.5}, {4.5, 84}, {3, 87}, {0.5, 87}};
    r = mason_check(plain_wall(), {quoin, lugged, curved}, kCm);
    EXPECT_EQ(r.narrow_pieces, 1);
    ASSERT_EQ(r.narrow_at.size(), 1u);
    EXPECT_NEAR(r.narrow_at[0].x, 2.5, 1e-9);
}

TEST(CellsMason, FindsHeadlessOpeningsAndClippedVoussoirs) {
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 300, 200), {"wall"}, "w"));
    s.push_back(shape(rect(30, 100, 60, 80), {"window"}, "flat"));
    s.push_back(shape(arched(150, 180, 80, 60), {"window", "arch"}, "round"));
    Facade f = Facade::from_shapes(std::move(s), "two.svg");
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1;
    Texture t = texture(f, brick_tree(), o, 1);
    MasonReport r = mason_check(f, t.cells, kCm);
    EXPECT_EQ(r.openings, 2);
    EXPECT_EQ(r.openings_without_head, 0);  // soldiers over the flat head, voussoirs round the arch
    // Without its soldier course the flat-headed window is found headless.
    t.cells.erase(std::remove_if(t.cells.begin(), t.cells.end(),
                                 [](const Cell& c) { return c.generator == "soldier_course"; }),
                  t.cells.end());
    r = mason_check(f, t.cells, kCm);
    ASSERT_EQ(r.headless.size(), 1u);
    EXPECT_NE(r.headless[0].find("flat"), std::string::npos);
    EXPECT_GT(r.voussoirs, 5);
    // Notch one voussoir: it is no longer whole.
    for (Cell& c : t.cells)
        if (c.generator == "arch_stones" && c.feature == FeatureKind::edge) {
            Point a = c.polygon[0], b = c.polygon[1];
            c.polygon.insert(c.polygon.begin() + 1, midpoint(a, b) + (b - a).perp() * 0.3);
            break;
        }
    EXPECT_EQ(mason_check(f, t.cells, kCm).voussoirs_clipped, r.voussoirs_clipped + 1);
}

TEST(CellsMason, FindsFourWayJointsStonesOnEndAndUnitSquares) {
    // Stones in a plain grid: every inner grid point is a four-way joint.
    std::vector<Cell> cells;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            cells.push_back(brick(30.0 * i, 15.0 * j, 30.0 * (i + 1), 15.0 * (j + 1), j, "ashlar"));
    MasonSpec stone = kCm;
    stone.stone = true;
    MasonReport r = mason_check(plain_wall(), cells, stone);
    EXPECT_EQ(r.stones, 12);
    EXPECT_EQ(r.four_way, 6);
    EXPECT_EQ(r.stones_on_end, 0);
    EXPECT_EQ(mason_check(plain_wall(), cells, kCm).stones, 0);  // a brick wall: not read
    // A stone on end in the wall, and three unit squares in a row.
    cells.push_back(brick(150, 0, 165, 30, 0, "ashlar"));
    for (int i = 0; i < 3; ++i)
        cells.push_back(brick(120 + 7.5 * i, 45, 127.5 + 7.5 * i, 52.5, 3, "ashlar"));
    r = mason_check(plain_wall(), cells, stone);
    EXPECT_EQ(r.stones_on_end, 1);
    EXPECT_EQ(r.unit_square_pairs, 2);
    EXPECT_EQ(r.unit_square_runs, 1);
    EXPECT_EQ(r.pier_stones, 0);
}

TEST(CellsMason, ReadsAPierBetweenTwoBearings) {
    // Two lintels' bearings 15 cm apart, the pier between them one stone of their height: not
    // on end; beside a lugged sill's plumb end too. The same stone a joint shorter, or between
    // two wall stones, is.
    MasonSpec stone = kCm;
    stone.stone = true;
    std::vector<Cell> cells = {brick(0, 60, 45, 90, 0, "lintel"),
                               brick(60, 60, 105, 90, 0, "lintel"),
                               brick(45, 60, 60, 90, 0, "ashlar")};
    MasonReport r = mason_check(plain_wall(), cells, stone);
    EXPECT_EQ(r.stones_on_end, 0);
    EXPECT_EQ(r.pier_stones, 1);
    cells[2] = brick(45, 61, 60, 90, 0, "ashlar");
    r = mason_check(plain_wall(), cells, stone);
    EXPECT_EQ(r.stones_on_end, 1);
    EXPECT_EQ(r.pier_stones, 0);
    cells[2] = brick(45, 60, 60, 90, 0, "ashlar");
    // A sill with a lug at its far end: its plumb end beside the pier is as tall, so a pier.
    cells[0].polygon = {{0.5, 65}, {10, 65}, {10, 60.5}, {44.5, 60.5}, {44.5, 89.5}, {0.5, 89.5}};
    cells[0].generator = "window_bottom";
    r = mason_check(plain_wall(), cells, stone);
    EXPECT_EQ(r.stones_on_end, 0);
    EXPECT_EQ(r.pier_stones, 1);
    cells[0] = brick(0, 60, 45, 90, 0, "ashlar");
    cells[1].generator = "ashlar";
    EXPECT_EQ(mason_check(plain_wall(), cells, stone).stones_on_end, 1);
}

TEST(CellsMason, FindsAJointAtTheCrown) {
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 300, 200), {"wall"}, "w"));
    s.push_back(shape(arched(150, 180, 80, 60), {"window", "arch"}, "round"));
    Facade f = Facade::from_shapes(std::move(s), "round.svg");
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1;
    Texture t = texture(f, brick_tree(), o, 1);
    MasonReport r = mason_check(f, t.cells, kCm);
    EXPECT_EQ(r.crowns, 1);
    EXPECT_EQ(r.crowns_open, 0);  // an odd count, the key at the crown
    // The ring turned half a voussoir about its centre (a semicircle of n stones: pi / 2n) puts
    // a joint at the crown, as an even count would.
    const Edge* arc = nullptr;
    for (const Edge& e : f.edges())
        if (e.arc) arc = &e;
    ASSERT_NE(arc, nullptr);
    const Point o2 = arc->segments.front().center;
    long stones = 0;
    for (const Cell& c : t.cells) stones += c.generator == "arch_stones";
    ASSERT_GT(stones, 2);
    const double turn = M_PI / (2.0 * static_cast<double>(stones)), cs = std::cos(turn),
                 sn = std::sin(turn);
    for (Cell& c : t.cells)
        if (c.generator == "arch_stones")
            for (Point& p : c.polygon)
                p = {o2.x + (p.x - o2.x) * cs - (p.y - o2.y) * sn,
                     o2.y + (p.x - o2.x) * sn + (p.y - o2.y) * cs};
    EXPECT_EQ(mason_check(f, t.cells, kCm).crowns_open, 1);
}

namespace {

Options centimetres() {  // as rules/facade.acr lays them
    Options o;
    o.brick_length = 21.5, o.brick_height = 6.5, o.mortar = 1, o.joint_tolerance = 0.3;
    return o;
}

const Bond kBrickBonds[] = {Bond::running, Bond::english, Bond::flemish, Bond::header, Bond::stack};

}  // namespace

// Facades no code here was tuned on (tests/stdlib/cells/facades/: a shop front with a wide
// window and close windows, a chapel end with pointed, segmental and round heads near the wall's
// ends, a terrace with jambs between quarter bricks, a gable with a pointed door at a wall end,
// a warehouse with a 4.2 m segmental arch, a stone front), every bond and tree.
// Odd pieces not forced by the geometry (mason_check.hpp), the most of any bond and tree at
// seed 1, per facade.
const std::map<std::string, long> kUnforced{
    {"row-house", 136}, {"gable", 48},        {"oculus", 1},   {"insets", 39},
    {"shopfront", 38},  {"chapel", 35},       {"terrace", 47}, {"gable-lancet", 50},
    {"warehouse", 41},  {"ashlar-front", 95}, {"mill", 46}};

std::string list(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size() && i < 12; ++i) s += "\n  " + v[i];
    if (v.size() > 12) s += "\n  ... " + std::to_string(v.size() - 12) + " more";
    return s;
}

// The warehouse's pier between the carriage arch and the right window, in Flemish bond with
// quoins: the window's jamb leaves the last piece 0.55 cm short of a header or 0.64 cm short of
// a brick, and the joints of consecutive courses stand 5.625 cm apart, 2.5 mm past the quarter
// brick (5.375 cm). With half the tolerance kept past a quarter brick, no joint could take up a mm
// and 19 bricks stood shaved beside the window; with a twentieth of a joint (fit_run_ends) the
// courses take it up in their joints: one is left, in the column's bottom course.
TEST(CellsMason, PierJointsTakeUpMillimetres) {
    const Facade f = Facade::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) +
                                           "/tests/stdlib/cells/facades/warehouse.svg");
    Options o = centimetres();
    o.bond = Bond::flemish;
    const Texture t = texture(f, mason_trees().at("framed"), o, 1);
    std::vector<Cell> pier;  // the pier's pieces beside the window's jambs
    for (const Cell& c : t.cells) {
        Rect b;
        if (mason_detail::is_rect(c.polygon, b) && b.x0 >= 660 && b.x1 <= 760 && b.y0 >= 200 &&
            b.y1 <= 347.3)
            pier.push_back(c);
    }
    EXPECT_GT(pier.size(), 80u);
    const MasonReport m = mason_check(f, pier, kCm);
    EXPECT_LE(m.shaved_bricks, 1) << list(m.shaved);
    EXPECT_EQ(m.straight_joints, 0);
    EXPECT_EQ(m.narrow_pieces, 0);
}

TEST(CellsMason, UnseenFacades) {
    const std::string dir = std::string(ACANTHUS_SOURCE_DIR) + "/tests/stdlib/cells/facades/";
    Options o = centimetres();
    const auto trees = mason_trees();
    for (const char* name :
         {"shopfront", "chapel", "terrace", "gable-lancet", "warehouse", "ashlar-front", "mill"}) {
        Facade f = Facade::from_svg_file(dir + name + ".svg");
        for (Bond bond : kBrickBonds)
            for (const auto& [tree_name, tree] : trees) {
                o.bond = bond;
                Texture t = texture(f, tree, o, 1);
                MasonReport r = mason_check(f, t.cells, kCm);
                std::cout << name << " " << to_string(bond) << " " << tree_name << ": " << r
                          << "\n";
                SCOPED_TRACE(std::string(name) + " " + std::string(to_string(bond)) + " " +
                             tree_name);
                // Odd pieces the geometry does not force (mason_check.hpp), at seed 1 the most
                // of any bond and tree: jambs the plumb unit lines miss (docs, Limitations).
                EXPECT_LE(r.unforced_odd, kUnforced.at(name)) << list(r.unforced);
                // The mill (made up after the rest, not tuned on): its loading door's ring, 9 cm
                // from the wall's end, is one half-brick ring (a brick-deep one would reach past
                // the end). A brick over the wide window's extrados, its corner cut by it,
                // keeps its course's beds (it was drawn 1.2 mm short, off its course line).
                EXPECT_EQ(r.slivers, 0);
                EXPECT_EQ(r.voussoirs_clipped, 0);  // voussoirs first, walling cut
                EXPECT_EQ(r.crowns_open, 0);        // a key at every crown
                // Soldiers of a brick's height, the head joints taking up the span (the
                // shopfront's were 6.3 to 6.7 cm wide when they shared it evenly).
                EXPECT_EQ(r.soldiers_off, 0) << "up to " << r.soldier_deviation;
                // A head over every opening: soldiers or a lintel by span, arches.
                EXPECT_EQ(r.openings_without_head, 0);
                // Courses on gauge from the ground, sills and heads met within the joints'
                // tolerance or cut at the opening; one cut course at most, under a level top.
                EXPECT_EQ(r.courses_off_gauge, 0);
                EXPECT_LE(r.cut_courses, 1);
                // Whole bricks within 1 mm.
                EXPECT_LE(r.height_deviation, kCm.tolerance / 3);
                if (bond != Bond::stack) {
                    std::string where;
                    for (Point p : r.straight_at)
                        where += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
                    // Framed: quoins bonded in (were 99-270 here); the shop front's 41 cm pier
                    // between the wall's end and the shop window, two quoins and what lies
                    // between, set out as a column (was 20-29 straight joints up it); lintels in
                    // the layout and the pieces round fixed ends cut again (0-9 before); fixed
                    // ends moved a quarter brick where two met, and a course cut again off the
                    // fixed ends of the course beyond it (the mill 2 before: the wide window's
                    // window-bottom row over the long quoin of the wall's end below it).
                    EXPECT_EQ(r.straight_joints, 0) << "at" << where;
                    if (std::string(name) == "shopfront") {
                        for (Point p : r.straight_at) EXPECT_GT(p.x, 41.3) << "up the pier";
                    }
                    // The warehouse's segmental windows left a 3 cm piece between each
                    // skewback and the bond: the skewback takes it in. Pieces notched by a
                    // skewback or a fixed end are measured too (the rectangle round them).
                    std::string narrow;
                    for (Point p : r.narrow_at)
                        narrow += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
                    EXPECT_EQ(r.narrow_pieces, 0) << "at" << narrow;
                }
                // King closers only at a reveal or quoin, the bond going on beside: a
                // stretcher, one cut to an arch, or the course cut at the next reveal (Flemish
                // only). Before: 21 misplaced here, cut to an arch's extrados (the mill's framed
                // tree: one under the loading door's ring) or a header beyond the closer.
                if (bond != Bond::flemish) {
                    EXPECT_EQ(r.king_closers, 0);
                }
                std::string kings;
                for (Point p : r.misplaced_kings)
                    kings += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
                EXPECT_EQ(r.king_closers_misplaced, 0) << "at" << kings;
            }
    }
}

// Every example facade in every bond and tree; the numbers go to the log (the table).
TEST(CellsMason, ExampleFacades) {
    const std::string dir = std::string(ACANTHUS_SOURCE_DIR) + "/examples/facades/";
    Options o = centimetres();
    const std::map<std::string, Node> trees = mason_trees();
    long sills = 0, sills_off_centre = 0;
    for (const char* name : {"row-house", "gable", "oculus", "insets"}) {
        Facade f = Facade::from_svg_file(dir + name + ".svg");
        for (Bond bond : kBrickBonds)
            for (const auto& [tree_name, tree] : trees) {
                o.bond = bond;
                Texture t = texture(f, tree, o, 1);
                MasonReport r = mason_check(f, t.cells, kCm);
                std::cout << name << " " << to_string(bond) << " " << tree_name << ": " << r
                          << "\n";
                sills += r.sills, sills_off_centre += r.sills_off_centre;
                SCOPED_TRACE(std::string(name) + " " + std::string(to_string(bond)) + " " +
                             tree_name);
                // Fixed units: whole bricks keep their height, courses their gauge, head joints
                // between bricks their width within the tolerance.
                EXPECT_LE(r.height_deviation, kCm.tolerance / 3);
                EXPECT_EQ(r.joints_off, 0) << "up to " << r.joint_deviation;
                // Pieces neither a brick nor a standard bat, cut where a jamb the perpends do not
                // reach falls between head joints: at seed 1 the most of any bond and tree (were
                // 274, 104, 80 and 60 before the perpends were set out from the jambs).
                const std::map<std::string, long> odd{
                    {"row-house", 137}, {"gable", 48}, {"oculus", 41}, {"insets", 50}};
                EXPECT_LE(r.odd_pieces, odd.at(name));
                EXPECT_LE(r.unforced_odd, kUnforced.at(name)) << list(r.unforced);
                EXPECT_EQ(r.slivers, 0);  // pieces under 10% of a face are left to the mortar
                EXPECT_EQ(r.voussoirs_clipped, 0);
                EXPECT_EQ(r.crowns_open, 0);
                EXPECT_EQ(r.soldiers_off, 0) << "up to " << r.soldier_deviation;
                if (bond != Bond::stack && tree_name != "framed") {
                    // Closers at jambs and wall ends, window-bottom rows in the layout (row-house
                    // before them: English 68, Flemish 124, running 30).
                    EXPECT_EQ(r.straight_joints, 0);
                    EXPECT_EQ(r.narrow_pieces, 0);  // no piece narrower than a queen closer
                    // Jamb bricks a few mm off laid whole (row-house English 44, Flemish 75
                    // before); run ends laid again with whole bricks and closers (fit_run_ends)
                    // leave 2 at most (36 before).
                    EXPECT_LE(r.shaved_bricks, 2);
                }
                if (tree_name == "framed" && bond != Bond::stack) {
                    // 297 on the row-house before quoins were bonded in, 0-2 before lintels were,
                    // one on the insets before fixed ends were moved a quarter brick.
                    EXPECT_EQ(r.straight_joints, 0);
                    EXPECT_EQ(r.narrow_pieces, 0);
                }
                EXPECT_EQ(r.courses_off_gauge, 0);
                EXPECT_LE(r.cut_courses, 1);
                EXPECT_EQ(r.openings_without_head, 0);
                // Closers and cut pieces back from the arrises (fit_arrises): a piece narrower
                // than a header at a quoin or a jamb only where the run forces it (the row-house
                // had 29-75 a wall before, every one at a window's jamb).
                const std::map<std::string, long> arris{
                    {"row-house", 5}, {"gable", 7}, {"oculus", 11}, {"insets", 7}};
                EXPECT_LE(r.arris_small - r.arris_small_forced, arris.at(name))
                    << "arris pieces " << r.arris_pieces;
                // King closers (Flemish) only at a reveal or quoin, the bond going on beside.
                EXPECT_EQ(r.king_closers_misplaced, 0);
                if (bond != Bond::flemish) {
                    EXPECT_EQ(r.king_closers, 0);
                }
            }
        o.bond = Bond::ashlar;
        MasonReport r = mason_check(f, texture(f, ashlar_tree(), o, 1).cells, kCm);
        std::cout << name << " ashlar: " << r << "\n";
        EXPECT_EQ(r.slivers, 0) << name << " ashlar";
    }
    // Window-bottom rows as far past one jamb as past the other, within a quarter brick, where
    // that shaves no brick: 35 of the 165 are not (51 with every row two units past each jamb).
    EXPECT_EQ(sills, 165);
    EXPECT_LE(sills_off_centre, 35);
}

// Ashlar walls: the ready tree (the joint-rules layout, lintels and sill stones) on every example
// and unseen facade: four-way joints counted over all stones, jamb, sill and lintel stones too.
TEST(CellsMason, AshlarWalls) {
    const std::string root = std::string(ACANTHUS_SOURCE_DIR);
    Options o = centimetres();
    o.bond = Bond::ashlar;
    MasonSpec spec = kCm;
    spec.stone = true;
    for (const char* name :
         {"tests/stdlib/cells/facades/shopfront", "tests/stdlib/cells/facades/chapel",
          "tests/stdlib/cells/facades/terrace", "tests/stdlib/cells/facades/gable-lancet",
          "tests/stdlib/cells/facades/warehouse", "tests/stdlib/cells/facades/ashlar-front",
          "tests/stdlib/cells/facades/mill", "examples/facades/row-house", "examples/facades/gable",
          "examples/facades/oculus", "examples/facades/insets"}) {
        Facade f = Facade::from_svg_file(root + "/" + name + ".svg");
        for (AshlarMethod method : {AshlarMethod::rules, AshlarMethod::merge}) {
            o.ashlar_method = method;
            MasonReport r = mason_check(f, texture(f, ashlar_tree(), o, 1).cells, spec);
            std::cout << name << " ashlar " << to_string(method) << ": " << r << "\n";
            SCOPED_TRACE(std::string(name) + " " + std::string(to_string(method)));
            EXPECT_EQ(r.slivers, 0);
            EXPECT_EQ(r.openings_without_head, 0);  // lintels over flat heads, arches
            EXPECT_EQ(r.crowns_open, 0);
            // No voussoir clipped: a skewback without a bed below its springing (stone walls)
            // was taken for its bounding box and cut the ring's first stone (warehouse 3); the
            // mill's loading-door ring, which reached past the wall's end, is a half-brick ring.
            EXPECT_EQ(r.voussoirs_clipped, 0);
            if (method == AshlarMethod::merge) {
                EXPECT_GT(r.four_way, r.stones / 50);  // the paper's merge: what the rules avoid
                continue;
            }
            EXPECT_GT(r.stones, 400);
            EXPECT_LE(r.four_way, r.stones / 100);
            // Stones on end stand only at jambs and the wall's ends (random heights there, as
            // the paper's edge stones): the stones round one elsewhere are laid again.
            EXPECT_EQ(r.stones_on_end, 0);
            // Unit squares only where nothing wider fits and never three in a row; two side by
            // side at most 0.5% of stones.
            EXPECT_EQ(r.unit_square_runs, 0);
            EXPECT_LE(r.unit_square_pairs, r.stones / 100);
        }
    }
}

// Two elevations meeting at a building corner (docs/stdlib/cells.md, "Building corners"): the
// front's right end and the side's left end, labelled corner-right and corner-left. Their courses
// stand at the same heights above the ground, and at the corner each course ends in a stretcher
// on one face and that stretcher's end, half a brick, on the other, by turns.
TEST(CellsMason, BuildingCornerTurns) {
    std::vector<FacadeShape> a, b;
    a.push_back(shape(rect(0, 0, 317.3, 241.6), {"wall", "corner-right"}, "front"));
    a.push_back(shape(rect(61.4, 52.8, 93.1, 118.7), {"window"}, "fw"));  // sill off gauge
    b.push_back(shape(rect(0, 0, 263.9, 241.6), {"wall", "corner-left"}, "side"));
    b.push_back(shape(rect(120.2, 70.1, 88.6, 96.3), {"window"}, "sw"));
    Facade front = Facade::from_shapes(std::move(a), "front.svg");
    Facade side = Facade::from_shapes(std::move(b), "side.svg");
    Options o = centimetres();
    for (Bond bond : {Bond::running, Bond::english, Bond::flemish}) {
        o.bond = bond;
        SCOPED_TRACE(std::string(to_string(bond)));
        Texture tf = texture(front, brick_tree(), o, 1), ts = texture(side, brick_tree(), o, 1);
        // Course lines as heights above the ground (both walls stand on y = 241.6).
        auto lines = [&](const Texture& t) {
            std::set<long> out;
            for (const Cell& c : t.cells) {
                Rect r;
                if (mason_detail::coursed(c) && mason_detail::is_rect(c.polygon, r) &&
                    std::abs(r.height() - 6.5) < 0.05)
                    out.insert(std::lround((241.6 - r.y1) * 100));
            }
            return out;
        };
        EXPECT_EQ(lines(tf), lines(ts));
        EXPECT_GT(lines(tf).size(), 25u);
        // The piece at the corner in each course: its length in quarter bricks, by course.
        auto at_corner = [&](const Texture& t, double x) {
            std::map<long, int> out;
            for (const Cell& c : t.cells) {
                Rect r;
                if (!mason_detail::coursed(c) || !mason_detail::is_rect(c.polygon, r) ||
                    std::abs(r.height() - 6.5) > 0.05 ||
                    std::min(std::abs(r.x0 - x), std::abs(r.x1 - x)) > 0.6)
                    continue;
                out[std::lround((241.6 - r.y1) / 7.5)] =
                    static_cast<int>(std::lround((r.width() + 1) / 5.625));
            }
            return out;
        };
        const auto f = at_corner(tf, 317.3), s = at_corner(ts, 0);
        ASSERT_GT(f.size(), 25u);
        int compared = 0;
        for (const auto& [course, len] : f) {
            EXPECT_TRUE(len == 2 || len == 4) << "course " << course << ": " << len;
            if (f.count(course + 1)) {
                EXPECT_NE(len, f.at(course + 1)) << "course " << course;
            }
            if (!s.count(course)) continue;
            ++compared;
            EXPECT_EQ(len + s.at(course), 6) << "course " << course;  // a stretcher and its end
        }
        EXPECT_GT(compared, 25);
        // English bond: a header's end on one face where a stretcher runs on the other, so each
        // course is a stretcher course on one face and a header course on the other; and the
        // header course's quoin header is followed by a queen closer, as a mason lays it.
        if (bond == Bond::english) {
            auto kinds = [&](const Texture& t, double corner) {
                std::map<long, std::vector<std::pair<double, int>>> rows;  // by course: x, quarters
                for (const Cell& c : t.cells) {
                    Rect r;
                    if (!mason_detail::coursed(c) || !mason_detail::is_rect(c.polygon, r) ||
                        std::abs(r.height() - 6.5) > 0.05)
                        continue;
                    rows[std::lround((241.6 - r.y1) / 7.5)].push_back(
                        {std::abs(r.center().x - corner),
                         static_cast<int>(std::lround((r.width() + 1) / 5.625))});
                }
                std::map<long, std::vector<int>> out;  // the first pieces from the corner
                for (auto& [course, row] : rows) {
                    std::sort(row.begin(), row.end());
                    for (std::size_t i = 0; i < row.size() && i < 4; ++i)
                        out[course].push_back(row[i].second);
                }
                return out;
            };
            const auto kf = kinds(tf, 317.3), ks = kinds(ts, 0);
            int checked = 0;
            for (const auto& [course, front] : kf) {
                if (!ks.count(course) || front.size() < 4 || ks.at(course).size() < 4) continue;
                const auto& side = ks.at(course);
                // The header course: the quoin's end (2), a queen closer (1), then headers.
                const auto& headers = front[0] == 2 ? front : side;
                const auto& stretchers = front[0] == 2 ? side : front;
                EXPECT_EQ(headers[0], 2) << "course " << course;
                EXPECT_EQ(headers[1], 1) << "course " << course << ": queen closer";
                EXPECT_EQ(headers[2], 2) << "course " << course;
                EXPECT_EQ(stretchers[0], 4) << "course " << course;
                EXPECT_EQ(stretchers[1], 4) << "course " << course;
                ++checked;
            }
            EXPECT_GT(checked, 20);
        }
        for (const Texture* t : {&tf, &ts}) {
            MasonReport r = mason_check(t == &tf ? front : side, t->cells, kCm);
            std::cout << to_string(bond) << (t == &tf ? " front: " : " side: ") << r << "\n";
            EXPECT_EQ(r.straight_joints, 0);
            // Left: Flemish on the side, a 3.6 cm piece beside the window's right jamb in the
            // two courses its sill and head fall within (not a corner matter).
            EXPECT_LE(r.narrow_pieces, bond == Bond::flemish && t == &ts ? 2 : 0);
            EXPECT_EQ(r.courses_off_gauge, 0);
            // 241.6 cm is 32 courses and 1.6 cm: two courses of 4.6 cm under the top.
            EXPECT_LE(r.cut_courses, 2);
        }
    }
}
