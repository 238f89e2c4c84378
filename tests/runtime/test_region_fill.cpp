// Shapes combined as a renderer fills them (region_fill, region_trace): the union and fill rules
// decided by Clipper, the boundary handed back as exact curves, checked against closed forms.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <string>

#include "region/build.hpp"
#include "region/region_data.hpp"

using acanthus::Point;
using acanthus::Region;

namespace {

Region svg(const std::string& body) {
    return Region::from_svg_string("<svg xmlns=\"http://www.w3.org/2000/svg\">" + body + "</svg>",
                                   "inline.svg");
}

// Area of the union of two discs of radius r whose centres are d apart (0 < d < 2r).
double two_discs(double r, double d) {
    const double lens = 2 * r * r * std::acos(d / (2 * r)) - d / 2 * std::sqrt(4 * r * r - d * d);
    return 2 * M_PI * r * r - lens;
}

// Arcs are held as cubics within 6e-9 of the radius, so a disc's area is good to ~1e-8.
constexpr double kCurveArea = 1e-7;

}  // namespace

TEST(RegionFill, OverlappingDiscsKeepExactCurves) {
    // Chords are within 1e-6 of the size; an area this close shows the curves are exact.
    const Region r = svg("<circle cx='0' cy='0' r='10'/><circle cx='12' cy='0' r='10'/>");
    EXPECT_NEAR(r.area(), two_discs(10, 12), kCurveArea * r.area());
    EXPECT_EQ(r.parts().size(), 1u);
    // The crossings are exact (up to the cubics standing for the arcs): through (6, ±8).
    EXPECT_NEAR(r.distance_to_boundary(Point{6, 8}), 0, 1e-7);
    EXPECT_NEAR(r.distance_to_boundary(Point{6, -8}), 0, 1e-7);
    EXPECT_TRUE(r.contains(Point{6, 0}));
    EXPECT_FALSE(r.contains(Point{6, 8.01}));
}

TEST(RegionFill, CircleAndRectOverlapCountedOnce) {
    const Region r = svg("<circle cx='5' cy='5' r='3'/><rect x='5' y='5' width='4' height='4'/>");
    EXPECT_NEAR(r.area(), 9 * M_PI + 16 - 9 * M_PI / 4, kCurveArea * r.area());
}

TEST(RegionFill, CircleInscribedInSquareIsTheSquare) {
    const Region r = svg("<rect width='10' height='10'/><circle cx='5' cy='5' r='5'/>");
    EXPECT_NEAR(r.area(), 100, 1e-9);
}

TEST(RegionFill, DuplicatesCountOnce) {
    EXPECT_NEAR(svg("<rect width='10' height='10'/><rect width='10' height='10'/>").area(), 100,
                1e-9);
    EXPECT_NEAR(svg("<circle cx='5' cy='5' r='5'/><circle cx='5' cy='5' r='5'/>").area(), 25 * M_PI,
                kCurveArea * 25 * M_PI);
}

TEST(RegionFill, TrianglesTouchingAtAVertexAreTwoParts) {
    const Region r = svg("<path d='M0,0 L10,0 L5,10Z'/><path d='M10,0 L20,0 L15,-10Z'/>");
    EXPECT_NEAR(r.area(), 100, 1e-9);
    EXPECT_EQ(r.parts().size(), 2u);
    EXPECT_TRUE(r.contains(Point{5, 3}));
    EXPECT_TRUE(r.contains(Point{15, -3}));
}

TEST(RegionFill, SharedEdgeLeavesNoSeam) {
    const Region r = svg("<rect width='4' height='7'/><rect x='4' y='1' width='3' height='5'/>");
    EXPECT_NEAR(r.area(), 43, 1e-9);
    // No boundary runs along the shared stretch of x = 4.
    EXPECT_GT(r.distance_to_boundary(Point{4, 3.5}), 0.99);
}

TEST(RegionFill, CubicClosedByItsChord) {
    const Region r = svg("<path d='M0,0 C-14.5,-6.44 -21.05,-23.53 -14.6,-38.04 Z'/>");
    // The area rsvg paints (236.64); chords through the curve would give far less.
    EXPECT_NEAR(r.area(), 236.638050, 1e-5);
}

TEST(RegionFill, EvenOddSelfOverlapIsAHole) {
    // A square and a diamond in one evenodd path: their overlap (a triangle of area 25) is empty.
    const Region r =
        svg("<path fill-rule='evenodd' d='M0,0 L10,0 L10,10 L0,10 Z M10,0 L20,5 L10,10 L5,5 Z'/>");
    EXPECT_NEAR(r.area(), 100 + 75 - 2 * 25, 1e-9);
    EXPECT_FALSE(r.contains(Point{9, 5}));
    EXPECT_TRUE(r.contains(Point{12, 5}));
}

TEST(RegionFill, SimplePanelKeepsItsOwnBoundary) {
    // A loop that is a whole input subpath comes back as that subpath, start point and all.
    const Region r = svg("<path d='M 10,0 L 30,0 C 40,10 40,30 30,40 L 10,40 Z'/>");
    EXPECT_EQ(r.path_data().substr(0, 9), "M 10 0 H ");
}

TEST(RegionFill, OpenFilledPathIsClosed) {
    EXPECT_NEAR(svg("<path d='M0,0 L10,0 L10,10'/>").area(), 50, 1e-9);
}

TEST(RegionFill, CoordinatesOutOfRangeAreRefusedNamingTheElement) {
    try {
        svg("<rect id='big' width='1e300' height='1e300'/>");
        FAIL() << "expected an InputError";
    } catch (const acanthus::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("coordinates out of range"), std::string::npos) << what;
        EXPECT_NE(what.find("big"), std::string::npos) << what;
    }
    EXPECT_THROW(Region::from_spec("rect:1e300,1e300"), acanthus::InputError);
}

TEST(RegionFill, ManyCurvesUseTheIndex) {
    // 500 small arcs along one edge: queries go through the boundary index and agree with
    // the geometry (each bump is a half disc of radius 0.5 dipping below y = 0).
    std::string d = "M0,0";
    for (int i = 0; i < 500; ++i) d += " a0.5,0.5 0 0 0 1,0";
    d += " L500,100 L0,100 Z";
    const Region r = svg("<path d='" + d + "'/>");
    EXPECT_NEAR(r.area(), 500 * 100 - 500 * M_PI / 8, 1e-6 * r.area());
    EXPECT_FALSE(r.contains(Point{0.5, 0.3}));
    EXPECT_TRUE(r.contains(Point{0.5, 0.6}));
    EXPECT_NEAR(r.distance_to_boundary(Point{250.5, 1.5}), 1.0, 1e-9);
    // A long plateau of equal radii: a coarse tolerance keeps the search short.
    EXPECT_NEAR(r.largest_inscribed_circle(0.1).radius, 49.75, 0.1);
}
