// CoalescingSink (PDF, PostScript, EPS): shapes of one colour and style gathered into one Cairo
// operation while nothing painted between them touches them, and the picture unchanged: a
// coalesced PDF of a few thousand dots rasterized by pdftoppm against the one drawn operation by
// operation.
#include <cairo-pdf.h>
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <sstream>
#include <string>

#include "draw/coalescing_sink.hpp"
#include "fixtures/sample_elements.hpp"
#include "fixtures/temp_dir.hpp"

using namespace acanthus;
using namespace acanthus::detail;
using namespace acanthus::test;

namespace {

// A PDF page drawn to nowhere: the sink's counts are what is looked at.
struct Page {
    cairo_surface_t* surface;
    cairo_t* cr;
    Page()
        : surface(cairo_pdf_surface_create_for_stream(
              [](void*, const unsigned char*, unsigned int) { return CAIRO_STATUS_SUCCESS; },
              nullptr, 400, 300)),
          cr(cairo_create(surface)) {
        // As the renderer draws: round joins (a mitred join may reach ten half-widths out).
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    }
    ~Page() {
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
    }
};

CircleProxy circle(Point c, double r) {
    CircleProxy p;
    p.set(c, r);
    return p;
}

// A dot as rules/dots.acr draws it: its own colour, then a dark rim.
void dot(Canvas& canvas, Point c, double r, Color fill) {
    canvas.fill_circle(c, r, fill);
    canvas.set_color(0.12, 0.12, 0.18);
    canvas.set_line_width(0.5);
    canvas.stroke(circle(c, r));
}

}  // namespace

TEST(SlotGrid, KeepsTheNewestOpenSlotOfEachCell) {
    SlotGrid grid(100, 50, 4);
    long run, other;
    grid.newest({10, 10, 12, 12}, 0, run, other);
    EXPECT_EQ(run, -1);
    EXPECT_EQ(other, -1);
    grid.mark({10, 10, 12, 12}, 2, 0, true);
    grid.mark({10, 10, 12, 12}, 1, 0, true);  // older: the cell keeps slot 2
    grid.mark({11, 11, 20, 20}, 1, 0, false);
    grid.newest({11.5, 11.5, 30, 30}, 0, run, other);
    EXPECT_EQ(run, 2);
    EXPECT_EQ(other, 1);
    grid.newest({22, 10, 30, 12}, 0, run, other);
    EXPECT_EQ(run, -1);
    // Off the page lands on the border cells.
    grid.mark({-50, 40, -40, 42}, 3, 0, false);
    grid.newest({0, 41, 0.5, 41.5}, 0, run, other);
    EXPECT_EQ(other, 3);
    // Closing slots oldest first clears their marks.
    grid.close(0);
    grid.close(1);
    grid.newest({11.5, 11.5, 30, 30}, 2, run, other);
    EXPECT_EQ(run, 2);
    EXPECT_EQ(other, -1);
    grid.close(2);
    grid.newest({11.5, 11.5, 30, 30}, 3, run, other);
    EXPECT_EQ(run, -1);
    // A box of most of the page is not counted cell by cell: it touches whatever comes next.
    grid.mark({0, 0, 90, 45}, 4, 3, true);
    grid.newest({95, 48, 96, 49}, 3, run, other);
    EXPECT_EQ(run, 4);
    EXPECT_EQ(other, -1);
    // Slot numbers past 255 reuse codes; the open ones stay distinct.
    SlotGrid late(100, 50, 4);
    late.mark({10, 10, 12, 12}, 300, 299, true);
    late.newest({10, 10, 12, 12}, 299, run, other);
    EXPECT_EQ(run, 300);
}

TEST(CoalescingSink, RimsOfApartDotsBecomeOneStroke) {
    Page page;
    CoalescingSink sink(page.cr, 400, 300);
    Canvas canvas(page.cr, &sink);
    // 100 dots 12 units apart, each its own colour: 100 fills, and the rims one stroke once
    // the rim's style has come back 16 times (the first fill's style is the run's until then).
    for (int i = 0; i < 100; ++i)
        dot(canvas, {20.0 + 12 * (i % 25), 20.0 + 12 * (i / 25)}, 4, hue(i / 100.0));
    sink.flush();
    EXPECT_EQ(sink.received(), 200);
    EXPECT_EQ(sink.painted(), 100 + 15 + 1);
    EXPECT_EQ(cairo_status(page.cr), CAIRO_STATUS_SUCCESS);
}

TEST(CoalescingSink, AFillOverAGatheredRimPaintsTheRunFirst) {
    Page page;
    CoalescingSink sink(page.cr, 400, 300);
    Canvas canvas(page.cr, &sink);
    // Touching dots: each fill covers the previous rim, so nothing may wait.
    for (int i = 0; i < 10; ++i) dot(canvas, {20.0 + 8 * i, 20}, 4, hue(i / 10.0));
    sink.flush();
    EXPECT_EQ(sink.painted(), 20);
}

