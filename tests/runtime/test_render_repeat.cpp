// The output as a repeat of its tile (docs/symmetry.md): --repeat NxM in Cairo's formats and in
// the structured SVG (copies by <use>), and --svg-pattern (a <pattern> of the tile); rsvg must
// draw the SVGs as Cairo draws the PNG, and the PNG must repeat with the tile's period.
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <cstdlib>
#include <pugixml.hpp>
#include <set>
#include <string>

#include "fixtures/sample_elements.hpp"
#include "fixtures/temp_dir.hpp"
#include "output/repeat.hpp"

using namespace acanthus;
using namespace acanthus::detail;
using namespace acanthus::test;

namespace {

RenderOptions repeated(double width, int n, int m, bool pattern = false) {
    RenderOptions o;
    o.width = width;
    o.repeat_x = n;
    o.repeat_y = m;
    o.svg_pattern = pattern;
    o.background = Color{1, 1, 1, 1};
    return o;
}

struct Image {
    cairo_surface_t* s = nullptr;
    explicit Image(const std::string& png) : s(cairo_image_surface_create_from_png(png.c_str())) {
        cairo_surface_flush(s);
    }
    ~Image() { cairo_surface_destroy(s); }
    bool ok() const { return cairo_surface_status(s) == CAIRO_STATUS_SUCCESS; }
    int width() const { return cairo_image_surface_get_width(s); }
    int height() const { return cairo_image_surface_get_height(s); }
    // Darkness 0..255 of pixel (x, y), over white.
    int ink(int x, int y) const {
        const unsigned char* p =
            cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s) + 4 * x;
        const int alpha = p[3];
        const int grey = (p[0] + p[1] + p[2]) / 3;  // premultiplied
        return 255 - (grey + 255 - alpha);
    }
};

bool rasterize(const std::string& svg, const std::string& png, int width, int height) {
    const std::string command = std::string(RSVG_CONVERT) + " -b white -w " +
                                std::to_string(width) + " -h " + std::to_string(height) + " '" +
                                svg + "' -o '" + png + "'";
    return std::system(command.c_str()) == 0;
}

// Mean absolute ink difference and the fraction of pixels off by more than 96.
std::pair<double, double> difference(const Image& x, const Image& y) {
    if (!x.ok() || !y.ok() || x.width() != y.width() || x.height() != y.height()) return {1e9, 1};
    double sum = 0;
    long far = 0;
    for (int r = 0; r < x.height(); ++r)
        for (int c = 0; c < x.width(); ++c) {
            const int d = std::abs(x.ink(c, r) - y.ink(c, r));
            sum += d;
            if (d > 96) ++far;
        }
    const double n = double(x.width()) * x.height();
    return {sum / n, far / n};
}

long total_ink(const Image& x) {
    long sum = 0;
    for (int r = 0; r < x.height(); ++r)
        for (int c = 0; c < x.width(); ++c) sum += x.ink(c, r);
    return sum;
}

}  // namespace

TEST(Repeat, ParsesNxM) {
    EXPECT_EQ(parse_repeat("3x3"), std::make_pair(3, 3));
    EXPECT_EQ(parse_repeat("1X12"), std::make_pair(1, 12));
    EXPECT_EQ(parse_repeat("100x1"), std::make_pair(100, 1));
    for (const char* bad : {"", "3", "x3", "3x", "0x3", "3x0", "-1x2", "3x3x3", "2.5x2", "101x1",
                            "3 x 3", "ax3", "99999999999x1"})
        EXPECT_THROW(parse_repeat(bad), UsageError) << bad;
}

