// The band (docs/symmetry.md): the centre line read from SVG and parametrized by arc length, the
// bend (s, t) -> C(s) + t N(s), the refusal of a band wider than twice the smallest radius of
// curvature, and shapes drawn in the straight band coming out bent.
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/canvas.hpp>
#include <acanthus/error.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "output/band_sink.hpp"
#include "region/band.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

Band band_of(const std::string& path_data, double width) {
    return Band::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"" + path_data + "\"/></svg>", "test",
        width);
}

const char* circle100 = "M 300 200 A 100 100 0 0 1 100 200 A 100 100 0 0 1 300 200 Z";

// Records the points of every path it is handed.
struct Recorder : CanvasSink {
    std::vector<std::vector<Point>> paths;
    void path(cairo_t* cr, bool) override {
        cairo_path_t* p = cairo_copy_path_flat(cr);
        paths.emplace_back();
        for (int i = 0; i < p->num_data; i += p->data[i].header.length)
            if (p->data[i].header.type != CAIRO_PATH_CLOSE_PATH)
                paths.back().push_back({p->data[i + 1].point.x, p->data[i + 1].point.y});
        cairo_path_destroy(p);
    }
    void circle(cairo_t*, Point, double, bool) override {}
    void polygon(cairo_t*, const std::vector<Point>&, bool) override {}
};

}  // namespace

TEST(Band, AStraightCentreLineIsTheStraightBand) {
    const Band b = band_of("M 0 0 H 300", 40);
    EXPECT_NEAR(b.length(), 300, 1e-6);
    EXPECT_FALSE(b.closed());
    EXPECT_TRUE(std::isinf(b.min_radius()));
    for (Point st : {Point{0, 0}, Point{150, 20}, Point{299, -20}, Point{-10, 5}, Point{310, 5}}) {
        const Point p = b.map(st);
        EXPECT_NEAR(p.x, st.x, 1e-6);
        EXPECT_NEAR(p.y, st.y, 1e-6);  // N points down the page: t grows with y
    }
    const Rect r = b.straight_region().bounds();
    EXPECT_NEAR(r.x0, 0, 1e-9);
    EXPECT_NEAR(r.x1, 300, 1e-9);
    EXPECT_NEAR(r.y0, -20, 1e-9);
    EXPECT_NEAR(r.y1, 20, 1e-9);
}

TEST(Band, ACircleIsClosedParametrizedByArcLengthAndBendsTheBandIntoARing) {
    const Band b = band_of(circle100, 60);
    EXPECT_TRUE(b.closed());
    EXPECT_NEAR(b.length(), 2 * std::numbers::pi * 100, 0.05);
    EXPECT_NEAR(b.min_radius(), 100, 2);
    const double L = b.length();
    for (int k = 0; k < 50; ++k) {
        const double s = L * k / 50;
        for (double t : {-30.0, 0.0, 30.0}) {
            const Point p = b.map({s, t});
            EXPECT_NEAR(std::abs(std::hypot(p.x - 200, p.y - 200) - 100), std::abs(t), 0.05);
        }
        // Arc length: a step ds along s moves the centre ds along the circle.
        const Point a = b.map({s, 0}), c = b.map({s + 1, 0});
        EXPECT_NEAR(std::hypot(c.x - a.x, c.y - a.y), 1, 1e-3);
    }
    // It wraps: s and s + L are the same point.
    const Point p = b.map({10, 5}), q = b.map({10 + L, 5});
    EXPECT_NEAR(p.x, q.x, 1e-9);
    EXPECT_NEAR(p.y, q.y, 1e-9);
    EXPECT_EQ(b.outline(0.1).size(), 2u);  // a closed band is an annulus
    EXPECT_EQ(band_of("M 0 0 H 300", 40).outline(0.1).size(), 1u);
}

TEST(Band, AWidthOverTwiceTheSmallestRadiusIsRefused) {
    EXPECT_NO_THROW(band_of(circle100, 190));
    try {
        band_of(circle100, 210);
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("radius of curvature"), std::string::npos) << e.what();
    }
    // A corner has no radius: any width folds.
    EXPECT_THROW(band_of("M 0 0 L 200 0 L 200 200", 2), UsageError);
    // A gentle S curve takes its band.
    EXPECT_NO_THROW(band_of("M 0 0 C 100 -50 200 50 300 0", 20));
    for (double bad : {0.0, -5.0, std::nan("")})
        EXPECT_THROW(band_of("M 0 0 H 300", bad), UsageError);
}

TEST(Band, TheCentreLineIsOnePath) {
    EXPECT_THROW(band_of("M 0 0 H 300 M 0 50 H 300", 10), InputError);  // two subpaths
    EXPECT_THROW(Band::from_svg_string("<svg xmlns=\"http://www.w3.org/2000/svg\"/>", "empty", 10),
                 InputError);
    EXPECT_THROW(Band::from_svg_file("/no/such/centre-line.svg", 10), InputError);
}

TEST(Band, ShapesDrawnInTheStraightBandComeOutBent) {
    const Band b = band_of(circle100, 40);
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
    cairo_t* straight = cairo_create(surface);
    cairo_t* target = cairo_create(surface);
    Recorder recorder;
    BandSink sink(b, target, 0.01, &recorder);
    Canvas canvas(straight, &sink);
    // A line along the whole centre line, 10 below it: a circle of radius 110 (N points out of
    // this clockwise-on-the-page circle, as y points down).
    canvas.move_to({0, 10});
    canvas.line_to({b.length(), 10});
    canvas.stroke();
    ASSERT_EQ(recorder.paths.size(), 1u);
    const auto& ring = recorder.paths.front();
    EXPECT_GT(ring.size(), 100u);  // subdivided, so that it follows the bend
    const double radius = std::hypot(ring.front().x - 200, ring.front().y - 200);
    EXPECT_NEAR(std::abs(radius - 100), 10, 0.05);
    for (const Point& p : ring) EXPECT_NEAR(std::hypot(p.x - 200, p.y - 200), radius, 0.05);
    // A circle drawn in the band (a dot) stays a closed curve of the same size, near its place.
    canvas.fill_circle({b.length() / 4, 0}, 5);
    ASSERT_EQ(recorder.paths.size(), 2u);
    const Point centre = b.map({b.length() / 4, 0});
    for (const Point& p : recorder.paths.back())
        EXPECT_NEAR(std::hypot(p.x - centre.x, p.y - centre.y), 5, 0.3);
    cairo_destroy(straight);
    cairo_destroy(target);
    cairo_surface_destroy(surface);
}
