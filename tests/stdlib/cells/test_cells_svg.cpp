// The facade SVG reader: wall and openings from class words (inherited from groups), labels,
// ignored lines and unfilled shapes, even-odd holes, panels as walls, and bad drawings named by
// file and SVG id.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cells_oracle.hpp"

using namespace cells_test;

namespace {

bool has(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

std::string svg(const std::string& body) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"600\" height=\"400\">\n" + body +
           "\n</svg>\n";
}

std::string error_of(const std::string& text) {
    try {
        Facade::from_svg_string(text, "front.svg");
    } catch (const acanthus::InputError& e) {
        return e.what();
    }
    return "";
}

// A 600 x 400 wall; a sash window drawn as a group with glazing bars; an arched door on the
// ground, named by its group; a round window.
const std::string kFront = svg(R"(
  <rect id="front" class="wall brick" x="0" y="0" width="600" height="400" fill="#b55"/>
  <g class="window sash" id="w1">
    <rect id="w1-hole" x="60" y="100" width="120" height="180" fill="#335"/>
    <line x1="120" y1="100" x2="120" y2="280" stroke="white"/>
    <rect x="60" y="190" width="120" height="4" fill="none" stroke="white"/>
  </g>
  <g id="door" class="door">
    <path class="arch" d="M 260 400 V 250 A 40 40 0 0 1 340 250 V 400 Z" fill="#333"/>
  </g>
  <circle id="oculus" class="window oculus" cx="480" cy="150" r="40" fill="#335"/>)");

}  // namespace

TEST(CellsSvg, WallAndOpeningsFromClasses) {
    Facade f = Facade::from_svg_string(kFront, "front.svg");
    ASSERT_EQ(f.faces().size(), 1u);
    double expected = 600.0 * 400 - 120 * 180 - (80 * 150 + M_PI * 40 * 40 / 2) - M_PI * 40 * 40;
    EXPECT_NEAR(f.wall_area(), expected, 1e-3 * expected);
    EXPECT_EQ(f.openings().size(), 3u);  // lines and the unfilled glazing bar are no openings
    EXPECT_TRUE(has(f.faces()[0].labels, "wall"));
    EXPECT_TRUE(has(f.faces()[0].labels, "brick"));
    EXPECT_TRUE(has(f.faces()[0].labels, "front"));
}

TEST(CellsSvg, LabelsInheritGroupClassesAndIds) {
    Facade f = Facade::from_svg_string(kFront, "front.svg");
    bool sill = false, arch = false, oculus = false;
    for (const Edge& e : f.edges()) {
        if (has(e.labels, "w1-hole")) {
            EXPECT_TRUE(has(e.labels, "window"));  // from <g class="window sash">
            EXPECT_TRUE(has(e.labels, "sash"));
            EXPECT_FALSE(has(e.labels, "wall"));
            sill = sill || e.part == Part::bottom;
        }
        if (e.arc && has(e.labels, "door")) {
            EXPECT_TRUE(has(e.labels, "arch"));  // its own class, then the group's
            EXPECT_EQ(e.labels.back(), "door");  // no id of its own: the group's
            arch = true;
        }
        if (has(e.labels, "oculus")) {
            EXPECT_TRUE(e.closed && e.arc);
            EXPECT_NEAR(e.length, 2 * M_PI * 40, 1e-6);
            oculus = true;
        }
    }
    EXPECT_TRUE(sill && arch && oculus);
}

TEST(CellsSvg, OpeningInsideAWallGroup) {
    Facade f = Facade::from_svg_string(svg(R"(
      <g class="wall">
        <rect x="0" y="0" width="300" height="200"/>
        <rect id="win" class="window" x="100" y="50" width="100" height="100"/>
      </g>)"),
                                       "g.svg");
    EXPECT_NEAR(f.wall_area(), 300.0 * 200 - 100 * 100, 1e-6);
    for (const Edge& e : f.edges()) {
        if (has(e.labels, "win")) {
            EXPECT_FALSE(has(e.labels, "wall"));
        }
    }
}

TEST(CellsSvg, EvenOddWallWithAHole) {
    Facade f = Facade::from_svg_string(svg(R"(
      <path class="wall" fill-rule="evenodd"
            d="M 0 0 H 300 V 200 H 0 Z M 100 50 H 200 V 150 H 100 Z"/>)"),
                                       "evenodd.svg");
    EXPECT_NEAR(f.wall_area(), 300.0 * 200 - 100 * 100, 1e-6);
    EXPECT_TRUE(f.openings().empty());
}