TEST(Repeat, LayoutOfAnObliqueTile) {
    RenderOptions o = repeated(400, 2, 3);
    o.tile = RepeatTile{{10, 20}, {100, 0}, {40, 80}};
    const RepeatLayout layout = repeat_layout(Rect{0, 0, 1, 1}, o);
    const auto c = layout.corners();
    EXPECT_DOUBLE_EQ(c[2].x, 10 + 200 + 120);
    EXPECT_DOUBLE_EQ(c[2].y, 20 + 240);
    const Rect b = layout.bounds();
    EXPECT_DOUBLE_EQ(b.x0, 10);
    EXPECT_DOUBLE_EQ(b.x1, 330);
    EXPECT_DOUBLE_EQ(b.y1, 260);
    EXPECT_EQ(layout.offsets().size(), 6u);
    EXPECT_DOUBLE_EQ(layout.offsets()[0].x, 0);  // the tile itself first
    EXPECT_DOUBLE_EQ(layout.offsets()[5].x, 100 + 80);
    EXPECT_DOUBLE_EQ(layout.offsets()[5].y, 160);
    // Without a tile, the region's bounding box.
    const RepeatLayout box = repeat_layout(Rect{5, 6, 105, 86}, repeated(400, 3, 3));
    EXPECT_DOUBLE_EQ(box.tile.a.x, 100);
    EXPECT_DOUBLE_EQ(box.tile.b.y, 80);
    EXPECT_DOUBLE_EQ(box.tile.origin.y, 6);
    EXPECT_FALSE(repeats(RenderOptions{}));
    EXPECT_TRUE(repeats(repeated(400, 1, 1, true)));
}

TEST(Repeat, ThePngRepeatsWithTheTilesPeriod) {
    TempDir dir;
    sample::Ornament o;
    const Region region = Region::from_spec("rect:100,80");
    const Rect r = region.bounds();
    // 3 x 2 tiles of 100 x 80 and a 2% margin of 300: a page 624 wide puts 2 px per unit.
    render_to_file(dir / "one.png", o.pattern, region, o.placed, repeated(624, 1, 1));
    render_to_file(dir / "rep.png", o.pattern, region, o.placed, repeated(624, 3, 2));
    const Image one(dir / "one.png"), rep(dir / "rep.png");
    ASSERT_TRUE(rep.ok());
    ASSERT_EQ(rep.width(), 624);
    ASSERT_EQ(rep.height(), 344);
    const int x0 = 12, y0 = 12, tw = 200, th = 160;  // the area's corner and the tile in pixels
    EXPECT_NEAR(r.width() * 2, tw, 1e-9);
    long compared = 0, off = 0, inked = 0;
    for (int y = y0; y < y0 + th; ++y)
        for (int x = x0; x < x0 + tw; ++x)
            for (auto [i, j] : {std::pair{1, 0}, {2, 0}, {0, 1}, {2, 1}}) {
                ++compared;
                inked += rep.ink(x, y) > 64;
                off += std::abs(rep.ink(x, y) - rep.ink(x + i * tw, y + j * th)) > 8;
            }
    EXPECT_GT(inked, compared / 200);  // something is drawn
    EXPECT_LT(off, compared / 1000) << off << " of " << compared;
    // Outside the area, nothing.
    for (int y = 0; y < rep.height(); ++y)
        for (int x : {0, 5, rep.width() - 5}) EXPECT_EQ(rep.ink(x, y), 0) << x << "," << y;
    // The single tile is not the repeat.
    EXPECT_NE(one.width() * 0 + one.height(), rep.height());
    EXPECT_GT(total_ink(rep), total_ink(one));
}

