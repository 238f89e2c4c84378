// render_to_file and render_debug_frame: every format opened by a real reader, reproducible
// bytes, styles, %draw, debug frames, skeletal strokes.
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "fixtures/sample_elements.hpp"
#include "fixtures/temp_dir.hpp"
#include "output/document.hpp"
#include "output/dsc_rewriter.hpp"

using namespace acanthus;
using namespace acanthus::detail;
using namespace acanthus::test;
namespace fs = std::filesystem;

namespace {

int run(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

Region panel() { return Region::from_spec("rect:100,80"); }

RenderOptions options(double width = 400, std::string style = "outline") {
    RenderOptions o;
    o.width = width;
    o.style = std::move(style);
    return o;
}

struct Image {
    cairo_surface_t* surface;
    explicit Image(const std::string& path)
        : surface(cairo_image_surface_create_from_png(path.c_str())) {}
    ~Image() { cairo_surface_destroy(surface); }
    bool ok() const { return cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS; }
    int width() const { return cairo_image_surface_get_width(surface); }
    int height() const { return cairo_image_surface_get_height(surface); }
    std::uint32_t at(int x, int y) const {
        const unsigned char* data = cairo_image_surface_get_data(surface);
        int stride = cairo_image_surface_get_stride(surface);
        return reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];
    }
    int channel(int x, int y, int shift) const { return (at(x, y) >> shift) & 0xff; }
    int alpha(int x, int y) const { return channel(x, y, 24); }
    int r(int x, int y) const { return channel(x, y, 16); }
    int g(int x, int y) const { return channel(x, y, 8); }
    int b(int x, int y) const { return channel(x, y, 0); }
    // Extremes over the 5x5 pixels around (x, y): thin lines need not hit one exact pixel.
    int max_alpha_near(int x, int y) const {
        int best = 0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) best = std::max(best, alpha(x + dx, y + dy));
        return best;
    }
    int min_red_near(int x, int y) const {
        int best = 255;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) best = std::min(best, r(x + dx, y + dy));
        return best;
    }
};

// Page position of a user point for rect:100,80 at width 400: margin 2, scale 400/104.
std::pair<int, int> page_pixel(Point p) {
    double scale = 400.0 / 104.0;
    double offset_y = 323 / 2.0 - 40 * scale;
    return {static_cast<int>((p.x + 2) * scale), static_cast<int>(p.y * scale + offset_y)};
}

void draw_blue_disc(Canvas& canvas, const Element& e) {
    const auto& c = static_cast<const CircleProxy&>(e.proxy(0));
    canvas.fill_circle(c.center, c.radius, Color{0, 0, 1, 1});
}

const ElementType blue_dot_type{"bluedot", {ProxyKind::circle}, nullptr, &draw_blue_disc, 21};

}  // namespace

TEST(FormatForPath, FollowsTheExtension) {
    EXPECT_EQ(format_for_path("a.svg"), OutputFormat::svg);
    EXPECT_EQ(format_for_path("dir.x/a.PDF"), OutputFormat::pdf);
    EXPECT_EQ(format_for_path("a.ps"), OutputFormat::ps);
    EXPECT_EQ(format_for_path("a.eps"), OutputFormat::eps);
    EXPECT_EQ(format_for_path("a.png"), OutputFormat::png);
    EXPECT_EQ(format_for_path("-"), OutputFormat::svg);
    EXPECT_THROW(format_for_path("a.jpg"), UsageError);
    EXPECT_THROW(format_for_path("noextension"), UsageError);
    EXPECT_THROW(format_for_path("svg"), UsageError);
}

