// The structured SVG (docs/rendering.md): layers per type, a group per element, shared classes,
// circles and polygons as such, Cairo's SVG for a drawing that reaches for canvas.cairo(), the
// same bytes every time, and the same picture as Cairo's PNG once rsvg rasterizes it.
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <random>
#include <set>
#include <string>

#include "fixtures/sample_elements.hpp"
#include "fixtures/temp_dir.hpp"
#include "output/svg_fallback.hpp"
#include "output/svg_writer.hpp"

using namespace acanthus;
using namespace acanthus::test;

namespace {

RenderOptions at(double width, const char* style = "drawn") {
    RenderOptions o;
    o.width = width;
    o.style = style;
    return o;
}

std::vector<pugi::xml_node> layers(const pugi::xml_document& doc) {
    std::vector<pugi::xml_node> out;
    for (pugi::xml_node g : doc.child("svg").children("g"))
        if (std::string(g.attribute("inkscape:groupmode").value()) == "layer") out.push_back(g);
    return out;
}

std::set<std::string> unique_ids(const pugi::xml_document& doc, int& count) {
    std::set<std::string> ids;
    count = 0;
    for (pugi::xpath_node n : doc.select_nodes("//*[@id]")) {
        ids.insert(n.node().attribute("id").value());
        ++count;
    }
    return ids;
}

// rsvg-convert at the PNG's size; empty when it fails.
bool rasterize(const std::string& svg, const std::string& png, int width, int height) {
    std::string command = std::string(RSVG_CONVERT) + " -w " + std::to_string(width) + " -h " +
                          std::to_string(height) + " '" + svg + "' -o '" + png + "'";
    return std::system(command.c_str()) == 0;
}

struct Difference {
    double mean = 1e9;  // mean absolute channel difference, 0..255
    double far = 1;     // fraction of pixels off by more than 96 in some channel
};

Difference compare_png(const std::string& a, const std::string& b) {
    cairo_surface_t* x = cairo_image_surface_create_from_png(a.c_str());
    cairo_surface_t* y = cairo_image_surface_create_from_png(b.c_str());
    Difference d;
    int w = cairo_image_surface_get_width(x), h = cairo_image_surface_get_height(x);
    if (cairo_surface_status(x) == CAIRO_STATUS_SUCCESS &&
        cairo_surface_status(y) == CAIRO_STATUS_SUCCESS && w > 0 &&
        w == cairo_image_surface_get_width(y) && h == cairo_image_surface_get_height(y)) {
        cairo_surface_flush(x);
        cairo_surface_flush(y);
        double sum = 0;
        long far = 0;
        for (int r = 0; r < h; ++r) {
            auto* p = cairo_image_surface_get_data(x) + r * cairo_image_surface_get_stride(x);
            auto* q = cairo_image_surface_get_data(y) + r * cairo_image_surface_get_stride(y);
            for (int c = 0; c < w; ++c) {
                int worst = 0;
                for (int k = 0; k < 4; ++k) {
                    int diff = std::abs(int(p[4 * c + k]) - int(q[4 * c + k]));
                    sum += diff;
                    worst = std::max(worst, diff);
                }
                if (worst > 96) ++far;
            }
        }
        d.mean = sum / (4.0 * w * h);
        d.far = double(far) / (double(w) * h);
    }
    cairo_surface_destroy(x);
    cairo_surface_destroy(y);
    return d;
}

int png_size(const std::string& png, int& height) {
    cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
    int width = cairo_image_surface_get_width(s);
    height = cairo_image_surface_get_height(s);
    cairo_surface_destroy(s);
    return width;
}

// A %draw that goes around the Canvas: a gradient-filled square through raw Cairo.
void draw_gradient(Canvas& canvas, const Element& e) {
    const auto& c = static_cast<const CircleProxy&>(e.proxy(0));
    cairo_t* cr = canvas.cairo();
    cairo_pattern_t* gradient =
        cairo_pattern_create_linear(c.center.x - c.radius, 0, c.center.x + c.radius, 0);
    cairo_pattern_add_color_stop_rgb(gradient, 0, 1, 0, 0);
    cairo_pattern_add_color_stop_rgb(gradient, 1, 0, 0, 1);
    cairo_rectangle(cr, c.center.x - c.radius, c.center.y - c.radius, 2 * c.radius, 2 * c.radius);
    cairo_set_source(cr, gradient);
    cairo_fill(cr);
    cairo_pattern_destroy(gradient);
}
const ElementType gradient_dot_type{"gdot", {ProxyKind::circle}, nullptr, &draw_gradient, 40};

}  // namespace