TEST(CoalescingSink, OverlappingFillsOfOneColourStaySeparate) {
    Page page;
    CoalescingSink sink(page.cr, 400, 300);
    Canvas canvas(page.cr, &sink);
    // Half-transparent: an overlap painted once would be lighter than painted twice.
    canvas.fill_circle({50, 50}, 10, Color{0, 0, 1, 0.5});
    canvas.fill_circle({60, 50}, 10, Color{0, 0, 1, 0.5});
    // Apart: one path.
    canvas.fill_circle({150, 50}, 10, Color{0, 0, 1, 0.5});
    sink.flush();
    EXPECT_EQ(sink.received(), 3);
    EXPECT_EQ(sink.painted(), 2);
}

TEST(CoalescingSink, OverlappingOpaqueStrokesOfOneStyleAreOnePath) {
    Page page;
    CoalescingSink sink(page.cr, 400, 300);
    Canvas canvas(page.cr, &sink);
    canvas.set_line_width(2);
    for (int i = 0; i < 5; ++i) canvas.stroke(circle({50.0 + 3 * i, 50}, 10));
    canvas.set_line_width(3);  // another style: the run is painted
    canvas.stroke(circle({60, 50}, 10));
    sink.flush();
    EXPECT_EQ(sink.painted(), 2);
}

TEST(CoalescingSink, ARunHoldsAtMost1024Shapes) {
    Page page;
    CoalescingSink sink(page.cr, 400, 300);
    Canvas canvas(page.cr, &sink);
    canvas.set_line_width(0.2);
    // Cairo outlines a whole stroke at once to find its extents: runs are kept short enough.
    for (int i = 0; i < 2100; ++i)
        canvas.stroke(circle({2.0 + 4 * (i % 99), 2.0 + 4 * (i / 99)}, 0.5));
    sink.flush();
    EXPECT_EQ(sink.painted(), 3);
}

TEST(CoalescingSink, CairoCallsPaintTheRunAndAreFollowedAsTheyCome) {
    Page page;
    CoalescingSink sink(page.cr, 400, 300);
    Canvas canvas(page.cr, &sink);
    canvas.stroke(circle({50, 50}, 10));
    canvas.stroke(circle({100, 50}, 10));
    EXPECT_EQ(sink.painted(), 0);
    cairo_t* cr = canvas.cairo();
    EXPECT_EQ(sink.painted(), 1);
    cairo_rectangle(cr, 0, 0, 10, 10);
    cairo_clip(cr);
    // A clip the sink cannot see: the rest of the element is painted as it comes.
    canvas.stroke(circle({200, 50}, 10));
    canvas.stroke(circle({250, 50}, 10));
    EXPECT_EQ(sink.painted(), 3);
    cairo_reset_clip(cr);
    sink.end_element();
    canvas.stroke(circle({200, 150}, 10));
    canvas.stroke(circle({250, 150}, 10));
    sink.flush();
    EXPECT_EQ(sink.painted(), 4);
}

