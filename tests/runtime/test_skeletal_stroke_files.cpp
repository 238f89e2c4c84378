// User skeletal strokes from SVG path data and SVG files: the bounding box mapped to the stroke
// frame, transforms, defs, the fill rule, and bad data or files named in the error.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <string>

#include "fixtures/alpha_coverage.hpp"
#include "fixtures/proxy_factory.hpp"
#include "fixtures/temp_dir.hpp"

namespace {
using namespace acanthus;
using namespace acanthus::test;

template <typename F>
std::string input_error_message(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

TEST(SkeletalStroke, UserStrokeFromPathDataMapsBoundingBoxToFrame) {
    // A wedge pointing along the skeleton, in arbitrary units.
    SkeletalStroke wedge = SkeletalStroke::from_svg_path("M 5,5 L 105,55 L 5,105 Z", "wedge");
    EXPECT_EQ(wedge.name(), "wedge");
    Coverage c(300, 100, [&](Canvas& canvas) {
        wedge.draw(canvas, segment_proxy({50, 50}, {250, 50}), 40);
    });
    Rect b = c.bounds(8);
    EXPECT_NEAR(b.x0, 50, 1.5);
    EXPECT_NEAR(b.x1 + 1, 250, 2);
    EXPECT_NEAR(b.y0, 30, 1);
    EXPECT_NEAR(b.y1 + 1, 70, 1);
    EXPECT_NEAR(c.column(60), 38, 1.5);
    EXPECT_NEAR(c.column(200), 10, 1.5);
}

TEST(SkeletalStroke, UserStrokeFromFileAppliesTransformsAndSkipsDefs) {
    TempDir dir("stroke");
    auto path = dir.write("wedge.svg",
                          "<svg xmlns='http://www.w3.org/2000/svg'>\n"
                          "<defs><path d='M 0,0 H 1000 V 1000 Z'/></defs>\n"
                          "<g transform='translate(100,0) scale(2)'>\n"
                          "  <path d='M 0,0 L 10,5 L 0,10 Z'/>\n"
                          "</g></svg>\n");
    SkeletalStroke file = SkeletalStroke::from_svg_file(path.string());
    SkeletalStroke data = SkeletalStroke::from_svg_path("M 0,0 L 10,5 L 0,10 Z", "same");
    EXPECT_EQ(file.name(), path.string());
    auto draw = [](const SkeletalStroke& s) {
        return Coverage(300, 100, [&](Canvas& canvas) {
            s.draw(canvas, segment_proxy({50, 50}, {250, 50}), 40);
        });
    };
    Coverage a = draw(file), b = draw(data);
    EXPECT_GT(a.count(), 0.4 * 200 * 40);
    EXPECT_NEAR(a.count(), b.count(), 4);
}

TEST(SkeletalStroke, UserStrokeFileHonoursEvenOddFillRule) {
    TempDir dir("stroke");
    const char* ring = "M 0,0 H 10 V 10 H 0 Z M 3,3 H 7 V 7 H 3 Z";
    auto evenodd = dir.write("ring.svg", std::string("<svg xmlns='http://www.w3.org/2000/svg'>"
                                                     "<path style='fill-rule:evenodd' d='") +
                                             ring + "'/></svg>");
    auto nonzero = dir.write("ring2.svg", std::string("<svg xmlns='http://www.w3.org/2000/svg'>"
                                                      "<path d='") +
                                              ring + "'/></svg>");
    auto centre_covered = [](const SkeletalStroke& s) {
        Coverage c(300, 100, [&](Canvas& canvas) {
            s.draw(canvas, segment_proxy({50, 50}, {250, 50}), 60);
        });
        return c.covered(150, 50);
    };
    EXPECT_FALSE(centre_covered(SkeletalStroke::from_svg_file(evenodd.string())));
    EXPECT_TRUE(centre_covered(SkeletalStroke::from_svg_file(nonzero.string())));
}

TEST(SkeletalStroke, BadPathDataIsInputErrorNamingTheStroke) {
    auto m = input_error_message([] { SkeletalStroke::from_svg_path("M 0,0 L 5 Q", "mystroke"); });
    EXPECT_NE(m.find("mystroke"), std::string::npos) << m;
    m = input_error_message([] { SkeletalStroke::from_svg_path("", "empty"); });
    EXPECT_NE(m.find("empty: no path data"), std::string::npos) << m;
    m = input_error_message([] { SkeletalStroke::from_svg_path("M 0,0 L 10,0", "flat"); });
    EXPECT_NE(m.find("flat: the stroke shape has no area"), std::string::npos) << m;
    m = input_error_message(
        [] { SkeletalStroke::from_svg_path("M 0,0 L 1e999,5 L 0,5 Z", "huge"); });
    EXPECT_NE(m.find("huge"), std::string::npos) << m;
}

TEST(SkeletalStroke, BadStrokeFilesAreInputErrorsNamingTheFile) {
    TempDir dir("stroke");
    auto m = input_error_message([] { SkeletalStroke::from_svg_file("/nonexistent/stroke.svg"); });
    EXPECT_NE(m.find("/nonexistent/stroke.svg"), std::string::npos) << m;

    auto nopath = dir.write("nopath.svg", "<svg xmlns='http://www.w3.org/2000/svg'><rect/></svg>");
    m = input_error_message([&] { SkeletalStroke::from_svg_file(nopath.string()); });
    EXPECT_NE(m.find(nopath.string() + ": no path element"), std::string::npos) << m;

    auto broken = dir.write("broken.svg", "<svg>\n<path d='M 0 0'\n</svg>");
    m = input_error_message([&] { SkeletalStroke::from_svg_file(broken.string()); });
    EXPECT_NE(m.find(broken.string()), std::string::npos) << m;

    auto notsvg = dir.write("notsvg.svg", "<html/>");
    m = input_error_message([&] { SkeletalStroke::from_svg_file(notsvg.string()); });
    EXPECT_NE(m.find("not an SVG file"), std::string::npos) << m;

    auto baddata = dir.write("baddata.svg", "<svg>\n\n<path d='M 0 0 L x'/></svg>");
    m = input_error_message([&] { SkeletalStroke::from_svg_file(baddata.string()); });
    EXPECT_NE(m.find(baddata.string() + ": <path> (line 3): bad path data"), std::string::npos)
        << m;

    auto badtransform =
        dir.write("badtransform.svg", "<svg><path transform='spin(3)' d='M0,0 H1 V1 Z'/></svg>");
    m = input_error_message([&] { SkeletalStroke::from_svg_file(badtransform.string()); });
    EXPECT_NE(m.find("bad transform"), std::string::npos) << m;
}

}  // namespace
