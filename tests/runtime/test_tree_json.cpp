// The --json element tree, the --metrics object and the coverage measure.
#include <cairo.h>
#include <gtest/gtest.h>

#include <acanthus/canvas.hpp>
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fixtures/sample_elements.hpp"
#include "output/coverage.hpp"
#include "program/metrics_json.hpp"
#include "program/tree_json.hpp"

using namespace acanthus;
using namespace acanthus::detail;
using json = nlohmann::ordered_json;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> keys(const nlohmann::ordered_json& object) {
    std::vector<std::string> out;
    for (const auto& [key, value] : object.items()) out.push_back(key);
    return out;
}

std::vector<const Element*> just(const Element& e) { return {&e}; }

}  // namespace

TEST(TreeJson, HasTheDocumentedShape) {
    sample::Ornament o;
    Region region = Region::from_spec("rect:100,80");
    auto tree = json::parse(tree_json(region, o.placed));
    EXPECT_EQ(keys(tree), (std::vector<std::string>{"region", "elements"}));
    EXPECT_EQ(tree["region"]["bounds"], json::parse("[0, 0, 100, 80]"));
    EXPECT_DOUBLE_EQ(tree["region"]["area"].get<double>(), 8000);

    const auto& elements = tree["elements"];
    ASSERT_EQ(elements.size(), o.placed.size());
    for (std::size_t i = 0; i < elements.size(); ++i) {
        EXPECT_EQ(keys(elements[i]), (std::vector<std::string>{"id", "type", "parent", "depth",
                                                               "sterile", "fields", "proxies"}));
        EXPECT_EQ(elements[i]["id"], static_cast<int>(i));
    }
    const auto& seed = elements[0];
    EXPECT_EQ(seed["type"], "seed");
    EXPECT_TRUE(seed["parent"].is_null());
    EXPECT_EQ(seed["depth"], 0);
    EXPECT_EQ(seed["sterile"], true);
    EXPECT_TRUE(seed["fields"].is_object() && seed["fields"].empty());
    EXPECT_EQ(seed["proxies"], json::parse(R"([{"kind": "point", "point": [20, 60]}])"));

    const auto& dot = elements[2];  // dots[1]: child of dots[0]
    EXPECT_EQ(dot["type"], "dot");
    EXPECT_EQ(dot["parent"], 1);
    EXPECT_EQ(dot["depth"], 2);
    EXPECT_EQ(dot["sterile"], false);
    EXPECT_EQ(keys(dot["fields"]),
              (std::vector<std::string>{"order", "weight", "marked", "label"}));
    EXPECT_EQ(dot["fields"], json::parse(R"({"order": 1, "weight": 0.25, "marked": true,
                                              "label": "dot1"})"));
    EXPECT_EQ(dot["proxies"],
              json::parse(R"([{"kind": "circle", "center": [34, 52], "radius": 6}])"));

    EXPECT_EQ(elements[6]["proxies"],
              json::parse(R"([{"kind": "linesegment", "p0": [10, 10], "p1": [40, 25]}])"));
    const auto& leaf = elements[7]["proxies"];
    EXPECT_EQ(leaf[0], json::parse(R"({"kind": "bezier",
                                       "c": [[50, 10], [60, 0], [75, 25], [90, 12]]})"));
    EXPECT_EQ(leaf[1]["kind"], "arc");
    EXPECT_EQ(leaf[1]["center"], json::parse("[80, 65]"));
    EXPECT_EQ(leaf[1]["radius"], 8);
    EXPECT_EQ(leaf[1]["start"], 0);
    EXPECT_DOUBLE_EQ(leaf[1]["end"].get<double>(), M_PI);
    EXPECT_EQ(elements[8]["proxies"],
              json::parse(R"([{"kind": "polygon", "points": [[5, 70], [15, 70], [10, 76]]}])"));
    EXPECT_EQ(elements[8]["parent"], 3);
}

TEST(TreeJson, UnsetCoordinatesBecomeNull) {
    sample::Dot d;
    d.id = 0;
    auto tree = json::parse(tree_json(Region::from_spec("rect:10,10"), just(d)));
    EXPECT_TRUE(tree["elements"][0]["proxies"][0]["radius"].is_null());
    EXPECT_TRUE(tree["elements"][0]["proxies"][0]["center"][0].is_null());
}