namespace {

// A few thousand dots on a jittered grid, drawn in a scrambled order (as a growth places them,
// not row by row), every one touching its neighbours: rims cross the next fills now and then.
// Every 37th is half transparent; every 101st draws through canvas.cairo() with a clip.
void many_dots_draw(Canvas& canvas, const Element& e) {
    const auto& d = static_cast<const sample::Dot&>(e);
    Color c = hue(0.8 * d.order / 3000.0);
    if (d.order % 37 == 0) c.a = 0.5;
    if (d.order % 101 == 0) {
        cairo_t* cr = canvas.cairo();
        cairo_save(cr);
        cairo_rectangle(cr, d.c.center.x - d.c.radius, d.c.center.y - d.c.radius, d.c.radius,
                        2 * d.c.radius);
        cairo_clip(cr);
        canvas.fill_circle(d.c.center, d.c.radius, Color{0, 0, 0, 1});
        cairo_restore(cr);
    }
    dot(canvas, d.c.center, d.c.radius, c);
}
const ElementType many_dots_type{"mdot", {ProxyKind::circle}, nullptr, &many_dots_draw, 7};

struct ManyDots {
    std::deque<sample::Dot> dots;
    std::vector<const Element*> placed;
    Pattern pattern;
    explicit ManyDots(const ElementType* type) {
        pattern.name = "many";
        pattern.file = "many.acr";
        pattern.types = {type};
        const int columns = 60, rows = 48, n = columns * rows;
        std::uint32_t state = 12345;
        for (int k = 0; k < n; ++k) {
            // A fixed permutation of the cells (an odd stride coprime with n) with jitter.
            int cell = static_cast<int>((static_cast<long>(k) * 1367) % n);
            state = state * 1664525u + 1013904223u;
            double jitter = (state >> 8) % 1000 / 1000.0 - 0.5;
            auto& d = dots.emplace_back();
            d.kind = type;
            d.id = k;
            d.order = k;
            d.c.set({1.0 + 1.65 * (cell % columns) + 0.2 * jitter, 1.0 + 1.65 * (cell / columns)},
                    0.85 + 0.1 * jitter);
            placed.push_back(&d);
        }
    }
};

struct Raster {
    cairo_surface_t* s;
    explicit Raster(const std::string& path)
        : s(cairo_image_surface_create_from_png(path.c_str())) {}
    ~Raster() { cairo_surface_destroy(s); }
    bool ok() const { return cairo_surface_status(s) == CAIRO_STATUS_SUCCESS; }
};

// Mean absolute channel difference (0..255) and the fraction of pixels off by more than 96.
std::pair<double, double> difference(const Raster& a, const Raster& b) {
    int w = cairo_image_surface_get_width(a.s), h = cairo_image_surface_get_height(a.s);
    if (w != cairo_image_surface_get_width(b.s) || h != cairo_image_surface_get_height(b.s))
        return {1e9, 1};
    double sum = 0;
    long far = 0;
    for (int y = 0; y < h; ++y) {
        const unsigned char* p =
            cairo_image_surface_get_data(a.s) + y * cairo_image_surface_get_stride(a.s);
        const unsigned char* q =
            cairo_image_surface_get_data(b.s) + y * cairo_image_surface_get_stride(b.s);
        for (int x = 0; x < w; ++x) {
            int worst = 0;
            for (int k = 0; k < 4; ++k) {
                int diff = std::abs(int(p[4 * x + k]) - int(q[4 * x + k]));
                sum += diff;
                worst = std::max(worst, diff);
            }
            if (worst > 96) ++far;
        }
    }
    return {sum / (4.0 * w * h), double(far) / (double(w) * h)};
}

// Fills and strokes of a PostScript page: the operators f, f* and S.
int painting_operators(const std::string& ps) {
    std::istringstream in(ps.substr(ps.find("%%EndPageSetup")));
    std::string token;
    int n = 0;
    while (in >> token) n += token == "f" || token == "f*" || token == "S";
    return n;
}

}  // namespace

TEST(Coalescing, ThePdfOfThousandsOfDotsIsTheSamePicture) {
    TempDir dir;
    Region region = Region::from_spec("rect:100,80");
    struct Case {
        const ElementType* type;
        const char* style;
    };
    for (Case c : {Case{&many_dots_type, "drawn"}, Case{&sample::dot_type, "filled"},
                   Case{&sample::dot_type, "outline"}, Case{&many_dots_type, "overlay"}}) {
        SCOPED_TRACE(c.style);
        ManyDots many(c.type);
        RenderOptions o;
        o.width = 600;
        o.style = c.style;
        render_to_file(dir / "gathered.pdf", many.pattern, region, many.placed, o);
        render_to_file(dir / "gathered.ps", many.pattern, region, many.placed, o);
        o.coalesce = false;
        render_to_file(dir / "each.pdf", many.pattern, region, many.placed, o);
        render_to_file(dir / "each.ps", many.pattern, region, many.placed, o);
        for (const char* name : {"gathered", "each"}) {
            std::string command = "pdftoppm -r 144 -png -singlefile '" + (dir / name) + ".pdf' '" +
                                  (dir / name) + "' >/dev/null 2>&1";
            ASSERT_EQ(std::system(command.c_str()), 0) << command;
        }
        Raster gathered(dir / "gathered.png"), each(dir / "each.png");
        ASSERT_TRUE(gathered.ok());
        ASSERT_TRUE(each.ok());
        auto [mean, far] = difference(gathered, each);
        std::printf("%s: mean difference %.3f, pixels far off %.4f%%\n", c.style, mean, 100 * far);
        // Where outlines of one colour cross, the union's antialiased edge is not two edges
        // painted one over the other (outline: 4 % of the pixels, by 2 levels on average); no
        // shape is missing or recoloured. The structured SVG's bounds against the PNG are 1.5
        // and 0.5 %.
        EXPECT_LT(mean, 1.0);
        EXPECT_LT(far, 1e-3);
        // And far fewer operations: PostScript shows them as text.
        std::string a = slurp(dir / "gathered.ps"), b = slurp(dir / "each.ps");
        int gathered_ops = painting_operators(a), each_ops = painting_operators(b);
        EXPECT_GT(each_ops, 2000);  // half-transparent shapes are images in PostScript
        EXPECT_LT(gathered_ops, each_ops * 3 / 4) << gathered_ops << " of " << each_ops;
    }
}
