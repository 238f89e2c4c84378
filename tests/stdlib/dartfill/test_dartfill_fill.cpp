// dartfill placement methods: no overlaps, inside the panel, deterministic, and the fill-gap
// candidate distribution.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/dartfill.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "candidate_sampler.hpp"
#include "container.hpp"
#include "dartfill_oracle.hpp"
#include "gap_field.hpp"
#include "layout.hpp"
#include "methods.hpp"
#include "shape_list.hpp"

using namespace acanthus;
using namespace acanthus::dartfill;

namespace {

ShapeSet test_shapes() {
    ShapeSet set;
    std::vector<Point> star;
    for (int k = 0; k < 10; ++k) {
        double r = k % 2 ? 3 : 8;
        star.push_back({r * std::cos(M_PI * k / 5), r * std::sin(M_PI * k / 5)});
    }
    set.add_points("star", star);
    set.add_points("c", {{0, 0}, {12, 0}, {12, 3}, {3, 3}, {3, 9}, {12, 9}, {12, 12}, {0, 12}});
    set.add_path("leaf", "M 0 0 C 5 -7 15 -7 20 0 C 15 7 5 7 0 0 Z");
    return set;
}

// A 160 x 120 panel with a triangular hole: containment must respect a concave boundary.
Region holed_panel() {
    return Region::from_svg_string(
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="160" height="120">
  <path fill-rule="evenodd" d="M 0 0 H 160 V 120 H 0 Z M 50 30 L 110 40 L 70 90 Z"/></svg>)",
        "holed");
}

Options quick(Method method) {
    Options o;
    o.method = method;
    o.naive_cancellations = 400;
    o.resolution = 256;
    return o;
}

// Every placement lies in the region and shares no area with another (independent checks).
void expect_valid(const FillResult& r, const Region& region) {
    const double touch = 1e-6;
    for (std::size_t i = 0; i < r.placements.size(); ++i) {
        const auto& outline = r.placements[i].outline;
        for (Point v : outline)
            ASSERT_TRUE(region.contains(v) || region.distance_to_boundary(v) < touch)
                << "placement " << i << " vertex (" << v.x << ", " << v.y << ") is outside";
        Rect b = dartfill_oracle::ring_bounds(outline);
        for (int j = 0; j < 12; ++j)
            for (int k = 0; k < 12; ++k) {
                Point p{b.x0 + (k + 0.5) / 12 * b.width(), b.y0 + (j + 0.5) / 12 * b.height()};
                if (dartfill_oracle::in_ring(outline, p)) {
                    ASSERT_TRUE(region.contains(p) || region.distance_to_boundary(p) < touch)
                        << "placement " << i << " covers outside point (" << p.x << ", " << p.y
                        << ")";
                }
            }
    }
    for (std::size_t i = 0; i < r.placements.size(); ++i) {
        Rect bi = dartfill_oracle::ring_bounds(r.placements[i].outline);
        for (std::size_t j = i + 1; j < r.placements.size(); ++j) {
            Rect bj = dartfill_oracle::ring_bounds(r.placements[j].outline);
            if (bi.x1 < bj.x0 || bj.x1 < bi.x0 || bi.y1 < bj.y0 || bj.y1 < bi.y0) continue;
            double shared = dartfill_oracle::intersection_area(r.placements[i].outline,
                                                               r.placements[j].outline);
            ASSERT_LT(shared, 1e-6) << "placements " << i << " and " << j << " overlap";
        }
    }
}

}  // namespace

class DartfillMethod : public ::testing::TestWithParam<Method> {};

TEST_P(DartfillMethod, PlacesWithoutOverlapInsideAHoledPanel) {
    Region region = holed_panel();
    Options o = quick(GetParam());
    o.scale_min = 0.4;
    o.scale_max = 1.0;
    FillResult r = fill(test_shapes(), region, o, 11);
    EXPECT_GT(r.placements.size(), 40u);
    expect_valid(r, region);
    // Shapes are cycled: counts differ by at most one.
    int count[3] = {0, 0, 0};
    for (const auto& p : r.placements) count[p.shape]++;
    EXPECT_LE(std::max({count[0], count[1], count[2]}) - std::min({count[0], count[1], count[2]}),
              1);
    EXPECT_GT(r.stats.coverage, 0.2);
    EXPECT_LT(r.stats.coverage, 1.0);
    EXPECT_NEAR(r.stats.space_area, 160 * 120 - 0.5 * std::abs(60 * 60 - 10 * 20), 1e-6);
}

