// Features of a facade [3.1]: wall minus openings, exact arcs, corners, labels, window
// analysis; bad facades named by file and shape.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/partial_picture.hpp>
#include <algorithm>
#include <chrono>

#include "cells_oracle.hpp"

using namespace cells_test;

namespace {

bool has(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

std::string message_of(std::vector<FacadeShape> shapes) {
    try {
        Facade::from_shapes(std::move(shapes), "bad.svg");
    } catch (const acanthus::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(CellsFacade, WallMinusOpenings) {
    Facade f = row_house();
    ASSERT_EQ(f.faces().size(), 1u);
    // 6000 x 4000 less two windows, the arched window and the door.
    double arched = 800 * 900 + M_PI * 400 * 400 / 2;
    double expected = 6000.0 * 4000 - 2 * 900 * 1400 - arched - 600 * 1000;
    EXPECT_NEAR(f.wall_area(), expected, 1e-3 * expected);
    // The door reaches the ground: a notch in the outline, two more convex corners.
    int convex = 0, concave = 0;
    for (const Corner& c : f.corners()) (c.convex ? convex : concave)++;
    EXPECT_EQ(convex, 4 + 2);       // the wall's four, and the door's feet on the ground
    EXPECT_EQ(concave, 8 + 2 + 2);  // two windows, the arched one's sill, the door's head
}

TEST(CellsFacade, ArcsStayExactAndLabelled) {
    Facade f = row_house();
    int arcs = 0;
    for (const Edge& e : f.edges()) {
        if (!e.arc) continue;
        ++arcs;
        EXPECT_TRUE(has(e.labels, "arch"));
        EXPECT_TRUE(has(e.labels, "w3"));
        EXPECT_NEAR(e.segments.front().radius, 400, 1e-6);
        EXPECT_NEAR(e.length, M_PI * 400, 1e-6);
        EXPECT_EQ(e.part, Part::top);
        // Arc length parameterization: the middle of the arc is its crown.
        EXPECT_NEAR(e.at(e.length / 2).y, 1700 - 400, 1e-6);
        EXPECT_NEAR(e.project(e.at(123.0)), 123.0, 1e-6);
    }
    EXPECT_EQ(arcs, 1);
}

TEST(CellsFacade, WindowAnalysis) {
    Facade f = row_house();
    int bottoms = 0, tops = 0;
    for (const Edge& e : f.edges()) {
        if (!has(e.labels, "w1")) continue;
        if (e.part == Part::bottom) {
            ++bottoms;
            EXPECT_NEAR(e.at(0).y, 2600, 1e-9);  // the sill: wall below it
            EXPECT_GT(e.inward(e.length / 2).y, 0.99);
        }
        if (e.part == Part::top) ++tops;
    }
    EXPECT_EQ(bottoms, 1);
    EXPECT_EQ(tops, 1);
    for (const Corner& c : f.corners())
        if (has(c.labels, "w1")) {
            EXPECT_NE(c.part, Part::side);
        }
    // The wall's own top edge: the wall lies below it.
    for (const Edge& e : f.edges())
        if (!e.opening && !e.vertical() && e.at(0).y == 0) {
            EXPECT_EQ(e.part, Part::top);
        }
}

TEST(CellsFacade, UnionOfWallShapes) {
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 1000, 1000), {"wall"}, "a"));
    s.push_back(shape(rect(1000, 0, 1000, 1000), {"wall", "brick"}, "b"));
    Facade f = Facade::from_shapes(std::move(s), "two.svg");
    ASSERT_EQ(f.faces().size(), 1u);
    EXPECT_NEAR(f.wall_area(), 2e6, 1);
    EXPECT_EQ(f.corners().size(), 4u);
}

TEST(CellsFacade, BadFacadesNameFileAndShape) {
    std::string m = message_of({shape(rect(0, 0, 10, 10), {"window"}, "w")});
    EXPECT_NE(m.find("bad.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("wall"), std::string::npos) << m;

    m = message_of({shape(rect(0, 0, 100, 100), {"wall"}, "wall1"),
                    shape(rect(90, 10, 20, 20), {"window"}, "w7")});
    EXPECT_NE(m.find("bad.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("w7"), std::string::npos) << m;
    EXPECT_NE(m.find("crosses"), std::string::npos) << m;

    m = message_of({shape(rect(0, 0, 100, 100), {"wall"}, "wall1"),
                    shape("M 10 10 L 50 10 L 90 10 Z", {"window"}, "flat")});
    EXPECT_NE(m.find("flat"), std::string::npos) << m;
    EXPECT_NE(m.find("no area"), std::string::npos) << m;

    Facade f = row_house();
    Options o;
    o.brick_length = 0;
    try {
        texture(f, brick_tree(), o, 1);
        ADD_FAILURE() << "a brick of length zero was accepted";
    } catch (const acanthus::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("row_house.svg"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("brick"), std::string::npos);
    }
}

TEST(CellsFacade, OverlappingOpeningsRefused) {
    std::string m = message_of({shape(rect(0, 0, 1000, 1000), {"wall"}, "front"),
                                shape(rect(100, 100, 200, 300), {"window"}, "w1"),
                                shape(rect(250, 350, 200, 300), {"window"}, "w2")});
    EXPECT_NE(m.find("bad.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("w1"), std::string::npos) << m;
    EXPECT_NE(m.find("w2"), std::string::npos) << m;
    EXPECT_NE(m.find("openings overlap"), std::string::npos) << m;
    // Openings that only touch along a side stay two openings.
    m = message_of({shape(rect(0, 0, 1000, 1000), {"wall"}, "front"),
                    shape(rect(100, 100, 200, 300), {"window"}, "w1"),
                    shape(rect(300, 100, 200, 300), {"window"}, "w2")});
    EXPECT_EQ(m, "");
}

TEST(CellsFacade, ThinAndHugeWallsRefusedBeforeLaying) {
    Options o;  // courses of 65 + 10 mm
    auto refusal = [&](const Facade& f) {
        try {
            texture(f, brick_tree(), o, 1);
        } catch (const acanthus::InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    // 60 mm high: no course fits anywhere.
    std::string m =
        refusal(Facade::from_shapes({shape(rect(0, 0, 6000, 60), {"wall"}, "strip")}, "thin.svg"));
    EXPECT_NE(m.find("thin.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("strip"), std::string::npos) << m;
    EXPECT_NE(m.find("thinner than a course"), std::string::npos) << m;
    // One course high is enough.
    EXPECT_EQ(
        refusal(Facade::from_shapes({shape(rect(0, 0, 6000, 75), {"wall"}, "strip")}, "thin.svg")),
        "");
    // A wall 1e-5 thick is no area at all.
    m = message_of({shape(rect(0, 0, 6000, 1e-5), {"wall"}, "film")});
    EXPECT_NE(m.find("film"), std::string::npos) << m;
    EXPECT_NE(m.find("no area"), std::string::npos) << m;
    // A kilometre by 30 m (mm): refused at once with the estimate, not after minutes of work.
    Facade huge = Facade::from_shapes({shape(rect(0, 0, 1e6, 3e4), {"wall"}, "long")}, "km.svg");
    auto start = std::chrono::steady_clock::now();
    m = refusal(huge);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1);
    EXPECT_NE(m.find("km.svg"), std::string::npos) << m;
    EXPECT_NE(m.find("about 1,777,778 cells"), std::string::npos) << m;
    EXPECT_NE(m.find("cells_max_cells"), std::string::npos) << m;
    o.max_cells = 0;
    EXPECT_NE(refusal(row_house()).find("cells_max_cells must be at least 1"), std::string::npos);
}

// Two windows drawn side by side, sharing a side, are one opening as wide as both (as a door
// and its fanlight drawn apart are one); each name's share of the outline is no opening size.
TEST(CellsFacade, WindowsDrawnSideBySideAreLaidAsOneOpening) {
    auto laid = [](const std::vector<FacadeShape>& shapes, std::string& error) {
        try {
            Options o;
            return texture(Facade::from_shapes(shapes, "pair.svg"), brick_tree(), o, 1)
                .cells.size();
        } catch (const acanthus::InputError& e) {
            error = e.what();
        }
        return std::size_t{0};
    };
    std::string error;
    EXPECT_GT(laid({shape(rect(0, 0, 4000, 3000), {"wall"}, "front"),
                    shape(rect(1000, 1000, 800, 1000), {"window"}, "w1"),
                    shape(rect(1800, 1000, 800, 1000), {"window"}, "w2")},
                   error),
              0u)
        << error;
    // A speck beside a window, not touching it, is still refused by its own name.
    error.clear();
    laid({shape(rect(0, 0, 4000, 3000), {"wall"}, "front"),
          shape(rect(1000, 1000, 800, 1000), {"window"}, "w1"),
          shape(rect(1900, 1000, 1, 1), {"window"}, "speck")},
         error);
    EXPECT_NE(error.find("\"window speck\""), std::string::npos) << error;
    EXPECT_EQ(error.find("w1"), std::string::npos) << error;
}

TEST(CellsFacade, EdgeOccupancyMergesIntervals) {
    EdgeOccupancy e(10);
    e.claim(2, 3);
    e.claim(5, 6);
    e.claim(2.5, 5.5);
    ASSERT_EQ(e.claimed().size(), 1u);
    EXPECT_FALSE(e.is_free(4, 4.5));
    EXPECT_TRUE(e.is_free(7, 9));
    auto free = e.free_intervals();
    ASSERT_EQ(free.size(), 2u);
    EXPECT_DOUBLE_EQ(free[0].second, 2);
    EXPECT_DOUBLE_EQ(free[1].first, 6);
}

namespace {

// Edge::project as it was, trying every segment in order: the least distance, the first on a tie.
double project_by_all_segments(const Edge& e, Point p) {
    double best = 0, best_d = 1e300;
    for (std::size_t i = 0; i < e.segments.size(); ++i) {
        double s = e.segments[i].project(p);
        double d = distance(e.segments[i].at(s), p);
        if (d < best_d) {
            best_d = d;
            best = e.offsets[i] + s;
        }
    }
    return best;
}

Segment arc_segment(Point center, double radius, double start, double sweep) {
    Segment s;
    s.arc = true;
    s.center = center;
    s.radius = radius;
    s.start = start;
    s.sweep = sweep;
    s.a = s.at(0);
    s.b = s.at(s.length());
    return s;
}

void add_segment(Edge& e, Segment s) {
    e.offsets.push_back(e.length);
    e.length += s.length();
    e.segments.push_back(s);
}

}  // namespace

// The pruned search (nearest box first) answers exactly as a look at every segment, ties
// included: points on a grid through the segments' joints, on the row house's edges and on an
// edge of many lines and arcs, some of them meeting at the same points.
TEST(CellsFacade, ProjectIsTheNearestOfAllSegments) {
    Edge zigzag;
    for (int i = 0; i < 12; ++i) {
        Segment s;
        s.a = {i * 100.0, (i % 2) * 100.0};
        s.b = {(i + 1) * 100.0, ((i + 1) % 2) * 100.0};
        add_segment(zigzag, s);
    }
    // Arcs over the zigzag, and back through the same points: equal distances to several.
    for (int i = 0; i < 6; ++i)
        add_segment(zigzag, arc_segment({1250.0 - i * 200.0, 50.0}, 100.0 + 10 * i,
                                        -M_PI * (0.25 * i), (i % 2 ? -1 : 1) * M_PI * 1.5));
    add_segment(zigzag, arc_segment({600, 50}, 650, -3 * M_PI, 7 * M_PI / 2));
    // From the origin: the second segment's box is nearer (80) than the first's (100), both
    // segments are exactly 100 away; the first segment is the answer.
    Edge tie;
    Segment level, away;
    level.a = {-50, 100};
    level.b = {50, 100};
    away.a = {60, 80};
    away.b = {-20, 140};
    add_segment(tie, level);
    add_segment(tie, away);
    EXPECT_EQ(tie.project({0, 0}), 50.0);
    std::vector<Edge> edges = row_house().edges();
    edges.push_back(zigzag);
    edges.push_back(tie);
    long tried = 0;
    for (const Edge& e : edges) {
        acanthus::Rect b = e.bounds;
        for (const Segment& s : e.segments)
            for (Point q : {s.a, s.b})
                b = {std::min(b.x0, q.x), std::min(b.y0, q.y), std::max(b.x1, q.x),
                     std::max(b.y1, q.y)};
        double x0 = b.x0 - 200, y0 = b.y0 - 200;
        double w = b.width() + 400, h = b.height() + 400;
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j <= 40; ++j) {
                Point p{x0 + w * i / 40, y0 + h * j / 40};
                ASSERT_EQ(e.project(p), project_by_all_segments(e, p))
                    << "point " << p.x << "," << p.y << " edge of " << e.segments.size();
                ++tried;
            }
        for (const Segment& s : e.segments)
            for (Point p : {s.a, s.b, s.at(s.length() / 3), Point{s.center.x, s.center.y}}) {
                ASSERT_EQ(e.project(p), project_by_all_segments(e, p));
                ++tried;
            }
    }
    EXPECT_GT(tried, 1000);
}

namespace {

struct PartialCell : acanthus::Element {
    acanthus::PolygonProxy p0;
    std::string generator, feature, label;
    int course = -1;
    const acanthus::ElementType& type() const override {
        static const acanthus::ElementType t{
            "cell", {acanthus::ProxyKind::polygon}, nullptr, nullptr, 0};
        return t;
    }
    std::size_t proxy_count() const override { return 1; }
    acanthus::Proxy& proxy(std::size_t) override { return p0; }
};

}  // namespace

// A texture reports the cells laid so far (report_partial) for the program's partial pictures,
// made by cells.acr's maker: at each report the cells before the one being laid, most as the
// finished texture has them; the texture is the same with the reports as without.
TEST(CellsFacade, PartialPicturesHaveTheCellsLaidSoFar) {
    Facade f = row_house();
    const Texture plain = texture(f, brick_tree(), Options{}, 3);

    struct Seen {
        std::vector<long> placed;
        std::vector<std::vector<std::vector<Point>>> polygons;
    } seen;
    acanthus::detail::set_partial_handler(
        [](void* context, long placed, const acanthus::PartialElements& extra) {
            Seen& s = *static_cast<Seen*>(context);
            s.placed.push_back(placed);
            if (placed % 64 != 0) return;  // every cell each time: quadratic
            std::vector<const acanthus::Element*> made;
            extra(made);
            s.polygons.emplace_back();
            for (const acanthus::Element* e : made) {
                s.polygons.back().push_back(static_cast<const PartialCell*>(e)->p0.points);
                delete e;
            }
            EXPECT_LE(made.size(), static_cast<std::size_t>(placed));
        },
        &seen);
    acanthus::cells::detail::set_partial_maker(
        [](const Cell& c) -> const acanthus::Element* { return new_cell<PartialCell>(c); });
    const Texture reported = texture(f, brick_tree(), Options{}, 3);
    acanthus::detail::set_partial_handler(nullptr, nullptr);
    acanthus::cells::detail::set_partial_maker(nullptr);

    ASSERT_EQ(reported.cells.size(), plain.cells.size());
    for (std::size_t i = 0; i < plain.cells.size(); ++i) {
        EXPECT_EQ(reported.cells[i].polygon, plain.cells[i].polygon);
        EXPECT_EQ(reported.cells[i].generator, plain.cells[i].generator);
    }
    ASSERT_EQ(seen.placed.size(), plain.cells.size());
    for (std::size_t k = 0; k < seen.placed.size(); ++k)
        EXPECT_EQ(seen.placed[k], static_cast<long>(k));
    // The last picture made shows nearly every cell, most of them as they end up.
    ASSERT_FALSE(seen.polygons.empty());
    EXPECT_GT(seen.polygons.back().size() + 64, plain.cells.size());
    std::size_t same = 0;
    for (std::size_t i = 0; i + 1 < plain.cells.size(); ++i)
        same += std::count(seen.polygons.back().begin(), seen.polygons.back().end(),
                           plain.cells[i].polygon) > 0;
    EXPECT_GT(same, plain.cells.size() * 9 / 10);
}
