// Canvas drawing of every proxy kind, the hue wheel and colour parsing.
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/canvas.hpp>
#include <acanthus/error.hpp>
#include <cmath>
#include <cstdint>

#include "draw/default_style.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

// A 100x100 ARGB image with a Canvas in pixel units, drawing opaque black lines 2 px wide.
class Raster {
  public:
    Raster() {
        surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 100, 100);
        cr_ = cairo_create(surface_);
        cairo_set_line_width(cr_, 2);
    }
    ~Raster() {
        cairo_destroy(cr_);
        cairo_surface_destroy(surface_);
    }
    Canvas canvas() { return Canvas(cr_); }
    cairo_t* cr() { return cr_; }
    // Alpha of the pixel containing (x, y), 0..255.
    int alpha(double x, double y) { return channel(x, y, 24); }
    int red(double x, double y) { return channel(x, y, 16); }
    int blue(double x, double y) { return channel(x, y, 0); }

  private:
    int channel(double x, double y, int shift) {
        cairo_surface_flush(surface_);
        const unsigned char* data = cairo_image_surface_get_data(surface_);
        int stride = cairo_image_surface_get_stride(surface_);
        auto row = reinterpret_cast<const std::uint32_t*>(data + static_cast<int>(y) * stride);
        return static_cast<int>((row[static_cast<int>(x)] >> shift) & 0xff);
    }
    cairo_surface_t* surface_;
    cairo_t* cr_;
};

}  // namespace

TEST(Hue, EndpointsRunRedToPurpleAndWrap) {
    Color red = hue(0.0);
    EXPECT_GT(red.r, 0.85);
    EXPECT_LT(red.g, 0.2);
    EXPECT_LT(red.b, 0.2);
    Color green = hue(1.0 / 3);
    EXPECT_GT(green.g, green.r + 0.5);
    EXPECT_GT(green.g, green.b + 0.5);
    Color blue = hue(2.0 / 3);
    EXPECT_GT(blue.b, blue.r + 0.5);
    EXPECT_GT(blue.b, blue.g + 0.5);
    Color purple = hue(detail::order_hue(9, 10));
    EXPECT_GT(purple.b, purple.r);
    EXPECT_GT(purple.r, purple.g + 0.4);
    Color wrapped = hue(1.0);
    EXPECT_DOUBLE_EQ(wrapped.r, red.r);
    EXPECT_DOUBLE_EQ(wrapped.g, red.g);
    EXPECT_DOUBLE_EQ(wrapped.b, red.b);
    Color far = hue(2.25), quarter = hue(0.25);
    EXPECT_NEAR(far.r, quarter.r, 1e-12);
    EXPECT_NEAR(far.g, quarter.g, 1e-12);
    EXPECT_DOUBLE_EQ(hue(0.3, 0.0, 0.5).r, 0.5);  // no saturation: grey
    EXPECT_DOUBLE_EQ(hue(0.3, 0.0, 0.5).b, 0.5);
}

TEST(Hue, OrderStyleGoesFromOldestRedToNewestPurple) {
    EXPECT_DOUBLE_EQ(detail::order_hue(0, 100), 0.0);
    EXPECT_DOUBLE_EQ(detail::order_hue(99, 100), 0.8);
    EXPECT_DOUBLE_EQ(detail::order_hue(0, 1), 0.0);
    EXPECT_LT(detail::order_hue(10, 100), detail::order_hue(11, 100));
}