TEST(SvgStructure, NumbersToThePrecisionOfThePageWithoutTrailingZeros) {
    EXPECT_EQ(detail::svg_digits(800, 600), 2);
    EXPECT_EQ(detail::svg_digits(300, 1999), 2);
    EXPECT_EQ(detail::svg_digits(2000, 300), 1);

    EXPECT_EQ(detail::svg_digits(4096, 4096), 1);
    EXPECT_EQ(detail::svg_digits(32767, 10), 0);
    EXPECT_EQ(detail::svg_digits(50, 40), 3);
    EXPECT_EQ(detail::svg_digits(1, 1), 3);
    EXPECT_EQ(detail::svg_number(3432.13, 1), "3432.1");
    EXPECT_EQ(detail::svg_number(1.96, 1), "2");
    EXPECT_EQ(detail::svg_number(12.0), "12");
    EXPECT_EQ(detail::svg_number(12.345), "12.35");  // to_chars rounds the binary value
    EXPECT_EQ(detail::svg_number(0.5), "0.5");
    EXPECT_EQ(detail::svg_number(-0.001), "0");
    EXPECT_EQ(detail::svg_number(-3.10), "-3.1");
    EXPECT_EQ(detail::xml_escape("a<b&\"c'>"), "a&lt;b&amp;&quot;c&apos;&gt;");
}

// svg_number's quick path (an integer scaled in a double) against std::to_chars' fixed format,
// which it must match byte for byte: page coordinates, values next to a tie at every precision
// (1.005, 0.125: the binary value decides), negative ones, huge ones.
TEST(SvgStructure, NumbersAsToCharsRoundsThem) {
    const auto reference = [](double value, int digits) {
        char buffer[64];
        auto [end, ec] =
            std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, digits);
        if (ec != std::errc()) return std::string("0");
        std::string text(buffer, end);
        if (text.find('.') != std::string::npos) {
            text.erase(text.find_last_not_of('0') + 1);
            if (text.back() == '.') text.pop_back();
        }
        return text == "-0" ? std::string("0") : text;
    };
    std::mt19937_64 random(29);
    std::uniform_real_distribution<double> page(-50, 5000);
    std::vector<double> values{0.0,
                               -0.0,
                               1.005,
                               0.125,
                               -0.125,
                               2.5,
                               -2.5,
                               0.05,
                               1e-9,
                               -1e-9,
                               4503599627370495.5,
                               1e15,
                               1e17,
                               -3e18,
                               1e300,
                               5e-324,
                               0.0049999999999999,
                               999.9999999,
                               -999.99995};
    for (int i = 0; i < 200000; ++i) values.push_back(page(random));
    for (int i = 0; i < 20000; ++i) {  // ties at 1 to 4 decimals, and their neighbours
        const double tie = (std::floor(page(random) * 1000) + 0.5) / 1000;
        values.insert(values.end(), {tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e9), -tie,
                                     (std::floor(tie * 10) + 0.5) / 10});
    }
    for (double v : values)
        for (int digits = 0; digits <= 9; ++digits)
            ASSERT_EQ(detail::svg_number(v, digits), reference(v, digits)) << v << " " << digits;
}