TEST(Render, EveryFormatIsAcceptedByARealReader) {
    TempDir dir;
    sample::Ornament o;
    Region region = panel();
    for (const char* ext : {"svg", "pdf", "ps", "eps", "png"}) {
        std::string file = dir / (std::string("out.") + ext);
        render_to_file(file, o.pattern, region, o.placed, options());
        ASSERT_TRUE(fs::exists(file)) << file;
        EXPECT_GT(fs::file_size(file), 100u) << file;
    }
    EXPECT_EQ(run("rsvg-convert -o " + (dir / "svg.png") + " " + (dir / "out.svg")), 0);
    EXPECT_EQ(run("pdftoppm -r 20 -png " + (dir / "out.pdf") + " " + (dir / "pdf")), 0);
    EXPECT_EQ(run("gs -q -dSAFER -dNOPAUSE -dBATCH -sDEVICE=png16m -r20 -sOutputFile=" +
                  (dir / "ps.png") + " " + (dir / "out.ps")),
              0);
    EXPECT_EQ(run("gs -q -dSAFER -dNOPAUSE -dBATCH -dEPSCrop -sDEVICE=png16m -r72 -sOutputFile=" +
                  (dir / "eps.png") + " " + (dir / "out.eps")),
              0);
    Image svg(dir / "svg.png"), eps(dir / "eps.png"), png(dir / "out.png");
    ASSERT_TRUE(svg.ok());
    ASSERT_TRUE(eps.ok());
    ASSERT_TRUE(png.ok());
    // Width 400, height from the 104 x 84 bounds with margin.
    EXPECT_EQ(png.width(), 400);
    EXPECT_EQ(png.height(), 323);
    EXPECT_EQ(eps.width(), 400);
    EXPECT_EQ(eps.height(), 323);
    EXPECT_TRUE(fs::exists(dir / "pdf-1.png"));
    EXPECT_TRUE(fs::exists(dir / "ps.png"));

    std::string text = slurp(dir / "out.eps");
    EXPECT_NE(text.find("%%BoundingBox: 0 0 400 323\n"), std::string::npos);
    EXPECT_EQ(text.find("%!PS-Adobe-3.0 EPSF-3.0"), 0u);
    // The marks lie inside the declared box (ghostscript's bbox device measures them).
    std::string bbox_log = dir / "bbox.txt";
    ASSERT_EQ(std::system(("gs -q -dSAFER -dNOPAUSE -dBATCH -sDEVICE=bbox " + (dir / "out.eps") +
                           " 2>" + bbox_log + " >/dev/null")
                              .c_str()),
              0);
    std::smatch m;
    std::string log = slurp(bbox_log);
    ASSERT_TRUE(
        std::regex_search(log, m, std::regex(R"(%%BoundingBox: (-?\d+) (-?\d+) (-?\d+) (-?\d+))")))
        << log;
    EXPECT_GE(std::stoi(m[1]), 0);
    EXPECT_GE(std::stoi(m[2]), 0);
    EXPECT_LE(std::stoi(m[3]), 400);
    EXPECT_LE(std::stoi(m[4]), 323);
    EXPECT_GT(std::stoi(m[3]) - std::stoi(m[1]), 300);  // the region outline spans the page
}

TEST(Render, OutputIsByteIdenticalOnReRender) {
    TempDir dir;
    sample::Ornament o;
    Region region = panel();
    for (const char* ext : {"svg", "pdf", "ps", "eps", "png"}) {
        std::string a = dir / (std::string("a.") + ext), b = dir / (std::string("b.") + ext);
        render_to_file(a, o.pattern, region, o.placed, options(300, "order"));
        // Another document in between advances Cairo's process-wide surface counters.
        render_to_file(dir / "other.svg", o.pattern, region, o.placed, options(200, "filled"));
        render_to_file(b, o.pattern, region, o.placed, options(300, "order"));
        std::string first = slurp(a), second = slurp(b);
        EXPECT_FALSE(first.empty());
        EXPECT_TRUE(first == second) << ext << " differs between two renders";
    }
    std::string ps = slurp(dir / "a.ps");
    EXPECT_NE(ps.find("%%CreationDate: Sat Jan  1 00:00:00 2000\n"), std::string::npos);
    std::string pdf = slurp(dir / "a.pdf");
    EXPECT_NE(pdf.find("/CreationDate (20000101000000Z)"), std::string::npos);
    EXPECT_NE(pdf.find("/ModDate (20000101000000Z)"), std::string::npos);
    // Cairo 1.16 leaves out the optional "D:" prefix; poppler still reads the date.
    ASSERT_EQ(std::system(("pdfinfo " + (dir / "a.pdf") + " >" + (dir / "info.txt")).c_str()), 0);
    EXPECT_NE(slurp(dir / "info.txt").find("Jan  1 00:00:00 2000"), std::string::npos);
    std::string svg = slurp(dir / "a.svg");
    EXPECT_NE(svg.find("id=\"layer-dot\""), std::string::npos);  // the structured SVG
}