TEST(ParseColor, AcceptsHexNamesAndNone) {
    Color white = parse_color("#fff");
    EXPECT_DOUBLE_EQ(white.r, 1);
    EXPECT_DOUBLE_EQ(white.g, 1);
    EXPECT_DOUBLE_EQ(white.b, 1);
    EXPECT_DOUBLE_EQ(white.a, 1);
    Color c = parse_color("#336699");
    EXPECT_DOUBLE_EQ(c.r, 0x33 / 255.0);
    EXPECT_DOUBLE_EQ(c.g, 0x66 / 255.0);
    EXPECT_DOUBLE_EQ(c.b, 0x99 / 255.0);
    Color half = parse_color("#FF000080");
    EXPECT_DOUBLE_EQ(half.r, 1);
    EXPECT_DOUBLE_EQ(half.a, 128 / 255.0);
    Color shorta = parse_color("#0f08");
    EXPECT_DOUBLE_EQ(shorta.g, 1);
    EXPECT_DOUBLE_EQ(shorta.a, 0x88 / 255.0);
    EXPECT_DOUBLE_EQ(parse_color("none").a, 0);
    EXPECT_DOUBLE_EQ(parse_color("Transparent").a, 0);
    Color navy = parse_color(" Navy ");
    EXPECT_DOUBLE_EQ(navy.b, 128 / 255.0);
    EXPECT_DOUBLE_EQ(navy.r, 0);
    for (const char* name : {"black",   "silver", "gray",   "white", "maroon", "red",    "purple",
                             "fuchsia", "green",  "lime",   "olive", "yellow", "navy",   "blue",
                             "teal",    "aqua",   "orange", "grey",  "cyan",   "magenta"})
        EXPECT_NO_THROW(parse_color(name)) << name;
    EXPECT_DOUBLE_EQ(parse_color("lime").g, 1);
    EXPECT_DOUBLE_EQ(parse_color("green").g, 128 / 255.0);
}

TEST(ParseColor, RejectsMalformedText) {
    for (const char* bad : {"", "#", "#ggg", "#12345", "#1234567", "#123456789", "reddish",
                            "rgb(1,2,3)", "##fff", "#ff 00 00", "light blue"}) {
        try {
            parse_color(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("bad colour"), std::string::npos);
        }
    }
}

TEST(Canvas, FillsACircleProxyInsideOnly) {
    Raster r;
    Canvas canvas = r.canvas();
    CircleProxy c;
    c.set({50, 50}, 20);
    canvas.fill(c);
    EXPECT_EQ(r.alpha(50, 50), 255);
    EXPECT_EQ(r.alpha(50, 32), 255);
    EXPECT_EQ(r.alpha(50, 25), 0);
    EXPECT_EQ(r.alpha(75, 50), 0);
}

TEST(Canvas, StrokesACircleAsARing) {
    Raster r;
    Canvas canvas = r.canvas();
    CircleProxy c;
    c.set({50, 50}, 20);
    canvas.stroke(c);
    EXPECT_EQ(r.alpha(50, 50), 0);
    EXPECT_GT(r.alpha(70, 50), 100);
    EXPECT_GT(r.alpha(50, 30), 100);
}

TEST(Canvas, ArcRunsCounterClockwiseInAngleFromStartToEnd) {
    // y points down: angle pi/2 is below the centre.
    Raster r;
    Canvas canvas = r.canvas();
    ArcProxy a;
    a.set({50, 50}, 30, 0, M_PI / 2);
    canvas.stroke(a);
    Point in = Point{50, 50}.offset(Direction(M_PI / 4), 30);
    Point out = Point{50, 50}.offset(Direction(-M_PI / 4), 30);
    EXPECT_GT(r.alpha(in.x, in.y), 100);
    EXPECT_EQ(r.alpha(out.x, out.y), 0);
    EXPECT_GT(r.alpha(50.5, 80), 100);  // end point, straight below

    Raster wrap;
    Canvas w = wrap.canvas();
    ArcProxy across;
    across.set({50, 50}, 30, 3 * M_PI / 2, M_PI / 2);  // end < start: passes through angle 0
    w.stroke(across);
    EXPECT_GT(wrap.alpha(80, 50.5), 100);
    EXPECT_EQ(wrap.alpha(20, 50), 0);
}

TEST(Canvas, StrokesSegmentsAndBeziersThroughTheirPoints) {
    Raster r;
    Canvas canvas = r.canvas();
    LineSegmentProxy s;
    s.set({10, 10}, {90, 10});
    canvas.stroke(s);
    EXPECT_GT(r.alpha(50, 10), 100);
    EXPECT_EQ(r.alpha(50, 14), 0);
    EXPECT_EQ(r.alpha(95, 10), 0);

    BezierProxy b;
    b.set({10, 90}, {30, 40}, {70, 40}, {90, 90});
    canvas.stroke(b);
    Point mid = b.at(0.5);
    EXPECT_GT(r.alpha(mid.x, mid.y), 100);
    EXPECT_EQ(r.alpha(50, 80), 0);
}

