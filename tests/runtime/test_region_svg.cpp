// SVG region loading: every element, transform and fill-rule feature, checked by exact area,
// bounds and containment.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <cmath>
#include <string>

#include "region/build.hpp"
#include "region/region_data.hpp"

using acanthus::Point;
using acanthus::Region;

namespace {

// Arcs become cubic Béziers within 6e-9 of the radius (lib2geom 1.2.2 mishandles arcs).
constexpr double kArcArea = 1e-3;

Region svg(const std::string& body, const std::string& root_attrs = "") {
    return Region::from_svg_string(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" " + root_attrs + ">" + body + "</svg>",
        "inline.svg");
}

Region path(const std::string& d, const std::string& extra = "") {
    return svg("<path d=\"" + d + "\" " + extra + "/>");
}

void expect_bounds(const Region& r, double x0, double y0, double x1, double y1, double tol = 1e-9) {
    EXPECT_NEAR(r.bounds().x0, x0, tol);
    EXPECT_NEAR(r.bounds().y0, y0, tol);
    EXPECT_NEAR(r.bounds().x1, x1, tol);
    EXPECT_NEAR(r.bounds().y1, y1, tol);
}

// Outer rings have positive signed area, so the boundary sums to the area.
void expect_oriented(const Region& r) {
    EXPECT_NEAR(acanthus::detail::signed_area(r.data().paths), r.area(), 1e-9 * r.area());
    EXPECT_GT(r.area(), 0);
}

}  // namespace

TEST(region_svg, AbsoluteLinesAndHV) {
    Region r = path("M 0 0 H 100 V 50 L 0 50 Z");
    EXPECT_NEAR(r.area(), 5000, 1e-9);
    expect_bounds(r, 0, 0, 100, 50);
    EXPECT_TRUE(r.contains({50, 25}));
    EXPECT_FALSE(r.contains({50, 51}));
    EXPECT_FALSE(r.contains({-1, 25}));
    EXPECT_EQ(r.name(), "inline.svg");
}

TEST(region_svg, RelativeCommands) {
    Region r = path("m 10 10 l 20 0 v 20 h -20 z");
    EXPECT_NEAR(r.area(), 400, 1e-9);
    expect_bounds(r, 10, 10, 30, 30);
}

TEST(region_svg, OpenPathIsFilledAsClosed) {
    EXPECT_NEAR(path("M0,0 L100,0 L100,100").area(), 5000, 1e-9);
}

TEST(region_svg, ReversedOrientationGivesSameArea) {
    Region cw = path("M0,0 H100 V50 H0 Z");
    Region ccw = path("M0,0 V50 H100 V0 Z");
    EXPECT_NEAR(cw.area(), ccw.area(), 1e-9);
    expect_oriented(cw);
    expect_oriented(ccw);
}

TEST(region_svg, CubicBezierExactArea) {
    // Area under C(0,0)(0,h)(w,h)(w,0) is 0.6 w h.
    Region r = path("M0,0 C0,100 100,100 100,0 Z");
    EXPECT_NEAR(r.area(), 6000, 1e-9);
    expect_bounds(r, 0, 0, 100, 75);
    expect_oriented(r);
}

TEST(region_svg, QuadraticAndSmoothQuadratic) {
    // Each half is a parabola under control height 80: area 100 * (80 - 80/3).
    Region t = path("M0,0 Q50,80 100,80 T200,0 Z");
    Region q = path("M0,0 Q50,80 100,80 Q150,80 200,0 Z");
    EXPECT_NEAR(t.area(), 2 * 100 * (80 - 80.0 / 3), 1e-9);
    EXPECT_NEAR(q.area(), t.area(), 1e-9);
    Region rel = path("m0,0 q50,80 100,80 t100,-80 z");
    EXPECT_NEAR(rel.area(), t.area(), 1e-9);
}

TEST(region_svg, SmoothCubicMatchesExplicitReflection) {
    Region s = path("M0,0 C0,50 50,100 100,100 S200,50 200,0 Z");
    Region c = path("M0,0 C0,50 50,100 100,100 C150,100 200,50 200,0 Z");
    Region rel = path("M0,0 c0,50 50,100 100,100 s100,-50 100,-100 z");
    EXPECT_NEAR(s.area(), c.area(), 1e-9);
    EXPECT_NEAR(rel.area(), c.area(), 1e-9);
    EXPECT_GT(c.area(), 10000);
}