TEST(TreeJson, WritesAtomicallyAndRefusesBadPaths) {
    std::string dir = (fs::temp_directory_path() / "acanthus-json-XXXXXX").string();
    ASSERT_NE(mkdtemp(dir.data()), nullptr);
    sample::Ornament o;
    Region region = Region::from_spec("rect:100,80");
    std::string file = dir + "/tree.json";
    write_tree_json(file, region, o.placed);
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), tree_json(region, o.placed));
    EXPECT_THROW(write_tree_json(dir + "/no/such/dir/tree.json", region, o.placed), InputError);
    EXPECT_THROW(write_tree_json(dir, region, o.placed), InputError);  // a directory
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++count;
    EXPECT_EQ(count, 1u);
    fs::remove_all(dir);
}

TEST(MetricsJson, HasEveryKey) {
    sample::Ornament o;
    Pattern pattern = o.pattern;
    pattern.rules.resize(2);
    pattern.rules[0].name = "seed --> dot";
    pattern.rules[0].line = 20;
    pattern.rules[1].name = "dot --> dot";
    pattern.rules[1].line = 31;
    GrowthStats stats;
    stats.iterations = 57;
    stats.rules = {{1, 0}, {40, 16}};
    stats.exclude_points = 3;
    stats.seconds = 0.5;
    auto m = json::parse(metrics_json(pattern, stats, 42, 0.625, 1.25, 0.125, false));
    EXPECT_EQ(keys(m),
              (std::vector<std::string>{"elements", "iterations", "rules", "exclude_points",
                                        "coverage", "seconds", "engine"}));
    EXPECT_EQ(m["elements"], 42);
    EXPECT_EQ(m["iterations"], 57);
    EXPECT_EQ(m["rules"], json::parse(R"([
        {"rule": "seed --> dot", "line": 20, "successes": 1, "failures": 0},
        {"rule": "dot --> dot", "line": 31, "successes": 40, "failures": 16}])"));
    EXPECT_EQ(m["exclude_points"], 3);
    EXPECT_EQ(m["coverage"], 0.625);
    EXPECT_EQ(m["seconds"], json::parse(R"({"total": 1.25, "growth": 0.5, "render": 0.125})"));
    EXPECT_EQ(m["engine"], "incremental");
    auto r = json::parse(metrics_json(pattern, GrowthStats{}, 0, 0, 0, 0, true));
    EXPECT_EQ(r["engine"], "reference");
    EXPECT_EQ(r["rules"][1]["successes"], 0);
    // With the region: its bounds and area, as the element tree gives them.
    const Region region = Region::from_spec("rect:100,80");
    auto g = json::parse(metrics_json(pattern, stats, 42, 0.625, 1.25, 0.125, false, &region));
    EXPECT_EQ(keys(g),
              (std::vector<std::string>{"elements", "iterations", "rules", "exclude_points",
                                        "coverage", "seconds", "engine", "region"}));
    EXPECT_EQ(g["region"], json::parse(R"({"bounds": [0, 0, 100, 80], "area": 8000})"));
}

TEST(Coverage, MeasuresFilledAreasAndStrokedCurves) {
    Region region = Region::from_spec("rect:100,80");
    sample::Dot disc;
    disc.c.set({50, 40}, 10);
    EXPECT_NEAR(coverage(region, just(disc), 1.0), M_PI * 100 / 8000, 0.01 * M_PI * 100 / 8000);

    sample::Dot twin;  // the same disc twice still covers its area once
    twin.c.set({50, 40}, 10);
    std::vector<const Element*> both{&disc, &twin};
    EXPECT_NEAR(coverage(region, both, 1.0), M_PI * 100 / 8000, 0.01 * M_PI * 100 / 8000);

    sample::Dot half;  // centred on the left edge: half of it lies outside the region
    half.c.set({0, 40}, 10);
    EXPECT_NEAR(coverage(region, just(half), 1.0), M_PI * 50 / 8000, 0.02 * M_PI * 50 / 8000);

    sample::Petal all;
    all.poly.set({{-10, -10}, {110, -10}, {110, 90}, {-10, 90}});
    EXPECT_NEAR(coverage(region, just(all), 1.0), 1.0, 1e-9);

    sample::Stem stem;  // 50 long, 2 wide, round caps
    stem.s.set({20, 40}, {70, 40});
    double stem_area = 50 * 2 + M_PI;
    EXPECT_NEAR(coverage(region, just(stem), 2.0), stem_area / 8000, 0.03 * stem_area / 8000);
    EXPECT_EQ(coverage(region, just(stem), 0.0), 0.0);

    sample::Seed seed;
    seed.p.set({50, 40});
    EXPECT_EQ(coverage(region, just(seed), 2.0), 0.0);
    EXPECT_EQ(coverage(region, {}, 2.0), 0.0);
}

