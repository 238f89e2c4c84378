// SVG references and guides (issue 10): elements at the centres of their bounding boxes after
// transforms, data-* attributes, outlines, <use>, and every bad input named by file and element.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace acanthus;
using namespace acanthus::growth;

namespace {

const std::string kHead = R"x(<svg xmlns="http://www.w3.org/2000/svg">)x";

// A 3 x 3 grid of squares, spacing 10, the middle one a group turned by a transform.
std::string grid_svg() {
    std::string s = kHead;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            if (r == 1 && c == 1) continue;
            s += "<rect id=\"e" + std::to_string(r * 3 + c) + "\" data-symbol=\"" +
                 (c % 2 ? "b" : "a") + "\" x=\"" + std::to_string(c * 10 - 1) + "\" y=\"" +
                 std::to_string(r * 10 - 1) + "\" width=\"2\" height=\"2\" fill=\"#f00\"/>";
        }
    s += R"x(<g id="mid" data-symbol="b" data-label="m" data-angle="90" data-size="3"
              transform="translate(10,10)"><circle r="1" fill="#00f"/><circle cx="0.5" r="0.5"/></g>)x";
    s += R"x(<text>ignored</text><rect id="frame" width="40" height="40" fill="none"/></svg>)x";
    return s;
}

std::string error_of(const std::string& svg) {
    try {
        Reference::from_svg_string(svg, "ref.svg");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(GrowthSvg, ElementsAtBoundingBoxCentresWithDataAttributes) {
    Reference ref = Reference::from_svg_string(grid_svg(), "ref.svg");
    ASSERT_EQ(ref.size(), 9u);  // the frame carries no data-symbol
    EXPECT_EQ(ref.element(0).symbol, "a");
    EXPECT_NEAR(ref.element(0).position.x, 0, 1e-9);
    EXPECT_NEAR(ref.element(0).position.y, 0, 1e-9);
    // The group is last in document order; its box spans both circles after the translation.
    const ReferenceElement& mid = ref.element(8);
    EXPECT_EQ(mid.symbol, "b");
    EXPECT_EQ(mid.label, "m");
    EXPECT_NEAR(mid.angle, M_PI / 2, 1e-12);
    EXPECT_NEAR(mid.position.x, 10, 1e-9);
    EXPECT_NEAR(mid.position.y, 10, 1e-9);
    EXPECT_DOUBLE_EQ(ref.radius(8), 3);
    // Outlines: the group's two circles, relative to its centre, in their own paint.
    ASSERT_EQ(ref.outlines(8).size(), 2u);
    EXPECT_DOUBLE_EQ(ref.outlines(8)[0].fill.b, 1);
    EXPECT_EQ(ref.outlines(0).size(), 1u);
    EXPECT_EQ(ref.symbol_count(), 2u);
    EXPECT_EQ(ref.edges().size(), 16u);  // a square grid: 12 sides and one diagonal per square
}

TEST(GrowthSvg, DataSubIsTheLabelsOldName) {
    std::string s = kHead;
    const int xs[] = {0, 10, 5, -5, -10, -5, 5}, ys[] = {0, 0, 9, 9, 0, -9, -9};
    for (int i = 0; i < 7; ++i)
        s += "<circle data-symbol=\"d\" data-sub=\"v" + std::to_string(i) + "\" r=\"1\" cx=\"" +
             std::to_string(xs[i]) + "\" cy=\"" + std::to_string(ys[i]) + "\"/>";
    Reference ref = Reference::from_svg_string(s + "</svg>", "old.svg");
    EXPECT_EQ(ref.element(2).label, "v2");
    std::string m = error_of(kHead + R"x(<circle data-symbol="a" data-label="p" data-sub="q" r="1"/>
        <circle data-symbol="a" cx="5" r="1"/><circle data-symbol="a" cy="5" r="1"/></svg>)x");
    EXPECT_NE(m.find("element 0 <circle> (line 1): data-label and its old name data-sub"),
              std::string::npos)
        << m;
}

TEST(GrowthSvg, UseElementsAreElementsOfTheirOwn) {
    std::string s = kHead + R"x(<defs><circle id="dot" r="1"/></defs>)x";
    const double xs[] = {0, 10, 5, -5, -10, -5, 5}, ys[] = {0, 0, 8, 8, 0, -8, -8};
    for (int i = 0; i < 7; ++i)
        s += "<use href=\"#dot\" data-symbol=\"d\" x=\"" + std::to_string(xs[i]) + "\" y=\"" +
             std::to_string(ys[i]) + "\"/>";
    Reference ref = Reference::from_svg_string(s + "</svg>", "use.svg");
    ASSERT_EQ(ref.size(), 7u);
    EXPECT_NEAR(ref.element(3).position.x, -5, 1e-9);
    EXPECT_NEAR(ref.element(3).position.y, 8, 1e-9);
}

TEST(GrowthSvg, FlipsOnTheRoot) {
    // A 3 x 3 grid: each square is split one way (canonically); the author's flip gives the
    // other diagonal of the first square.
    auto grid = [](const std::string& flips) {
        std::string s = R"x(<svg xmlns="http://www.w3.org/2000/svg" )x" + flips + ">";
        for (int i = 0; i < 9; ++i)
            s += "<circle data-symbol=\"s\" r=\"1\" cx=\"" + std::to_string(i % 3 * 10) +
                 "\" cy=\"" + std::to_string(i / 3 * 10) + "\"/>";
        return s + "</svg>";
    };
    Reference plain = Reference::from_svg_string(grid(""), "sq.svg");
    auto has = [](const Reference& r, int i, int j) {
        for (auto [a, b] : r.edges())
            if (a == i && b == j) return true;
        return false;
    };
    bool diagonal04 = has(plain, 0, 4);
    ASSERT_NE(diagonal04, has(plain, 1, 3));
    std::string flip = diagonal04 ? "data-flips=\"0 4\"" : "data-flips=\"1 3\"";
    Reference flipped = Reference::from_svg_string(grid(flip), "sq.svg");
    EXPECT_EQ(has(flipped, 0, 4), !diagonal04);
    EXPECT_EQ(has(flipped, 1, 3), diagonal04);
    EXPECT_NE(error_of(grid("data-flips=\"0 x\"")).find("ref.svg: data-flips"), std::string::npos);
}

TEST(GrowthSvg, BadInputNamesFileAndElement) {
    EXPECT_NE(error_of(kHead + "<rect width='3' height='3'/></svg>").find("no element carries"),
              std::string::npos);
    std::string bad_angle = kHead + R"x(<circle id="c0" data-symbol="a" data-angle="ninety" r="1"/>
        <circle data-symbol="a" cx="5" r="1"/><circle data-symbol="a" cy="5" r="1"/></svg>)x";
    std::string m = error_of(bad_angle);
    EXPECT_NE(m.find("ref.svg: element 0 <circle id=\"c0\"> (line 1): data-angle 'ninety'"),
              std::string::npos)
        << m;
    m = error_of(kHead + "\n<rect data-symbol='a' width='3'\n</svg>");
    EXPECT_NE(m.find("ref.svg:3"), std::string::npos) << m;
    m = error_of(kHead + R"x(<circle data-symbol="" r="1"/></svg>)x");
    EXPECT_NE(m.find("empty data-symbol"), std::string::npos) << m;
    m = error_of(
        kHead + R"x(<circle data-symbol="a" r="1"/><circle data-symbol="a" cx="9" r="1"/></svg>)x");
    EXPECT_NE(m.find("at least 3 elements"), std::string::npos) << m;
    m = error_of(kHead + R"x(<circle data-symbol="a" r="1" data-size="-1"/></svg>)x");
    EXPECT_NE(m.find("data-size must be positive"), std::string::npos) << m;
}

// The reader hands over only shapes, so an element without one would vanish silently (issue 27).
TEST(GrowthSvg, EmptySymbolGroupIsNamed) {
    auto with = [](const std::string& extra) {
        std::string s = grid_svg();
        return s.insert(s.size() - 6, extra);
    };
    // grid_svg() spans two lines: the group is on line 4.
    std::string m = error_of(with("\n\n<g id=\"lost\" data-symbol=\"a\"></g>"));
    EXPECT_NE(
        m.find("ref.svg: <g id=\"lost\"> (line 4): carries data-symbol=\"a\" but owns no shape"),
        std::string::npos)
        << m;
    // Only text (which the reader does not draw), or every shape owned by a nearer data-symbol.
    m = error_of(with("<g id=\"words\" data-symbol=\"b\"><text>b</text></g>"));
    EXPECT_NE(m.find("<g id=\"words\">"), std::string::npos) << m;
    m =
        error_of(with("<g id=\"outer\" data-symbol=\"a\"><g data-symbol=\"b\"><circle cx=\"30\" "
                      "r=\"1\"/></g></g>"));
    EXPECT_NE(m.find("<g id=\"outer\">"), std::string::npos) << m;
    // Hidden elements and templates are not elements at all, as before.
    EXPECT_EQ(error_of(with("<g data-symbol=\"a\" style=\"display: none\"></g>"
                            "<defs><g id=\"t\" data-symbol=\"a\"></g></defs>")),
              "");
    EXPECT_EQ(
        Reference::from_svg_string(with("<g data-symbol=\"a\" display=\"none\"/>"), "r").size(),
        9u);
}

TEST(GrowthSvg, FromFileReadsEitherFormat) {
    auto dir = std::filesystem::temp_directory_path() / "acanthus_growth_svg_test";
    std::filesystem::create_directories(dir);
    auto svg = dir / "ref.svg", json = dir / "ref.json";
    std::ofstream(svg) << "  \n" << grid_svg();
    std::ofstream(json) << R"x({"elements": [{"symbol": "a", "x": 0, "y": 0},
        {"symbol": "a", "x": 10, "y": 0}, {"symbol": "a", "x": 5, "y": 8},
        {"symbol": "a", "x": -5, "y": 8}, {"symbol": "a", "x": -10, "y": 0},
        {"symbol": "a", "x": -5, "y": -8}, {"symbol": "a", "x": 5, "y": -8}]})x";
    EXPECT_EQ(Reference::from_file(svg.string()).size(), 9u);
    EXPECT_EQ(Reference::from_file(json.string()).size(), 7u);
    EXPECT_EQ(&load_reference(svg.string()), &load_reference(svg.string()));
    std::filesystem::remove_all(dir);
}

