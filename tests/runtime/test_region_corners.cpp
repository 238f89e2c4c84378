// Corners of a panel's boundary (signal points): where they are, which way is in, their angle.
#include <gtest/gtest.h>

#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using acanthus::Corner;
using acanthus::Point;
using acanthus::Region;

namespace {

const std::string kPanels = std::string(ACANTHUS_SOURCE_DIR) + "/examples/panels/";

const Corner* at(const std::vector<Corner>& corners, Point p) {
    for (const Corner& c : corners)
        if (std::hypot(c.at.x - p.x, c.at.y - p.y) < 1e-6) return &c;
    return nullptr;
}

}  // namespace

TEST(region_corners, RectangleHasFourRightAnglesPointingIn) {
    const std::vector<Corner> corners = Region::from_spec("rect:100,60").corners();
    ASSERT_EQ(corners.size(), 4u);
    for (const Corner& c : corners) {
        EXPECT_NEAR(c.angle, M_PI / 2, 1e-9);
        EXPECT_TRUE(c.convex());
        const Point n = c.nestled(5);  // the circle of radius 5 touching both sides
        EXPECT_NEAR(std::min(n.x, 100 - n.x), 5, 1e-9);
        EXPECT_NEAR(std::min(n.y, 60 - n.y), 5, 1e-9);
    }
}

TEST(region_corners, CircleHasNone) {
    EXPECT_TRUE(Region::from_spec("circle:40").corners().empty());
}

TEST(region_corners, FrameHoleCornersAreConcave) {
    const std::vector<Corner> corners = Region::from_svg_file(kPanels + "frame.svg").corners();
    ASSERT_EQ(corners.size(), 8u);
    const Corner* outer = at(corners, {160, 160});
    const Corner* inner = at(corners, {130, 130});
    ASSERT_TRUE(outer && inner);
    EXPECT_TRUE(outer->convex());
    EXPECT_NEAR(outer->inward.angle, -3 * M_PI / 4, 1e-9);  // towards (-1, -1)
    EXPECT_FALSE(inner->convex());
    EXPECT_NEAR(inner->angle, 3 * M_PI / 2, 1e-9);
    EXPECT_NEAR(inner->inward.angle, M_PI / 4, 1e-9);  // away from the opening, to (+1, +1)
    const Point n = inner->nestled(4);
    EXPECT_NEAR(std::hypot(n.x - 130, n.y - 130), 4, 1e-9);
}

TEST(region_corners, HeartHasItsTipAndCleft) {
    const std::vector<Corner> corners = Region::from_svg_file(kPanels + "heart.svg").corners();
    const Corner* tip = at(corners, {80, 146});
    const Corner* cleft = at(corners, {80, 38});
    ASSERT_TRUE(tip && cleft);
    EXPECT_TRUE(tip->convex());
    EXPECT_NEAR(tip->angle, 2 * std::atan2(36.0, 34.0), 1e-9);  // handles (44,112), (116,112)
    EXPECT_NEAR(tip->inward.angle, -M_PI / 2, 1e-6);  // up, into the heart (y points down)
    EXPECT_FALSE(cleft->convex());
    EXPECT_NEAR(cleft->inward.angle, M_PI / 2, 1e-6);  // down
    EXPECT_EQ(corners.size(), 2u);                     // the lobes are smooth
}

TEST(region_corners, SmoothJoinsAreNoCorners) {
    // The arch's semicircle meets its straight sides tangentially.
    const std::vector<Corner> corners =
        Region::from_svg_file(kPanels + "arch-window.svg").corners();
    EXPECT_EQ(corners.size(), 4u);  // the sills' four right angles
    for (const Corner& c : corners) EXPECT_NEAR(c.at.y, c.at.y > 150 ? 200 : 115, 1e-9);
}