// Every shape drawn through the region's clip, as coverage() measured before it left the clip
// out for shapes whose pixels the region covers wholly.
double coverage_all_clipped(const Region& region, const std::vector<const Element*>& elements,
                            double stroke_width) {
    const Rect b = region.bounds();
    const double scale = 1024 / std::max(b.width(), b.height());
    const int w = static_cast<int>(std::ceil(b.width() * scale));
    const int h = static_cast<int>(std::ceil(b.height() * scale));
    auto measure = [&](bool with_elements) {
        cairo_surface_t* mask = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
        cairo_t* cr = cairo_create(mask);
        cairo_scale(cr, scale, scale);
        cairo_translate(cr, -b.x0, -b.y0);
        for (const auto& ring : region.rings(0.25 / scale)) {
            cairo_move_to(cr, ring[0].x, ring[0].y);
            for (std::size_t i = 1; i < ring.size(); ++i) cairo_line_to(cr, ring[i].x, ring[i].y);
            cairo_close_path(cr);
        }
        if (!with_elements) {
            cairo_fill(cr);
        } else {
            cairo_clip(cr);
            cairo_set_line_width(cr, stroke_width);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
            Canvas canvas(cr);
            for (const Element* e : elements)
                for (std::size_t k = 0; k < e->proxy_count(); ++k) {
                    const Proxy& p = e->proxy(k);
                    if (p.kind() == ProxyKind::point) continue;
                    if (is_area(p.kind()))
                        canvas.fill(p);
                    else
                        canvas.stroke(p);
                }
        }
        cairo_surface_flush(mask);
        const unsigned char* data = cairo_image_surface_get_data(mask);
        double sum = 0;
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i) sum += data[j * cairo_image_surface_get_stride(mask) + i];
        cairo_destroy(cr);
        cairo_surface_destroy(mask);
        return sum;
    };
    return measure(true) / measure(false);
}

TEST(Coverage, ShapesWhollyInsideMeasureAsClippedOnes) {
    // A disc (its edge no box): stems, curves and discs inside it, across its edge and outside.
    const Region region = Region::from_spec("circle:50");
    const Rect b = region.bounds();
    const Point c = b.center();
    std::deque<sample::Stem> stems;
    std::deque<sample::Leaf> leaves;
    std::deque<sample::Dot> dots;
    std::vector<const Element*> all;
    for (int k = 0; k < 24; ++k) {
        const double a = k * 2 * M_PI / 24, r0 = 5 + 2.2 * k, r1 = r0 + 7;
        const Point p0{c.x + r0 * std::cos(a), c.y + r0 * std::sin(a)};
        const Point p1{c.x + r1 * std::cos(a + 0.3), c.y + r1 * std::sin(a + 0.3)};
        stems.emplace_back().s.set(p0, p1);
        auto& leaf = leaves.emplace_back();
        leaf.b.set(p0, {p0.x + 3, p0.y - 4}, {p1.x - 2, p1.y + 5}, p1);
        dots.emplace_back().c.set(p1, 1.5);
        all.insert(all.end(), {&stems.back(), &leaves.back(), &dots.back()});
    }
    const double measured = coverage(region, all, 1.5);
    const double reference = coverage_all_clipped(region, all, 1.5);
    EXPECT_GT(measured, 0.05);
    // The same up to a few edge pixels that Cairo rounds otherwise without a clip (2e-6 of
    // the figure here; a shape drawn outside the clip would add its whole outside part).
    EXPECT_NEAR(measured, reference, 1e-5 * reference);
    // A stem across the edge counts only inside (half of it here), as clipped.
    sample::Stem across;
    across.s.set({c.x + 40, c.y}, {c.x + 60, c.y});
    sample::Stem inside;
    inside.s.set({c.x - 10, c.y}, {c.x + 10, c.y});
    EXPECT_NEAR(coverage(region, just(across), 1.5), 0.5 * coverage(region, just(inside), 1.5),
                0.05 * coverage(region, just(inside), 1.5));
}

TEST(Coverage, RespectsHoles) {
    // A 100x100 square with a 50x50 hole; a polygon over everything covers the 7500 of area.
    Region ring = Region::from_svg_string(
        R"(<svg xmlns="http://www.w3.org/2000/svg"><path fill-rule="evenodd"
           d="M0 0 H100 V100 H0 Z M25 25 H75 V75 H25 Z"/></svg>)",
        "ring.svg");
    sample::Petal left;  // covers x in [0, 50]: 5000 of area minus half the hole (1250)
    left.poly.set({{-5, -5}, {50, -5}, {50, 105}, {-5, 105}});
    EXPECT_NEAR(coverage(ring, just(left), 1.0), 3750.0 / 7500.0, 0.005);
}
