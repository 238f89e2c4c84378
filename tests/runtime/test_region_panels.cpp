// Every example panel loads, has a sensible size and a usable inscribed circle; a few have
// known areas.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using acanthus::Region;

namespace {

// Arcs become cubic Béziers within 6e-9 of the radius (lib2geom 1.2.2 mishandles arcs).
constexpr double kArcArea = 1e-3;

const std::string kPanels = std::string(ACANTHUS_SOURCE_DIR) + "/examples/panels";

std::vector<std::string> panel_files() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(kPanels))
        if (entry.path().extension() == ".svg") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST(region_panels, EveryPanelLoads) {
    std::vector<std::string> files = panel_files();
    EXPECT_GE(files.size(), 10u);
    for (const std::string& file : files) {
        SCOPED_TRACE(file);
        Region r = Region::from_svg_file(file);
        double w = r.bounds().width(), h = r.bounds().height();
        EXPECT_GE(std::max(w, h), 80);
        EXPECT_LE(std::max(w, h), 320);
        EXPECT_GT(r.area(), 0.1 * w * h);
        EXPECT_LE(r.area(), w * h * (1 + 1e-9));
        acanthus::Circle c = r.largest_inscribed_circle(0.05);
        EXPECT_TRUE(r.contains(c.center));
        EXPECT_GT(c.radius, 5);
        EXPECT_NEAR(r.distance_to_boundary(c.center), c.radius, 1e-6);
        EXPECT_FALSE(r.rings(0.1).empty());
    }
}

TEST(region_panels, KnownAreas) {
    EXPECT_NEAR(Region::from_svg_file(kPanels + "/rectangle.svg").area(), 200.0 * 140, 1e-6);
    EXPECT_NEAR(Region::from_svg_file(kPanels + "/circle.svg").area(), M_PI * 80 * 80, kArcArea);
    // Frame: 160 x 160 outside, 100 x 100 opening (evenodd).
    Region frame = Region::from_svg_file(kPanels + "/frame.svg");
    EXPECT_NEAR(frame.area(), 160.0 * 160 - 100 * 100, 1e-6);
    EXPECT_FALSE(frame.contains({frame.bounds().center()}));
    Region two = Region::from_svg_file(kPanels + "/two-parts.svg");
    EXPECT_FALSE(two.contains(two.bounds().center()));
}