TEST(Repeat, TheSvgRepeatAndTheSvgPatternAreDrawnByRsvgAsCairoDrawsThePng) {
    TempDir dir;
    sample::Ornament o;
    const Region rect = Region::from_spec("rect:100,80");
    // A small rectangle and a parallelogram that the sample's elements cross: clipped tiles.
    const Region small = Region::from_spec("rect:60,50");
    const Region oblique = Region::from_svg_string(
        R"(<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0 L100 0 L140 80 L40 80 Z"/></svg>)",
        "oblique");
    const Rect ob = oblique.bounds();
    const RepeatTile oblique_tile{{ob.x0, ob.y0}, {100, 0}, {40, 80}};
    struct Case {
        const char* name;
        const Region* region;
        int n, m;
        bool pattern, clip;
        std::optional<RepeatTile> tile;
    };
    for (const Case& c :
         {Case{"use", &rect, 3, 2, false, false, {}}, Case{"pattern", &rect, 3, 2, true, false, {}},
          Case{"pattern-one", &rect, 1, 1, true, false, {}},
          Case{"clipped-one", &small, 1, 1, false, true, {}},
          Case{"clipped-use", &small, 3, 2, false, true, {}},
          Case{"clipped-pattern", &small, 2, 3, true, true, {}},
          Case{"oblique-pattern", &oblique, 2, 2, true, true, oblique_tile},
          Case{"oblique-use", &oblique, 2, 2, false, true, oblique_tile}}) {
        SCOPED_TRACE(c.name);
        RenderOptions options = repeated(600, c.n, c.m, c.pattern);
        options.tile = c.tile;
        options.clip_to_region = c.clip;
        const std::string svg = dir / (std::string(c.name) + ".svg");
        const std::string png = dir / (std::string(c.name) + ".png");
        render_to_file(svg, o.pattern, *c.region, o.placed, options);
        options.svg_pattern = false;
        render_to_file(png, o.pattern, *c.region, o.placed, options);
        const Image cairo(png);
        ASSERT_TRUE(cairo.ok());
        ASSERT_TRUE(rasterize(svg, dir / "r.png", cairo.width(), cairo.height()));
        const Image rsvg(dir / "r.png");
        const auto [mean, far] = difference(cairo, rsvg);
        std::printf("%s: mean difference %.3f, far %.4f%%\n", c.name, mean, 100 * far);
        EXPECT_LT(mean, 1.5);
        EXPECT_LT(far, 0.005);

        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file(svg.c_str()));
        std::set<std::string> ids;
        int count = 0;
        for (pugi::xpath_node n : doc.select_nodes("//*[@id]")) {
            ids.insert(n.node().attribute("id").value());
            ++count;
        }
        EXPECT_EQ(ids.size(), std::size_t(count));  // ids stay unique
        const bool repeat = c.pattern || c.n * c.m > 1;
        EXPECT_EQ(doc.select_nodes("//*[@id='repeat-tile']").size(), repeat ? 1u : 0u);
        EXPECT_EQ(doc.select_nodes("//clipPath[@id='tile-clip']").size(), c.clip ? 1u : 0u);
        const std::size_t uses = doc.select_nodes("//use").size();
        if (c.pattern) {
            EXPECT_EQ(doc.select_nodes("//defs/pattern[@id='repeat-pattern']").size(), 1u);
            EXPECT_EQ(uses, 0u);
            EXPECT_EQ(doc.select_nodes("//path[@fill='url(#repeat-pattern)']").size(), 1u);
        } else {
            EXPECT_EQ(uses, std::size_t(c.n * c.m - 1));
        }
        EXPECT_EQ(doc.select_nodes("//g[@id='layer-panel-outline']").size(), repeat ? 0u : 1u);
    }
}

TEST(Repeat, ClippedToTheRegionNothingIsDrawnOutsideIt) {
    TempDir dir;
    sample::Ornament o;
    const Region small = Region::from_spec("rect:60,50");
    RenderOptions options = repeated(400, 1, 1);
    options.draw_region = false;
    render_to_file(dir / "free.png", o.pattern, small, o.placed, options);
    options.clip_to_region = true;
    render_to_file(dir / "clipped.png", o.pattern, small, o.placed, options);
    const Image free(dir / "free.png"), clipped(dir / "clipped.png");
    ASSERT_TRUE(clipped.ok());
    // The page's margin (2% of the side, 8 px) lies outside the region.
    long outside_free = 0, outside_clipped = 0;
    for (int y = 0; y < clipped.height(); ++y)
        for (int x = 0; x < clipped.width(); ++x)
            if (x < 7 || y < 7 || x >= clipped.width() - 7 || y >= clipped.height() - 7) {
                outside_free += free.ink(x, y);
                outside_clipped += clipped.ink(x, y);
            }
    EXPECT_GT(outside_free, 0);  // the sample's elements do cross this region's edge
    EXPECT_EQ(outside_clipped, 0);
}

TEST(Repeat, SvgPatternNeedsAnSvgOutput) {
    TempDir dir;
    sample::Ornament o;
    const Region region = Region::from_spec("rect:100,80");
    EXPECT_THROW(
        render_to_file(dir / "x.png", o.pattern, region, o.placed, repeated(300, 2, 2, true)),
        UsageError);
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}
