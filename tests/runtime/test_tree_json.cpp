// The --json element tree, the --metrics object and the coverage measure.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <cstdlib>
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