TEST(SvgStructure, FallbackIdsArePrefixed) {
    std::string svg =
        "<?xml?>\n<svg a=\"1\">\n<g id=\"surface1\" clip-path=\"url(#clip1)\">"
        "<use xlink:href=\"#glyph0\" data-id=\"3\"/></g>\n</svg>\n";
    EXPECT_EQ(detail::svg_inner_fragment(svg, "p-"),
              "\n<g id=\"p-surface1\" clip-path=\"url(#p-clip1)\">"
              "<use xlink:href=\"#p-glyph0\" data-id=\"3\"/></g>\n");
}

TEST(SvgStructure, LayersGroupsClassesAndShapes) {
    TempDir dir;
    sample::Ornament o;
    Region region = Region::from_spec("rect:100,80");
    for (const char* style : {"drawn", "filled", "order", "overlay"}) {
        SCOPED_TRACE(style);
        std::string path = dir / (std::string(style) + ".svg");
        render_to_file(path, o.pattern, region, o.placed, at(400, style));
        pugi::xml_document doc;
        ASSERT_TRUE(doc.load_file(path.c_str()));
        std::vector<std::string> labels;
        for (pugi::xml_node layer : layers(doc))
            labels.push_back(layer.attribute("inkscape:label").value());
        EXPECT_EQ(labels, (std::vector<std::string>{"panel outline", "seed", "dot", "stem", "leaf",
                                                    "petal"}));
        std::size_t groups = 0;
        for (pugi::xml_node layer : layers(doc)) {
            std::string type = layer.attribute("inkscape:label").value();
            if (type == "panel outline") {
                EXPECT_TRUE(layer.child("path"));
                continue;
            }
            EXPECT_EQ(std::string(layer.attribute("id").value()), "layer-" + type);
            for (pugi::xml_node g : layer.children("g")) {
                ++groups;
                // id TYPE-ID; no data-type, data-id or data-depth (docs/rendering.md, "Groups").
                std::string id = g.attribute("id").value();
                ASSERT_EQ(id.rfind(type + "-", 0), 0u) << id;
                EXPECT_FALSE(g.attribute("data-type") || g.attribute("data-id") ||
                             g.attribute("data-depth"));
                const Element& e = *o.placed.at(std::stoul(id.substr(type.size() + 1)));
                EXPECT_EQ(&e.type(),
                          o.pattern.types.at(
                              std::find_if(o.pattern.types.begin(), o.pattern.types.end(),
                                           [&](const ElementType* t) { return t->name == type; }) -
                              o.pattern.types.begin()));
                EXPECT_EQ(std::string(g.attribute("data-parent").value()),
                          e.parent ? std::to_string(e.parent->id) : "none");
            }
        }
        EXPECT_EQ(groups, o.placed.size());
        int count = 0;
        std::size_t ids = unique_ids(doc, count).size();
        EXPECT_EQ(ids, std::size_t(count));
        EXPECT_EQ(doc.select_nodes("//g[@id='layer-dot']/g/circle").size(), 5u);
        EXPECT_EQ(doc.select_nodes("//g[@id='layer-petal']/g/polygon").size(), 1u);
        EXPECT_EQ(doc.select_nodes("//g[@id='layer-seed']/g/*").size(), 0u);  // seeds: not drawn
        pugi::xml_node css = doc.child("svg").child("style");
        ASSERT_TRUE(css);
        for (pugi::xpath_node n : doc.select_nodes("//*[@class]"))
            EXPECT_NE(std::string(css.text().get())
                          .find("." + std::string(n.node().attribute("class").value()) + "{"),
                      std::string::npos);
    }
}

TEST(SvgStructure, SameBytesEveryTime) {
    TempDir dir;
    sample::Ornament o;
    Region region = Region::from_spec("rect:100,80");
    o.dots[2].kind = &gradient_dot_type;
    render_to_file(dir / "a.svg", o.pattern, region, o.placed, at(300));
    render_to_file(dir / "b.svg", o.pattern, region, o.placed, at(300));
    EXPECT_EQ(slurp(dir / "a.svg"), slurp(dir / "b.svg"));
}