TEST(GrowthGuides, ToolsByClassWithBrushWidths) {
    Guides g = Guides::from_svg_string(kHead + R"x(<path class="flow" d="M 0,0 C 10,0 20,10 30,10"/>
        <line class="boundary" x1="50" y1="0" x2="50" y2="100"/>
        <g class="spray" transform="scale(2)"><polyline points="0,0 10,0 20,5" stroke="#000"
           stroke-width="7"/></g>
        <rect width="5" height="5"/></svg>)x",
                                       "guides.svg");
    ASSERT_EQ(g.flow.size(), 1u);
    EXPECT_EQ(g.flow[0].size(), 17u);  // a curve is flattened
    EXPECT_NEAR(g.flow[0].back().x, 30, 1e-9);
    ASSERT_EQ(g.boundary.size(), 1u);
    EXPECT_EQ(g.boundary[0].size(), 2u);
    ASSERT_EQ(g.spray.size(), 1u);
    EXPECT_NEAR(g.spray[0].width, 14, 1e-9);  // scaled with the group
    EXPECT_NEAR(g.spray[0].points.back().x, 40, 1e-9);
    Options o;
    g.add_to(o);
    EXPECT_EQ(o.flow_strokes.size(), 1u);
    EXPECT_EQ(o.boundary_strokes.size(), 1u);
    EXPECT_EQ(o.spray_strokes.size(), 1u);
}