TEST(region_svg, ArcsAbsoluteAndRelative) {
    Region a = path("M0,50 A50,50 0 0 1 100,50 A50,50 0 0 1 0,50 Z");
    EXPECT_NEAR(a.area(), M_PI * 2500, kArcArea);
    expect_bounds(a, 0, 0, 100, 100);
    Region rel = path("m0,50 a50,50 0 1 0 100,0 a50,50 0 1 0 -100,0 z");
    EXPECT_NEAR(rel.area(), M_PI * 2500, kArcArea);
    expect_oriented(rel);
    // A half disc: the large-arc and sweep flags pick the lower half.
    Region half = path("M0,0 A50,50 0 0 0 100,0 Z");
    EXPECT_NEAR(half.area(), M_PI * 1250, kArcArea);
    EXPECT_TRUE(half.contains({50, 40}));
    EXPECT_FALSE(half.contains({50, -10}));
}

TEST(region_svg, RotatedEllipticalArc) {
    double c = 60 * std::cos(M_PI / 4), s = 60 * std::sin(M_PI / 4);
    std::string d = "M" + std::to_string(100 + c) + "," + std::to_string(100 + s) +
                    " A60,30 45 0 1 " + std::to_string(100 - c) + "," + std::to_string(100 - s) +
                    " A60,30 45 0 1 " + std::to_string(100 + c) + "," + std::to_string(100 + s) +
                    "Z";
    Region r = path(d);
    EXPECT_NEAR(r.area(), M_PI * 60 * 30, 1e-3);
    EXPECT_TRUE(r.contains({100 + 40, 100 + 40}));
    EXPECT_FALSE(r.contains({100 + 40, 100 - 40}));
}

TEST(region_svg, PolygonAndPolyline) {
    Region pg = svg("<polygon points=\"0,0 100,0 100,100\"/>");
    EXPECT_NEAR(pg.area(), 5000, 1e-9);
    Region pl = svg("<polyline points=\"0 0, 100 0 100 100\"/>");
    EXPECT_NEAR(pl.area(), 5000, 1e-9);
    EXPECT_TRUE(pl.contains({90, 10}));
    EXPECT_FALSE(pl.contains({10, 90}));
}

TEST(region_svg, RectPlainAndRounded) {
    Region plain = svg("<rect x=\"10\" y=\"20\" width=\"100\" height=\"50\"/>");
    EXPECT_NEAR(plain.area(), 5000, 1e-9);
    expect_bounds(plain, 10, 20, 110, 70);
    Region round = svg("<rect x=\"10\" y=\"20\" width=\"100\" height=\"50\" rx=\"10\"/>");
    EXPECT_NEAR(round.area(), 5000 - (4 - M_PI) * 100, kArcArea);
    EXPECT_FALSE(round.contains({11, 21}));
    EXPECT_TRUE(round.contains({20, 30}));
    Region both = svg("<rect width=\"100\" height=\"50\" rx=\"20\" ry=\"10\"/>");
    EXPECT_NEAR(both.area(), 5000 - (4 - M_PI) * 200, kArcArea);
    // rx larger than half the width is clamped: a stadium.
    Region stadium = svg("<rect width=\"100\" height=\"40\" rx=\"80\" ry=\"20\"/>");
    EXPECT_NEAR(stadium.area(), M_PI * 50 * 20, kArcArea);  // an ellipse
}

TEST(region_svg, CircleAndEllipse) {
    Region c = svg("<circle cx=\"50\" cy=\"60\" r=\"10\"/>");
    EXPECT_NEAR(c.area(), M_PI * 100, kArcArea);
    expect_bounds(c, 40, 50, 60, 70);
    EXPECT_TRUE(c.contains({50, 60}));
    EXPECT_FALSE(c.contains({58, 68}));
    Region e = svg("<ellipse cx=\"0\" cy=\"0\" rx=\"30\" ry=\"10\"/>");
    EXPECT_NEAR(e.area(), M_PI * 300, kArcArea);
    expect_bounds(e, -30, -10, 30, 10);
    EXPECT_TRUE(e.contains({25, 0}));
    EXPECT_FALSE(e.contains({0, 11}));
}

TEST(region_svg, Units) {
    Region r = svg("<rect width=\"1in\" height=\"72pt\"/>");
    EXPECT_NEAR(r.area(), 96.0 * 96.0, 1e-9);
    Region mm = svg("<circle cx=\"0\" cy=\"0\" r=\"25.4mm\"/>");
    EXPECT_NEAR(mm.area(), M_PI * 96 * 96, kArcArea);
}