TEST(SvgStructure, RawCairoDrawingFallsBackToCairoForThatElement) {
    TempDir dir;
    sample::Ornament o;
    Region region = Region::from_spec("rect:100,80");
    o.dots[2].kind = &gradient_dot_type;
    o.dots[3].kind = &gradient_dot_type;
    render_to_file(dir / "g.svg", o.pattern, region, o.placed, at(400));
    render_to_file(dir / "g.png", o.pattern, region, o.placed, at(400));
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file((dir / "g.svg").c_str()));
    EXPECT_TRUE(doc.select_node("//g[@id='gdot-3']//*[starts-with(@id,'gdot-3-')]"));
    EXPECT_TRUE(doc.select_node("//g[@id='gdot-3']//*[local-name()='linearGradient']"));
    EXPECT_EQ(doc.select_nodes("//g[@id='layer-dot']/g/circle").size(), 3u);
    int count = 0;
    std::size_t ids = unique_ids(doc, count).size();
    EXPECT_EQ(ids, std::size_t(count));
    int height = 0, width = png_size(dir / "g.png", height);
    ASSERT_TRUE(rasterize(dir / "g.svg", dir / "r.png", width, height));
    Difference d = compare_png(dir / "g.png", dir / "r.png");
    EXPECT_LT(d.mean, 1.5);
    EXPECT_LT(d.far, 0.005);
}

// The check: flowers on the heart panel, the SVG against the PNG and the --json tree.
TEST(SvgStructure, FlowersOnTheHeartAsThePngShowsThem) {
    TempDir dir;
    std::string panel = std::string(ACANTHUS_SOURCE_DIR) + "/examples/panels/heart.svg";
    std::string run = std::string(FLOWERS_PROGRAM) + " --region '" + panel +
                      "' --rng-seed 1 --quiet --width 800 ";
    ASSERT_EQ(
        std::system((run + "--json '" + dir / "t.json" + "' -o '" + dir / "f.svg" + "'").c_str()),
        0);
    ASSERT_EQ(std::system((run + "-o '" + dir / "f.png" + "'").c_str()), 0);

    nlohmann::json tree = nlohmann::json::parse(slurp(dir / "t.json"));
    std::map<std::string, std::size_t> per_type;
    for (const auto& e : tree["elements"]) ++per_type[e["type"].get<std::string>()];
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_file((dir / "f.svg").c_str()));
    std::map<std::string, std::size_t> groups;
    for (pugi::xml_node layer : layers(doc)) {
        std::string label = layer.attribute("inkscape:label").value();
        EXPECT_EQ(groups.count(label), 0u) << "two layers " << label;
        groups[label] = 0;
        for (pugi::xml_node g : layer.children("g")) {
            ++groups[label];
            EXPECT_EQ(std::string(g.attribute("id").value()).rfind(label + "-", 0), 0u);
        }
    }
    EXPECT_EQ(groups.count("panel outline"), 1u);
    groups.erase("panel outline");
    EXPECT_EQ(groups, per_type);
    int count = 0;
    std::size_t ids = unique_ids(doc, count).size();
    EXPECT_EQ(ids, std::size_t(count));
    EXPECT_GT(doc.select_nodes("//g[@id='layer-flower']/g/circle").size(), 5 * per_type["flower"]);

    int height = 0, width = png_size(dir / "f.png", height);
    ASSERT_TRUE(rasterize(dir / "f.svg", dir / "r.png", width, height));
    Difference d = compare_png(dir / "f.png", dir / "r.png");
    std::printf("flowers: mean difference %.3f, pixels far off %.4f%%\n", d.mean, 100 * d.far);
    EXPECT_LT(d.mean, 1.5);
    EXPECT_LT(d.far, 0.005);
}