TEST(GrowthGuides, BadGuides) {
    auto error = [](const std::string& svg) {
        try {
            Guides::from_svg_string(svg, "g.svg");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error(kHead + "<path d='M 0,0 L 5,5'/></svg>").find("g.svg: no guide"),
              std::string::npos);
    std::string m = error(kHead + "<path id='s' class='spray' d='M 0,0 L 5,5'/></svg>");
    EXPECT_NE(m.find("<path id=\"s\">"), std::string::npos) << m;
    EXPECT_NE(m.find("stroke-width"), std::string::npos) << m;
    EXPECT_NE(error("<svg").find("g.svg:1"), std::string::npos);
}

TEST(GrowthGuides, FlowStrokeErrorsNameTheGuidesFile) {
    const std::string head = R"x(<svg xmlns="http://www.w3.org/2000/svg">)x";
    try {
        Guides::from_svg_string(head + R"x(<path class="flow" d="M 5,5 L 5,5 L 5,5"/></svg>)x",
                                "guides.svg");
        FAIL() << "a flow stroke with no length loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("guides.svg: <path> (line 1): a flow stroke with no "
                                             "length"),
                  std::string::npos)
            << e.what();
    }
    // Flow mode with a guides file that has no flow stroke names the file.
    Options o;
    o.mode = Mode::flow;
    Guides::from_svg_string(head + R"x(<path class="boundary" d="M 0,0 L 9,9"/></svg>)x",
                            "walls.svg")
        .add_to(o);
    Reference ref = Reference::from_svg_string(
        head + R"x(<circle data-symbol="a" r="1"/><circle data-symbol="a" cx="10" r="1"/>
        <circle data-symbol="a" cx="5" cy="9" r="1"/><circle data-symbol="a" cx="-5" cy="9" r="1"/>
        <circle data-symbol="a" cx="-10" r="1"/><circle data-symbol="a" cx="-5" cy="-9" r="1"/>
        <circle data-symbol="a" cx="5" cy="-9" r="1"/></svg>)x",
        "ref.svg");
    try {
        synthesize(ref, Region::from_spec("rect:100,100"), o, {}, 1);
        FAIL() << "flow mode grew without a flow stroke";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("walls.svg has none"), std::string::npos) << e.what();
    }
}

TEST(GrowthPriority, ParsesSymbolLevels) {
    auto p = parse_priority(" flower=2, leaf = -1 ,");
    EXPECT_EQ(p.size(), 2u);
    EXPECT_EQ(p["flower"], 2);
    EXPECT_EQ(p["leaf"], -1);
    EXPECT_TRUE(parse_priority("").empty());
    EXPECT_THROW(parse_priority("flower"), InputError);
    EXPECT_THROW(parse_priority("flower=two"), InputError);
    EXPECT_THROW(parse_priority("=2"), InputError);
}

}  // namespace