TEST(CellsSvg, BadFacadesNameFileAndId) {
    std::string e = error_of(svg(R"(<rect id="w" class="window" width="10" height="10"/>)"));
    EXPECT_NE(e.find("front.svg"), std::string::npos);
    EXPECT_NE(e.find("wall"), std::string::npos);
    e = error_of(svg(R"(<rect id="front" class="wall" width="600" height="400" fill="none"
                          stroke="black"/>)"));
    EXPECT_NE(e.find("id=\"front\""), std::string::npos) << e;
    EXPECT_NE(e.find("no fill"), std::string::npos) << e;
    e = error_of(svg(R"(<rect class="wall" width="600" height="400"/>
                        <rect id="bay" class="window" x="550" y="100" width="100" height="100"/>)"));
    EXPECT_NE(e.find("id=\"bay\""), std::string::npos) << e;
    EXPECT_NE(e.find("crosses the wall's outline"), std::string::npos) << e;
    e = error_of(svg(R"(<rect class="wall" width="600" height="400"/>
                        <path id="flat" class="window" d="M 100 100 H 200 Z"/>)"));
    EXPECT_NE(e.find("id=\"flat\""), std::string::npos) << e;
    EXPECT_NE(e.find("no area"), std::string::npos) << e;
    e = error_of("<svg xmlns=\"http://www.w3.org/2000/svg\"><rect class=\"wall\"");
    EXPECT_EQ(e.rfind("front.svg", 0), 0u) << e;
    try {
        Facade::from_svg_file("/no/such/facade.svg");
        FAIL();
    } catch (const acanthus::InputError& x) {
        EXPECT_NE(std::string(x.what()).find("/no/such/facade.svg"), std::string::npos);
    }
}

TEST(CellsSvg, ZeroSizeAndOverlappingShapesNamed) {
    // SVG draws nothing for these; a facade refuses them rather than losing a window.
    std::string e = error_of(svg(R"(<rect id="front" class="wall" width="600" height="400"/>
                        <rect id="slot" class="window" x="100" y="100" width="0" height="50"/>)"));
    EXPECT_NE(e.find("front.svg: <rect id=\"slot\"> (line 3)"), std::string::npos) << e;
    EXPECT_NE(e.find("no area"), std::string::npos) << e;
    e = error_of(svg(R"(<rect id="front" class="wall" width="600" height="400"/>
                        <g class="oculus"><circle id="eye" cx="300" cy="100" r="0"/></g>)"));
    EXPECT_NE(e.find("<circle id=\"eye\">"), std::string::npos) << e;
    EXPECT_NE(e.find("no area"), std::string::npos) << e;
    e = error_of(svg(R"(<rect id="front" class="wall" width="0" height="400"/>
                        <rect id="back" class="wall" width="600" height="400"/>)"));
    EXPECT_NE(e.find("<rect id=\"front\">"), std::string::npos) << e;
    // Unfilled, hidden or in <defs>: not masonry, still ignored.
    e = error_of(svg(R"(<rect id="front" class="wall" width="600" height="400"/>
                        <rect class="window" width="0" height="5" fill="none"/>
                        <defs><rect id="d" width="0" height="5"/></defs>
                        <g display="none"><circle r="0"/></g>)"));
    EXPECT_EQ(e, "");
    e = error_of(svg(R"(<rect id="front" class="wall" width="600" height="400"/>
                        <rect id="a" class="window" x="100" y="100" width="100" height="100"/>
                        <rect id="b" class="window" x="150" y="150" width="100" height="100"/>)"));
    EXPECT_NE(e.find("<rect id=\"a\"> (line 3) and <rect id=\"b\"> (line 4)"), std::string::npos)
        << e;
    EXPECT_NE(e.find("openings overlap"), std::string::npos) << e;
}

TEST(CellsSvg, PanelsAreWholeWalls) {
    Facade f = Facade::for_panel(acanthus::Region::from_spec("rect:200,140"));
    EXPECT_NEAR(f.wall_area(), 200.0 * 140, 1e-6);
    EXPECT_TRUE(has(f.faces()[0].labels, "panel"));
    // The arched panel with an arched hole (even-odd): the hole is part of the wall's outline.
    acanthus::Region arch = acanthus::Region::from_svg_file(std::string(ACANTHUS_SOURCE_DIR) +
                                                            "/examples/panels/arch-window.svg");
    // Without a `wall` it is not a facade; asked to, it is tiled as one wall.
    try {
        Facade::for_panel(arch);
        ADD_FAILURE() << "an SVG without a wall was read as a facade";
    } catch (const acanthus::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("arch-window.svg: no filled shape with class"),
                  std::string::npos)
            << e.what();
    }
    f = Facade::for_panel(arch, true);
    EXPECT_NEAR(f.wall_area(), arch.area(), 1e-3 * arch.area());
    EXPECT_TRUE(f.openings().empty());
    // A facade drawing as --region: its `wall` shapes and openings.
    auto path = std::filesystem::temp_directory_path() / "cells_test_front.svg";
    std::ofstream(path) << kFront;
    acanthus::Region front = acanthus::Region::from_svg_file(path.string());
    f = Facade::for_panel(front);
    EXPECT_EQ(f.openings().size(), 3u);
    EXPECT_LT(f.wall_area(), front.area());
    std::filesystem::remove(path);
}