TEST(region_svg, TransformsOnShapes) {
    const std::string rect = "<rect width=\"10\" height=\"20\" transform=\"";
    expect_bounds(svg(rect + "translate(5,7)\"/>"), 5, 7, 15, 27);
    expect_bounds(svg(rect + "translate(5)\"/>"), 5, 0, 15, 20);
    Region scaled = svg(rect + "scale(2,3)\"/>");
    expect_bounds(scaled, 0, 0, 20, 60);
    EXPECT_NEAR(scaled.area(), 1200, 1e-9);
    expect_bounds(svg(rect + "scale(2)\"/>"), 0, 0, 20, 40);
    // rotate(90) maps (x, y) to (-y, x).
    expect_bounds(svg(rect + "rotate(90)\"/>"), -20, 0, 0, 10);
    // About the centre (5, 10) the box turns in place.
    expect_bounds(svg(rect + "rotate(90 5 10)\"/>"), -5, 5, 15, 15);
    Region skx = svg(rect + "skewX(45)\"/>");
    expect_bounds(skx, 0, 0, 30, 20);
    EXPECT_NEAR(skx.area(), 200, 1e-9);
    expect_bounds(svg(rect + "skewY(45)\"/>"), 0, 0, 10, 30);
    expect_bounds(svg(rect + "matrix(1 0 0 1 100 200)\"/>"), 100, 200, 110, 220);
    // Lists apply right to left: scale first, then translate.
    expect_bounds(svg(rect + "translate(100,0) scale(2)\"/>"), 100, 0, 120, 40);
    expect_bounds(svg(rect + "scale(2),translate(100,0)\"/>"), 200, 0, 220, 40);
}

TEST(region_svg, TransformedArcStaysExact) {
    Region r = svg("<circle cx=\"0\" cy=\"0\" r=\"10\" transform=\"scale(3,1) rotate(30)\"/>");
    EXPECT_NEAR(r.area(), M_PI * 300, kArcArea);
    expect_oriented(r);
    Region mirrored = svg("<circle cx=\"0\" cy=\"0\" r=\"10\" transform=\"scale(-1,1)\"/>");
    EXPECT_NEAR(mirrored.area(), M_PI * 100, kArcArea);
    expect_oriented(mirrored);
}

TEST(region_svg, NestedGroupTransforms) {
    Region r =
        svg("<g transform=\"translate(100,0)\"><g transform=\"scale(2)\">"
            "<rect width=\"10\" height=\"20\" transform=\"translate(1,1)\"/></g></g>");
    expect_bounds(r, 102, 2, 122, 42);
    EXPECT_NEAR(r.area(), 800, 1e-9);
}

TEST(region_svg, FillRuleNonzeroKeepsSameDirectionInnerRing) {
    const std::string d = "M0,0 H100 V100 H0 Z M25,25 H75 V75 H25 Z";
    Region nz = path(d);
    EXPECT_FALSE(nz.evenodd());
    EXPECT_NEAR(nz.area(), 10000, 1e-9);
    EXPECT_TRUE(nz.contains({50, 50}));
    // The redundant inner ring is not part of the boundary.
    EXPECT_NEAR(nz.distance_to_boundary({50, 50}), 50, 1e-9);
}

TEST(region_svg, FillRuleEvenOddAttributeAndStyle) {
    const std::string d = "M0,0 H100 V100 H0 Z M25,25 H75 V75 H25 Z";
    Region attr = path(d, "fill-rule=\"evenodd\"");
    EXPECT_TRUE(attr.evenodd());
    EXPECT_NEAR(attr.area(), 7500, 1e-9);
    EXPECT_FALSE(attr.contains({50, 50}));
    EXPECT_TRUE(attr.contains({10, 50}));
    Region style = path(d, "style=\"fill:#000;fill-rule:evenodd\"");
    EXPECT_NEAR(style.area(), 7500, 1e-9);
    // style wins over the attribute
    Region both = path(d, "fill-rule=\"nonzero\" style=\"fill-rule:evenodd\"");
    EXPECT_NEAR(both.area(), 7500, 1e-9);
    Region inherited = svg("<g style=\"fill-rule:evenodd\"><path d=\"" + d + "\"/></g>");
    EXPECT_NEAR(inherited.area(), 7500, 1e-9);
    Region overridden =
        svg("<g fill-rule=\"evenodd\"><path fill-rule=\"nonzero\" d=\"" + d + "\"/></g>");
    EXPECT_NEAR(overridden.area(), 10000, 1e-9);
    expect_oriented(attr);
}