TEST_P(DartfillMethod, SameSeedSameLayoutOtherSeedAnother) {
    Region region = Region::from_spec("rect:120,90");
    Options o = quick(GetParam());
    FillResult a = fill(test_shapes(), region, o, 5);
    FillResult b = fill(test_shapes(), region, o, 5);
    FillResult c = fill(test_shapes(), region, o, 6);
    ASSERT_EQ(a.placements.size(), b.placements.size());
    for (std::size_t i = 0; i < a.placements.size(); ++i) {
        EXPECT_EQ(a.placements[i].position, b.placements[i].position);
        EXPECT_EQ(a.placements[i].rotation, b.placements[i].rotation);
        EXPECT_EQ(a.placements[i].outline, b.placements[i].outline);
    }
    ASSERT_FALSE(c.placements.empty());
    EXPECT_NE(a.placements.front().position, c.placements.front().position);
}

TEST_P(DartfillMethod, StopsAtMaxElements) {
    Options o = quick(GetParam());
    o.max_elements = 7;
    FillResult r = fill(test_shapes(), Region::from_spec("rect:120,90"), o, 3);
    EXPECT_EQ(r.placements.size(), 7u);
}

INSTANTIATE_TEST_SUITE_P(All, DartfillMethod,
                         ::testing::Values(Method::naive, Method::fill_gap, Method::medial),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(DartfillFill, GapMethodsReachTheNaiveCount) {
    Region region = Region::from_spec("rect:150,150");
    Options o;
    o.resolution = 256;
    std::size_t naive = 0, gap = 0, medial = 0;
    for (std::uint64_t seed : {21, 22, 23}) {
        o.method = Method::naive;
        naive += fill(test_shapes(), region, o, seed).placements.size();
        o.method = Method::fill_gap;
        gap += fill(test_shapes(), region, o, seed).placements.size();
        o.method = Method::medial;
        medial += fill(test_shapes(), region, o, seed).placements.size();
    }
    // Table 1 of the paper: the fill-gap method places about as many shapes as naive dart
    // throwing stopped after 10,000 consecutive cancellations (bench/dartfill.cpp measures it).
    EXPECT_GE(gap, naive * 90 / 100) << "naive " << naive << ", fill-gap " << gap;
    EXPECT_GE(medial, naive * 95 / 100) << "naive " << naive << ", medial " << medial;
    std::printf("naive %zu, fill-gap %zu, medial %zu\n", naive, gap, medial);
}

TEST(DartfillFill, CandidatesFavourLargeDistances) {
    ShapeSet shapes = test_shapes();
    RingContainer panel({{{0, 0}, {200, 0}, {200, 200}, {0, 200}}}, false);
    Layout layout(1e-6);
    // A few shapes leave gaps of many sizes.
    const auto& list = shapes.list().shapes;
    for (Point p : {Point{40, 40}, Point{150, 60}, Point{90, 150}, Point{170, 170}, Point{30, 160}})
        layout.add(PlacedShape(list[0], 0, {p, 0.3, 1.5}));
    GapField gaps(panel, layout, 200);
    CandidateSampler sampler(gaps);
    double max = std::sqrt(static_cast<double>(gaps.max_squared_distance()));
    ASSERT_GT(max, 10);
    EXPECT_EQ(sampler.max_squared_distance(), gaps.max_squared_distance());

    auto mean_distance = [&](double exponent, double& far_fraction) {
        Random random(9);
        std::vector<int> q;
        sampler.draw_q(exponent, random, q);
        EXPECT_FALSE(q.empty());
        double sum = 0;
        int far = 0;
        for (int i : q) {
            double d = std::sqrt(static_cast<double>(gaps.squared_distance(i))) / max;
            sum += d;
            far += d > 0.5;
        }
        far_fraction = static_cast<double>(far) / q.size();
        return sum / q.size();
    };
    double far16 = 0, far0 = 0;
    double mean16 = mean_distance(16, far16);
    double mean0 = mean_distance(0, far0);
    EXPECT_GT(mean16, 0.8);
    EXPECT_GT(far16, 0.99);
    EXPECT_LT(mean0, 0.6);  // n = 0 takes every free pixel
    EXPECT_GT(mean16, mean0 + 0.3);
}

TEST(DartfillFill, BadOptionsAreRefused) {
    Region region = Region::from_spec("rect:50,50");
    Options o;
    o.scale_min = 0;
    EXPECT_THROW(fill(test_shapes(), region, o, 1), InputError);
    o = Options{};
    o.scale_min = 2;
    o.scale_max = 1;
    EXPECT_THROW(fill(test_shapes(), region, o, 1), InputError);
    o = Options{};
    o.candidates = 0;
    EXPECT_THROW(fill(test_shapes(), region, o, 1), InputError);
    EXPECT_THROW(fill(ShapeSet{}, region, Options{}, 1), InputError);
    EXPECT_THROW(parse_method("darts"), InputError);
    EXPECT_EQ(parse_method("fill-gap"), Method::fill_gap);
}

TEST(DartfillFill, OutsideARuleBodyTheEnvironmentFillRefuses) {
    EXPECT_THROW(fill(test_shapes(), Options{}), std::logic_error);
}