TEST(Render, SvgSurfaceIdsAreRenumberedInOrderOfAppearance) {
    std::string in = R"(<g id="surface17"><use xlink:href="#surface20"/><g id="surface20"/>)"
                     R"(<image id="image9"/></g><path id="surfaceX"/>)";
    EXPECT_EQ(detail::renumber_svg_surface_ids(in),
              R"(<g id="surface1"><use xlink:href="#surface2"/><g id="surface2"/>)"
              R"(<image id="image1"/></g><path id="surfaceX"/>)");
}

TEST(Render, OrderStyleColoursOldestRedToNewestPurple) {
    TempDir dir;
    sample::Ornament o;
    render_to_file(dir / "order.png", o.pattern, panel(), o.placed, options(400, "order"));
    Image img(dir / "order.png");
    ASSERT_TRUE(img.ok());
    auto [x0, y0] = page_pixel(o.dots[0].c.center);  // id 1 of 9: red-orange
    EXPECT_EQ(img.alpha(x0, y0), 255);
    EXPECT_GT(img.r(x0, y0), img.b(x0, y0) + 100);
    auto [x1, y1] = page_pixel({10, 72});  // the petal, placed last: purple
    EXPECT_GT(img.b(x1, y1), img.g(x1, y1) + 100);
    EXPECT_GT(img.r(x1, y1), img.g(x1, y1) + 60);
    auto [xs, ys] = page_pixel({55, 72});  // empty inside the region: transparent
    EXPECT_EQ(img.alpha(xs, ys), 0);
}

TEST(Render, OutlineLeavesAreasOpenFilledFillsThem) {
    TempDir dir;
    sample::Ornament o;
    Region region = panel();
    render_to_file(dir / "outline.png", o.pattern, region, o.placed, options());
    render_to_file(dir / "filled.png", o.pattern, region, o.placed, options(400, "filled"));
    Image outline(dir / "outline.png"), filled(dir / "filled.png");
    auto [x, y] = page_pixel(o.dots[2].c.center);
    EXPECT_EQ(outline.alpha(x, y), 0);
    EXPECT_EQ(filled.alpha(x, y), 255);
    EXPECT_GT(filled.g(x, y), 150);
    auto [ex, ey] = page_pixel({o.dots[2].c.center.x + 6, o.dots[2].c.center.y});  // on the rim
    EXPECT_GT(outline.max_alpha_near(ex, ey), 100);
    EXPECT_LT(outline.r(ex, ey), 60);
}

TEST(Render, DrawFunctionWinsInDrawnAndOverlayStylesOnly) {
    TempDir dir;
    sample::Ornament o;
    o.dots[3].kind = &blue_dot_type;
    Region region = panel();
    auto [x, y] = page_pixel(o.dots[3].c.center);
    render_to_file(dir / "draw.png", o.pattern, region, o.placed, options(400, "drawn"));
    Image drawn(dir / "draw.png");
    EXPECT_EQ(drawn.b(x, y), 255);
    EXPECT_EQ(drawn.r(x, y), 0);
    render_to_file(dir / "order.png", o.pattern, region, o.placed, options(400, "order"));
    Image order(dir / "order.png");
    EXPECT_EQ(order.alpha(x, y), 255);
    EXPECT_LT(order.b(x, y), 250);  // coloured by order (green-cyan), not by %draw
    // Outline shows the proxies themselves (Figure 15(d)): the disc's inside stays empty.
    render_to_file(dir / "outline.png", o.pattern, region, o.placed, options(400, "outline"));
    EXPECT_EQ(Image(dir / "outline.png").alpha(x, y), 0);
    // Overlay: the %draw picture over faint proxies; elements without %draw show faintly only.
    render_to_file(dir / "overlay.png", o.pattern, region, o.placed, options(400, "overlay"));
    Image overlay(dir / "overlay.png");
    EXPECT_EQ(overlay.b(x, y), 255);
    EXPECT_EQ(overlay.r(x, y), 0);
    auto [ex, ey] = page_pixel({o.dots[2].c.center.x + 6, o.dots[2].c.center.y});
    EXPECT_GT(overlay.max_alpha_near(ex, ey), 20);
    EXPECT_LT(overlay.max_alpha_near(ex, ey), 200);
}