TEST(region_svg, HoleByOppositeDirectionUnderNonzero) {
    Region r = path("M0,0 H100 V100 H0 Z M25,25 V75 H75 V25 Z");
    EXPECT_NEAR(r.area(), 7500, 1e-9);
    EXPECT_FALSE(r.contains({50, 50}));
    EXPECT_NEAR(r.distance_to_boundary({50, 50}), 25, 1e-9);
    expect_oriented(r);
}

TEST(region_svg, IslandInsideHole) {
    Region r = path("M0,0 H100 V100 H0 Z M20,20 H80 V80 H20 Z M40,40 H60 V60 H40 Z",
                    "fill-rule=\"evenodd\"");
    EXPECT_NEAR(r.area(), 10000 - 3600 + 400, 1e-9);
    EXPECT_TRUE(r.contains({50, 50}));
    EXPECT_FALSE(r.contains({30, 30}));
    expect_oriented(r);
}

TEST(region_svg, SelfCrossingFigureEight) {
    // Two triangles meeting at (50, 50): both lobes are filled under either rule.
    Region r = path("M0,0 L100,100 L100,0 L0,100 Z");
    EXPECT_NEAR(r.area(), 5000, 1e-9);
    EXPECT_TRUE(r.contains({10, 50}));
    EXPECT_TRUE(r.contains({90, 50}));
    EXPECT_FALSE(r.contains({50, 10}));
    expect_oriented(r);
}

TEST(region_svg, StarPolygonNonzeroAndEvenodd) {
    // A pentagram: nonzero fills the centre, evenodd leaves it empty.
    std::string pts;
    for (int i = 0; i < 5; ++i) {
        double a = -M_PI / 2 + i * 4 * M_PI / 5;
        pts += std::to_string(100 + 100 * std::cos(a)) + "," +
               std::to_string(100 + 100 * std::sin(a)) + " ";
    }
    Region nz = svg("<polygon points=\"" + pts + "\"/>");
    Region eo = svg("<polygon fill-rule=\"evenodd\" points=\"" + pts + "\"/>");
    EXPECT_TRUE(nz.contains({100, 100}));
    EXPECT_FALSE(eo.contains({100, 100}));
    EXPECT_GT(nz.area(), eo.area());
    expect_oriented(nz);
    expect_oriented(eo);
    // The tips are filled in both; the difference is the inner pentagon.
    double inner_r = 100 * std::cos(2 * M_PI / 5) / std::cos(M_PI / 5);
    double pentagon = 2.5 * inner_r * inner_r * std::sin(2 * M_PI / 5);
    EXPECT_NEAR(nz.area() - eo.area(), pentagon, 1e-3);  // points printed to 6 decimals
}

TEST(region_svg, ViewBoxKeepsUserUnits) {
    Region r = svg("<rect width=\"10\" height=\"10\"/>",
                   "width=\"100mm\" height=\"100mm\" viewBox=\"0 0 10 10\"");
    expect_bounds(r, 0, 0, 10, 10);
    EXPECT_NEAR(r.area(), 100, 1e-9);
}

TEST(region_svg, IgnoredContainersAndHiddenElements) {
    Region r =
        svg("<defs><rect id=\"d\" width=\"500\" height=\"500\"/></defs>"
            "<clipPath id=\"c\"><rect width=\"500\" height=\"500\"/></clipPath>"
            "<mask id=\"m\"><rect width=\"500\" height=\"500\"/></mask>"
            "<symbol id=\"s\"><rect width=\"500\" height=\"500\"/></symbol>"
            "<metadata><rect width=\"500\" height=\"500\"/></metadata>"
            "<rect width=\"500\" height=\"500\" style=\"display:none\"/>"
            "<g display=\"none\"><rect width=\"500\" height=\"500\"/></g>"
            "<text x=\"0\" y=\"0\">hello</text><line x1=\"0\" y1=\"0\" x2=\"900\" y2=\"900\"/>"
            "<rect width=\"10\" height=\"10\"/>");
    EXPECT_NEAR(r.area(), 100, 1e-9);
    expect_bounds(r, 0, 0, 10, 10);
}