TEST(Canvas, FillsAConcavePolygonClosed) {
    Raster r;
    Canvas canvas = r.canvas();
    PolygonProxy p;  // a U shape: the notch stays empty
    p.set({{10, 10}, {30, 10}, {30, 60}, {70, 60}, {70, 10}, {90, 10}, {90, 90}, {10, 90}});
    canvas.fill(p);
    EXPECT_EQ(r.alpha(20, 50), 255);
    EXPECT_EQ(r.alpha(80, 50), 255);
    EXPECT_EQ(r.alpha(50, 80), 255);
    EXPECT_EQ(r.alpha(50, 30), 0);

    Raster outline;
    Canvas o = outline.canvas();
    PolygonProxy tri;
    tri.set({{10, 10}, {90, 10}, {10, 90}});
    o.stroke(tri);
    EXPECT_GT(outline.alpha(10, 50), 100);  // the closing edge is drawn
    EXPECT_GT(outline.alpha(50, 50), 100);  // the hypotenuse
}

TEST(Canvas, DrawsAPointAsASmallDot) {
    Raster r;
    Canvas canvas = r.canvas();
    PointProxy p;
    p.set({50, 50});
    canvas.stroke(p);
    EXPECT_EQ(r.alpha(50, 50), 255);
    EXPECT_EQ(r.alpha(50, 58), 0);
}

TEST(Canvas, UnsetProxiesAddNothing) {
    Raster r;
    Canvas canvas = r.canvas();
    CircleProxy c;
    canvas.add_proxy(c);
    EXPECT_FALSE(cairo_has_current_point(r.cr()));
    canvas.fill(c);
    EXPECT_EQ(cairo_status(r.cr()), CAIRO_STATUS_SUCCESS);
}

TEST(Canvas, PathOperationsAndColoursReachCairo) {
    Raster r;
    Canvas canvas = r.canvas();
    canvas.set_line_width(6);
    EXPECT_DOUBLE_EQ(canvas.line_width(), 6);
    canvas.set_color(1, 0, 0);
    canvas.move_to({10, 20});
    canvas.line_to({90, 20});
    canvas.curve_to({90, 40}, {90, 40}, {90, 60});
    canvas.stroke();
    EXPECT_EQ(r.red(50, 20), 255);
    EXPECT_EQ(r.blue(50, 20), 0);

    canvas.save();
    canvas.set_color(parse_color("blue"));
    canvas.move_to({10, 70});
    canvas.line_to({40, 70});
    canvas.line_to({40, 95});
    canvas.close_path();
    canvas.fill();
    canvas.restore();
    EXPECT_EQ(r.blue(35, 75), 255);

    canvas.fill_circle({70, 80}, 5, Color{0, 0, 1, 1});
    EXPECT_EQ(r.blue(70, 80), 255);
    canvas.fill_circle({20, 50}, 4);  // the source is red again after fill_circle(colour)
    EXPECT_EQ(r.red(20, 50), 255);
    EXPECT_EQ(r.blue(20, 50), 0);
    canvas.arc({60, 45}, 3, 0, 2 * M_PI);
    canvas.fill();
    EXPECT_EQ(r.red(60, 45), 255);
    EXPECT_EQ(canvas.cairo(), r.cr());
}

TEST(Canvas, PixelIsOneOutputPixelInUserUnits) {
    Raster r;
    Canvas c = r.canvas();
    EXPECT_DOUBLE_EQ(c.pixel(), 1.0);
    cairo_scale(r.cr(), 4, 2);  // user units: 4 px across, 2 px down; the coarser one counts
    EXPECT_DOUBLE_EQ(c.pixel(), 0.5);
    cairo_rotate(r.cr(), 0.7);
    EXPECT_NEAR(c.pixel(), 0.5, 1e-12);
}
