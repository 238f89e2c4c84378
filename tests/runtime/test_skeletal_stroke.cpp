// Skeletal strokes: warping along straight and curved skeletons, built-ins, user strokes from
// SVG, bad input and degenerate skeletons. Output is measured on Cairo A8 surfaces.
#include <2geom/bezier-curve.h>
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "fixtures/alpha_coverage.hpp"
#include "fixtures/proxy_factory.hpp"

namespace {
using namespace acanthus;
using namespace acanthus::test;

BezierProxy curvy() {
    BezierProxy b;
    b.set({40, 150}, {100, 20}, {250, 280}, {300, 100});
    return b;
}

TEST(SkeletalStroke, BuiltinsIncludeTheFourOfFigure17) {
    auto names = SkeletalStroke::builtin_names();
    for (const char* n : {"tapered", "calligraphic", "leafy", "beaded"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    for (const auto& n : names) EXPECT_EQ(SkeletalStroke::builtin(n).name(), n);
}

TEST(SkeletalStroke, UnknownBuiltinIsUsageErrorNamingIt) {
    try {
        SkeletalStroke::builtin("squiggly");
        FAIL() << "no UsageError";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("squiggly"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("tapered"), std::string::npos);
    }
}

TEST(SkeletalStroke, TaperedOnHorizontalSegmentFillsLengthAndWidth) {
    const double x0 = 50, y = 50, length = 200, width = 20;
    Coverage c(300, 100, [&](Canvas& canvas) {
        SkeletalStroke::builtin("tapered").draw(canvas, segment_proxy({x0, y}, {x0 + length, y}),
                                                width);
    });
    ASSERT_EQ(c.status(), CAIRO_STATUS_SUCCESS);
    Rect b = c.bounds(8);
    EXPECT_NEAR(b.x0, x0, 1.5);
    EXPECT_NEAR(b.x1 + 1, x0 + length, 2.0);
    EXPECT_NEAR(b.y0, y - width / 2, 1.0);
    EXPECT_NEAR(b.y1 + 1, y + width / 2, 1.0);
    // Full width near the start, a point at the end.
    EXPECT_NEAR(c.column(static_cast<int>(x0 + 0.15 * length)), width, 1.5);
    EXPECT_LT(c.column(static_cast<int>(x0 + 0.95 * length)), width / 4);
    EXPECT_GT(c.column(static_cast<int>(x0 + 0.5 * length)),
              c.column(static_cast<int>(x0 + 0.8 * length)));
}

// Every stroke stays within width/2 of its skeleton; checked against lib2geom's nearest point.
TEST(SkeletalStroke, EveryBuiltinStaysWithinHalfWidthOfCurvedSkeleton) {
    BezierProxy b = curvy();
    Geom::CubicBezier curve({b.c[0].x, b.c[0].y}, {b.c[1].x, b.c[1].y}, {b.c[2].x, b.c[2].y},
                            {b.c[3].x, b.c[3].y});
    const double width = 16;
    for (const auto& name : SkeletalStroke::builtin_names()) {
        SCOPED_TRACE(name);
        Coverage c(340, 300,
                   [&](Canvas& canvas) { SkeletalStroke::builtin(name).draw(canvas, b, width); });
        ASSERT_EQ(c.status(), CAIRO_STATUS_SUCCESS);
        double worst = 0;
        for (int y = 0; y < c.height(); ++y)
            for (int x = 0; x < c.width(); ++x)
                if (c.covered(x, y)) {
                    Geom::Point p(x + 0.5, y + 0.5);
                    worst = std::max(worst, Geom::distance(p, curve.pointAt(curve.nearestTime(p))));
                }
        // Half a width, plus flattening tolerance and half a pixel diagonal.
        EXPECT_LE(worst, width / 2 + 0.05 * width + 0.75);
        // Non-empty: a fair share of the band along the curve is filled.
        double band = curve.length(0.01) * width;
        EXPECT_GT(c.count(), 0.15 * band);
        // Drawn along the whole curve, not just part of it.
        Rect bounds = c.bounds(128);
        Geom::Rect cb = curve.boundsExact();
        EXPECT_LT(bounds.x0, cb.left() + width);
        EXPECT_GT(bounds.x1, cb.right() - width);
    }
}

TEST(SkeletalStroke, CalligraphicIsThinAlongTheNibAndBroadAcrossIt) {
    const auto& pen = SkeletalStroke::builtin("calligraphic");
    const double width = 20;
    // On screen, up and to the right runs along the 45-degree nib.
    Coverage along(300, 300, [&](Canvas& c) {
        pen.draw(c, segment_proxy({50, 250}, {250, 50}), width);
    });
    Coverage across(300, 300, [&](Canvas& c) {
        pen.draw(c, segment_proxy({50, 50}, {250, 250}), width);
    });
    EXPECT_GT(across.count(), 0.9 * 283 * width);
    EXPECT_GT(along.count(), 0);
    EXPECT_GT(across.count(), 4 * along.count());
}

TEST(SkeletalStroke, BeadedPlacesSeparateBeadsSpacedByWidth) {
    const double width = 20;
    Coverage c(340, 60, [&](Canvas& canvas) {
        SkeletalStroke::builtin("beaded").draw(canvas, segment_proxy({20, 30}, {320, 30}), width);
    });
    // Motifs of 1.5 widths, a large and a small bead each: 10 motifs on 300 units.
    EXPECT_EQ(c.runs(30, 0, 340), 20);
}

TEST(SkeletalStroke, LeafyLeafCountIsProportionalToLengthOverWidth) {
    const double width = 20;
    auto leaves = [&](double length) {
        Coverage c(520, 60, [&](Canvas& canvas) {
            SkeletalStroke::builtin("leafy").draw(
                canvas, segment_proxy({10, 30}, {10 + length, 30}), width);
        });
        // One leaf per motif crosses the row a sixth of a width off the stem on each side.
        return std::make_pair(c.runs(33, 0, 520), c.runs(27, 0, 520));
    };
    EXPECT_EQ(leaves(240), std::make_pair(10, 10));  // 240 / (1.2 * 20)
    EXPECT_EQ(leaves(480), std::make_pair(20, 20));
}

TEST(SkeletalStroke, ArcIsFollowedCounterClockwiseFromStartToEnd) {
    ArcProxy a;
    a.set({150, 150}, 100, 0, M_PI / 2);  // from (250, 150) to (150, 250), y down
    const double width = 12;
    Coverage c(320, 320, [&](Canvas& canvas) {
        SkeletalStroke::builtin("calligraphic").draw(canvas, a, width);
    });
    Rect b = c.bounds(128);
    EXPECT_GE(b.x0, 150 - width);
    EXPECT_GE(b.y0, 150 - width);
    EXPECT_GT(c.count(), 0.1 * (M_PI / 2 * 100) * width);
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (c.covered(x, y)) {
                ASSERT_NEAR(std::hypot(x + 0.5 - 150, y + 0.5 - 150), 100, width / 2 + 1);
            }
}

TEST(SkeletalStroke, ClosedOutlinesAreFollowedAllRound) {
    CircleProxy circle;
    circle.set({100, 100}, 60);
    PolygonProxy square;
    square.set({{40, 40}, {160, 40}, {160, 160}, {40, 160}});
    for (const Proxy* p : std::initializer_list<const Proxy*>{&circle, &square}) {
        Coverage c(200, 200,
                   [&](Canvas& canvas) { SkeletalStroke::builtin("beaded").draw(canvas, *p, 10); });
        EXPECT_GT(c.count(), 0);
        // Beads on all four sides, none in the middle.
        Rect b = c.bounds(128);
        EXPECT_LT(b.x0, 45);
        EXPECT_GT(b.x1, 155);
        EXPECT_LT(b.y0, 45);
        EXPECT_GT(b.y1, 155);
        EXPECT_FALSE(c.covered(100, 100));
    }
}

TEST(SkeletalStroke, PolylineSkeletonWithSharpCornerIsFilledAlongBothLegs) {
    Coverage c(200, 200, [&](Canvas& canvas) {
        SkeletalStroke::builtin("ribbon").draw(canvas, {{20, 20}, {180, 20}, {180, 180}}, 10);
    });
    EXPECT_TRUE(c.covered(30, 20));
    EXPECT_TRUE(c.covered(180, 170));
    EXPECT_FALSE(c.covered(100, 100));
}

TEST(SkeletalStroke, ChainOfCurvesIsOneStroke) {
    const auto& s = SkeletalStroke::builtin("tapered");
    LineSegmentProxy a = segment_proxy({20, 50}, {120, 50}),
                     b = segment_proxy({120, 50}, {220, 50});
    BezierProxy unset;  // left out of the chain
    Coverage whole(240, 100, [&](Canvas& c) { s.draw(c, segment_proxy({20, 50}, {220, 50}), 20); });
    Coverage chain(240, 100, [&](Canvas& c) { s.draw(c, {&a, &unset, &b}, 20); });
    EXPECT_NEAR(chain.count(), whole.count(), 4);
    // One taper over the whole chain: still full width past the first curve's end.
    EXPECT_NEAR(chain.column(125), 20 * (1 - std::pow((0.525 - 0.2) / 0.8, 1.6)), 1.5);
    EXPECT_EQ(chain.count(1), whole.count(1));
}

TEST(SkeletalStroke, DegenerateSkeletonsDrawNothing) {
    const auto& s = SkeletalStroke::builtin("tapered");
    BezierProxy dot;
    dot.set({50, 50}, {50, 50}, {50, 50}, {50, 50});
    BezierProxy unset;  // NaN control points
    LineSegmentProxy nan_end = segment_proxy({10, 10}, {NAN, 20});
    CircleProxy zero_circle;
    zero_circle.set({50, 50}, 0);
    ArcProxy zero_arc;
    zero_arc.set({50, 50}, 20, 1, 1);
    PointProxy point;
    point.set({50, 50});
    PolygonProxy empty_polygon;
    empty_polygon.set(std::vector<Point>{});
    Coverage c(100, 100, [&](Canvas& canvas) {
        s.draw(canvas, segment_proxy({50, 50}, {50, 50}), 10);
        for (const Proxy* p : std::initializer_list<const Proxy*>{
                 &dot, &unset, &nan_end, &zero_circle, &zero_arc, &point, &empty_polygon})
            s.draw(canvas, *p, 10);
        s.draw(canvas, segment_proxy({10, 50}, {90, 50}), 0);
        s.draw(canvas, segment_proxy({10, 50}, {90, 50}), -5);
        s.draw(canvas, segment_proxy({10, 50}, {90, 50}), NAN);
        s.draw(canvas, segment_proxy({10, 50}, {90, 50}), INFINITY);
        s.draw(canvas, std::vector<Point>{}, 10);
        s.draw(canvas, std::vector<Point>{{40, 40}}, 10);
        s.draw(canvas, std::vector<Point>{{40, 40}, {40, 40}, {40, 40}}, 10);
        s.draw(canvas, std::vector<Point>{{40, 40}, {NAN, 40}, {60, 40}}, 10);
        SkeletalStroke moved = SkeletalStroke::builtin("leafy");
        SkeletalStroke taken = std::move(moved);
        moved.draw(canvas, segment_proxy({10, 50}, {90, 50}),
                   10);  // NOLINT: use after move on purpose
    });
    EXPECT_EQ(c.status(), CAIRO_STATUS_SUCCESS);
    EXPECT_EQ(c.count(1), 0);
}

TEST(SkeletalStroke, VeryShortSkeletonStaysAtItsPlace) {
    for (const auto& name : SkeletalStroke::builtin_names()) {
        Coverage c(100, 100, [&](Canvas& canvas) {
            SkeletalStroke::builtin(name).draw(canvas, segment_proxy({50, 50}, {50.0001, 50}), 10);
        });
        EXPECT_EQ(c.status(), CAIRO_STATUS_SUCCESS) << name;
        if (c.count(1) > 0) {
            Rect b = c.bounds(1);
            EXPECT_GE(b.x0, 44) << name;
            EXPECT_LE(b.x1, 56) << name;
        }
    }
}

TEST(SkeletalStroke, CopiesDrawTheSame) {
    SkeletalStroke copy = SkeletalStroke::builtin("leafy");
    SkeletalStroke assigned;
    assigned = copy;
    auto draw = [](const SkeletalStroke& s) {
        return Coverage(340, 300, [&](Canvas& canvas) { s.draw(canvas, curvy(), 16); }).count();
    };
    EXPECT_EQ(draw(assigned), draw(SkeletalStroke::builtin("leafy")));
    EXPECT_EQ(assigned.name(), "leafy");
}

// Renders docs/images/stroke-<name>.png when ACANTHUS_STROKE_GALLERY names a directory.
TEST(SkeletalStroke, Gallery) {
    const char* dir = std::getenv("ACANTHUS_STROKE_GALLERY");
    if (!dir) GTEST_SKIP() << "set ACANTHUS_STROKE_GALLERY=DIR to write the gallery images";
    for (const auto& name : SkeletalStroke::builtin_names()) {
        cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 480, 200);
        cairo_t* cr = cairo_create(surface);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        Canvas canvas(cr);
        canvas.set_color(0.12, 0.3, 0.18);
        BezierProxy s;
        s.set({30, 150}, {120, -20}, {250, 260}, {330, 60});
        SkeletalStroke::builtin(name).draw(canvas, s, 26);
        ArcProxy a;
        a.set({405, 110}, 45, M_PI, 3.2 * M_PI);
        SkeletalStroke::builtin(name).draw(canvas, a, 14);
        std::string out = std::string(dir) + "/stroke-" + name + ".png";
        EXPECT_EQ(cairo_surface_write_to_png(surface, out.c_str()), CAIRO_STATUS_SUCCESS) << out;
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
}

}  // namespace
