// The one SVG reader (svg/shape_reader): what its consumers other than regions rely on — element
// chains with ids, classes and data-*, inherited paint, open subpaths and lines, stroke widths in
// root units, and the coordinate range.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <string>

#include "svg/shape_reader.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

TEST(SvgShapes, ElementChainsCarryIdsClassesAndData) {
    auto shapes = read_svg_shapes(R"x(<svg xmlns="http://www.w3.org/2000/svg">
      <g id="row" class="wall  brick" data-symbol="a" data-angle="30">
        <rect id="r" class="window" width="2" height="1"/>
      </g></svg>)x",
                                  "t.svg");
    ASSERT_EQ(shapes.size(), 1u);
    const SvgElement& rect = *shapes[0].element;
    EXPECT_EQ(rect.tag, "rect");
    EXPECT_EQ(rect.id, "r");
    EXPECT_TRUE(rect.has_class("window"));
    EXPECT_NE(rect.label.find("<rect id=\"r\"> (line 3)"), std::string::npos) << rect.label;
    ASSERT_TRUE(rect.parent);
    const SvgElement& group = *rect.parent;
    EXPECT_EQ(group.classes, (std::vector<std::string>{"wall", "brick"}));
    EXPECT_EQ(group.data.at("symbol"), "a");
    EXPECT_EQ(group.data.at("angle"), "30");
    EXPECT_EQ(group.parent->tag, "svg");
}

TEST(SvgShapes, PaintIsInheritedAndStrokeWidthScaled) {
    auto shapes = read_svg_shapes(R"x(<svg xmlns="http://www.w3.org/2000/svg">
      <style>.s { stroke: #00f }</style>
      <g fill="red" stroke-width="3" transform="scale(2)">
        <path class="s" d="M 0,0 L 5,0 L 5,5"/>
        <line x1="0" y1="0" x2="4" y2="0" style="fill:none"/>
      </g></svg>)x",
                                  "t.svg");
    ASSERT_EQ(shapes.size(), 2u);
    EXPECT_EQ(shapes[0].fill, "red");
    EXPECT_EQ(shapes[0].stroke, "#00f");
    EXPECT_DOUBLE_EQ(shapes[0].stroke_width, 6);
    EXPECT_FALSE(shapes[0].paths.front().closed());  // open subpaths stay open
    EXPECT_EQ(shapes[0].paths.front().size_open(), 2u);
    EXPECT_EQ(shapes[1].element->tag, "line");
    EXPECT_EQ(shapes[1].fill, "none");
    EXPECT_DOUBLE_EQ(shapes[1].paths.front().finalPoint()[Geom::X], 8);
}

TEST(SvgShapes, UseIsTheParentOfWhatItDraws) {
    auto shapes = read_svg_shapes(R"x(<svg xmlns="http://www.w3.org/2000/svg">
      <defs><circle id="c" r="1"/></defs>
      <use href="#c" x="5" data-symbol="dot"/><use href="#c" x="9" data-symbol="dot"/></svg>)x",
                                  "t.svg");
    ASSERT_EQ(shapes.size(), 2u);
    EXPECT_EQ(shapes[0].element->parent->tag, "use");
    EXPECT_NE(shapes[0].element->parent, shapes[1].element->parent);
    EXPECT_NEAR(shapes[1].paths.boundsExact()->midpoint()[Geom::X], 9, 1e-9);
}

TEST(SvgShapes, CoordinatesBeyondTheRangeAreRefused) {
    try {
        read_svg_shapes(R"x(<svg xmlns="http://www.w3.org/2000/svg">
          <path id="far" d="M 0,0 L 2e9,0 L 0,1"/></svg>)x",
                        "t.svg");
        FAIL();
    } catch (const InputError& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("t.svg: <path id=\"far\"> (line 2): coordinates out of range"),
                  std::string::npos)
            << m;
    }
    EXPECT_TRUE(read_svg_shapes(R"x(<svg xmlns="http://www.w3.org/2000/svg"/>)x", "t.svg").empty());
}

}  // namespace