TEST(region_svg, InkscapeLayersAndNamedView) {
    Region r = Region::from_svg_string(R"SVG(<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
     xmlns:svg="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">
  <sodipodi:namedview id="base" pagecolor="#ffffff" inkscape:zoom="1.4"/>
  <g inkscape:groupmode="layer" inkscape:label="Layer 1" id="layer1" transform="translate(0,-50)">
    <svg:rect id="r1" x="10" y="60" width="30" height="30"/>
  </g>
  <g inkscape:groupmode="layer" inkscape:label="Hidden" style="display:none">
    <rect width="1000" height="1000"/>
  </g>
</svg>)SVG",
                                       "layers.svg");
    expect_bounds(r, 10, 10, 40, 40);
    EXPECT_NEAR(r.area(), 900, 1e-9);
}

TEST(region_svg, SeparateShapesAreUnited) {
    Region apart =
        svg("<rect width=\"10\" height=\"10\"/><rect x=\"20\" width=\"10\" height=\"10\"/>");
    EXPECT_NEAR(apart.area(), 200, 1e-9);
    EXPECT_TRUE(apart.contains({25, 5}));
    EXPECT_FALSE(apart.contains({15, 5}));
    Region overlap = svg(
        "<rect width=\"20\" height=\"10\"/><rect x=\"10\" y=\"5\" width=\"20\" height=\"10\"/>");
    EXPECT_NEAR(overlap.area(), 350, 1e-9);
    // The union's boundary has no edge inside the overlap: the nearest boundary point is the
    // corner (20, 5), not the edges x = 10, x = 20 or y = 10 that the two rects draw there.
    EXPECT_NEAR(overlap.distance_to_boundary({15, 7.5}), std::sqrt(31.25), 1e-9);
    expect_oriented(overlap);
    Region nested =
        svg("<rect width=\"100\" height=\"100\"/><circle cx=\"50\" cy=\"50\" r=\"10\"/>");
    EXPECT_NEAR(nested.area(), 10000, 1e-9);
    EXPECT_NEAR(nested.distance_to_boundary({50, 50}), 50, 1e-9);
}

TEST(region_svg, OverlappingCirclesUnionIsExact) {
    const double r = 10, d = 10;
    Region u = svg("<circle cx=\"0\" cy=\"0\" r=\"10\"/><circle cx=\"10\" cy=\"0\" r=\"10\"/>");
    double lens = 2 * r * r * std::acos(d / (2 * r)) - d / 2 * std::sqrt(4 * r * r - d * d);
    EXPECT_NEAR(u.area(), 2 * M_PI * r * r - lens, kArcArea);
    EXPECT_NEAR(u.distance_to_boundary({5, 0}), std::sqrt(100 - 25), 1e-6);
    expect_oriented(u);
}

TEST(region_svg, EvenOddShapeUnitedWithNonzeroShape) {
    Region r =
        svg("<path fill-rule=\"evenodd\" d=\"M0,0 H100 V100 H0 Z M25,25 H75 V75 H25 Z\"/>"
            "<rect x=\"200\" width=\"10\" height=\"10\"/>");
    EXPECT_NEAR(r.area(), 7600, 1e-9);
    EXPECT_FALSE(r.contains({50, 50}));
    EXPECT_TRUE(r.contains({205, 5}));
}

TEST(region_svg, UseReferencesDefs) {
    Region r =
        svg("<defs><rect id=\"tile\" width=\"10\" height=\"10\"/></defs>"
            "<use href=\"#tile\" x=\"0\"/><use xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
            "xlink:href=\"#tile\" x=\"20\" transform=\"scale(2)\"/>");
    EXPECT_NEAR(r.area(), 100 + 400, 1e-9);
    expect_bounds(r, 0, 0, 60, 20);
}

TEST(region_svg, NestedSvgViewport) {
    Region r =
        svg("<svg x=\"10\" y=\"10\" width=\"20\" height=\"20\" viewBox=\"0 0 10 10\">"
            "<rect width=\"10\" height=\"10\"/></svg>");
    expect_bounds(r, 10, 10, 30, 30);
}

TEST(region_svg, FromFileUsesPathAsName) {
    std::string file = std::string(ACANTHUS_SOURCE_DIR) + "/examples/panels/rectangle.svg";
    Region r = Region::from_svg_file(file);
    EXPECT_EQ(r.name(), file);
    EXPECT_GT(r.area(), 0);
    Region same = Region::from_argument(file);
    EXPECT_DOUBLE_EQ(same.area(), r.area());
}