TEST(Render, BackgroundAndRegionOutline) {
    TempDir dir;
    sample::Ornament o;
    RenderOptions opt = options();
    opt.background = parse_color("white");
    render_to_file(dir / "bg.png", o.pattern, panel(), o.placed, opt);
    Image bg(dir / "bg.png");
    EXPECT_EQ(bg.at(0, 0), 0xffffffffu);
    auto [rx, ry] = page_pixel({100, 40});  // the region's right edge: grey outline
    EXPECT_LT(bg.min_red_near(rx, ry), 240);
    EXPECT_EQ(bg.r(rx, ry), bg.b(rx, ry));

    opt.background.reset();
    opt.draw_region = false;
    render_to_file(dir / "bare.png", o.pattern, panel(), o.placed, opt);
    Image bare(dir / "bare.png");
    EXPECT_EQ(bare.alpha(0, 0), 0);
    EXPECT_EQ(bare.max_alpha_near(rx, ry), 0);
}

TEST(Render, SeedsAreNotDrawn) {
    TempDir dir;
    sample::Ornament o;
    o.dots[0].c.set({60, 40}, 3);  // move the first dot off the seed
    render_to_file(dir / "seed.png", o.pattern, panel(), o.placed, options(400, "order"));
    Image img(dir / "seed.png");
    auto [x, y] = page_pixel(o.seeds[0].p.point());
    EXPECT_EQ(img.alpha(x, y), 0);
}

TEST(DebugFrame, DrawsFigureEightColours) {
    TempDir dir;
    sample::Ornament o;
    DebugFrame frame;
    frame.iteration = 7;
    frame.grid = GridFrame{0, 0, 2, 50, 40};  // 2 user units per pixel over 100 x 80
    frame.occupancy.assign(50 * 40, 0);
    for (int i = 0; i < 50; ++i) frame.occupancy[i] = frame.occupancy[39 * 50 + i] = 1;
    for (int j = 0; j < 40; ++j) frame.occupancy[j * 50] = frame.occupancy[j * 50 + 49] = 1;
    for (int j = 27; j < 33; ++j)
        for (int i = 7; i < 13; ++i) frame.occupancy[j * 50 + i] = 2;
    frame.eligible = {Circle{{60, 50}, 10}, Circle{{30, 20}, 6}};
    frame.excluded = {Circle{{80, 20}, 7}};
    frame.chosen = Circle{{60, 50}, 10};
    frame.placed = std::vector<const Element*>(o.placed.begin(), o.placed.begin() + 4);
    frame.candidates = {o.placed[3]};
    frame.added = {o.placed[4]};
    std::string file = dir / "frame.png";
    RenderOptions opt = options(500);
    render_debug_frame(file, panel(), frame, opt);
    Image img(file);
    ASSERT_TRUE(img.ok());
    EXPECT_EQ(img.width(), 500);
    EXPECT_EQ(img.height(), 400);
    EXPECT_EQ(img.at(250, 5) & 0xffffff, 0xe02020u);    // boundary row, red
    EXPECT_EQ(img.at(85, 285) & 0xffffff, 0x505050u);   // element pixels, dark grey
    EXPECT_EQ(img.at(400, 370) & 0xffffff, 0xffffffu);  // free, white
    long yellow = 0, green = 0, blue = 0, purple = 0, orange = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            int r = img.r(x, y), g = img.g(x, y), b = img.b(x, y);
            if (r > 200 && g > 170 && b < 60) ++yellow;
            if (r < 40 && g > 130 && b < 60) ++green;
            if (r < 60 && g < 110 && b > 200) ++blue;
            if (r > 110 && r < 170 && g < 60 && b > 160) ++purple;
            if (r > 230 && g > 100 && g < 150 && b < 40) ++orange;
        }
    EXPECT_GT(yellow, 50);
    EXPECT_GT(green, 50);
    EXPECT_GT(blue, 50);
    EXPECT_GT(purple, 50);
    EXPECT_GT(orange, 50);

    frame.occupancy.pop_back();
    EXPECT_THROW(render_debug_frame(dir / "bad.png", panel(), frame, opt), InputError);
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

TEST(Render, SkeletalStrokeReplacesCurveLines) {
    TempDir dir;
    sample::Ornament o;
    Region region = panel();
    RenderOptions plain = options(400);
    plain.draw_region = false;
    RenderOptions stroked = plain;
    stroked.stroke = "tapered";
    render_to_file(dir / "plain.png", o.pattern, region, o.placed, plain);
    render_to_file(dir / "stroked.png", o.pattern, region, o.placed, stroked);
    render_to_file(dir / "stroked.svg", o.pattern, region, o.placed, stroked);
    EXPECT_EQ(run("rsvg-convert -o " + (dir / "check.png") + " " + (dir / "stroked.svg")), 0);
    Image a(dir / "plain.png"), b(dir / "stroked.png");
    auto inked = [](const Image& img) {
        long n = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) n += img.alpha(x, y) > 128;
        return n;
    };
    EXPECT_GT(inked(b), inked(a) + 100);           // the stem, leaf curve and arc got wider
    auto [x, y] = page_pixel(o.dots[2].c.center);  // areas are unchanged
    EXPECT_EQ(b.alpha(x, y), 0);
}

TEST(Render, DscRewriterFixesTheHeaderLinesWhateverTheChunks) {
    const std::string in =
        "%!PS-Adobe-3.0 EPSF-3.0\n%%CreationDate: Thu Nov 26 01:00:00 2026\n"
        "%%BoundingBox: 3 3 197 197\n%%EndComments\n%%Page: 1 1\n%%BeginPageSetup\n"
        "%%PageBoundingBox: 3 3 197 197\n%%EndPageSetup\nq 0 0 1 rg\n"
        "%%BoundingBox: 1 1 1 1\n%%CreationDate: later\nQ showpage";
    const std::string want =
        "%!PS-Adobe-3.0 EPSF-3.0\n%%CreationDate: Sat Jan  1 00:00:00 2000\n"
        "%%BoundingBox: 0 0 200 200\n%%EndComments\n%%Page: 1 1\n%%BeginPageSetup\n"
        "%%PageBoundingBox: 0 0 200 200\n%%EndPageSetup\nq 0 0 1 rg\n"
        "%%BoundingBox: 1 1 1 1\n%%CreationDate: later\nQ showpage";
    for (std::size_t chunk = 1; chunk <= in.size(); ++chunk) {
        std::string out;
        detail::DscRewriter dsc({{"%%CreationDate:", "Sat Jan  1 00:00:00 2000"},
                                 {"%%BoundingBox:", "0 0 200 200"},
                                 {"%%PageBoundingBox:", "0 0 200 200"}},
                                [&](std::string_view bytes) { out.append(bytes); });
        for (std::size_t at = 0; at < in.size(); at += chunk) dsc.write(in.substr(at, chunk));
        dsc.finish();
        ASSERT_EQ(out, want) << "in chunks of " << chunk;
    }
    // A key on an unterminated last line is still rewritten.
    std::string out;
    detail::DscRewriter dsc({{"%%CreationDate:", "x"}},
                            [&](std::string_view bytes) { out.append(bytes); });
    dsc.write("%!PS\n%%Creation");
    dsc.write("Date: y");
    dsc.finish();
    EXPECT_EQ(out, "%!PS\n%%CreationDate: x");
}
