// Ornament: the nearest-element searches of the growth loop against brute force, with and
// without the radius the nearest element is likely within.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <memory>
#include <vector>

#include "fixtures/dots_pattern.hpp"
#include "growth/ornament.hpp"

using acanthus::Point;
using acanthus::detail::Ornament;

TEST(Ornament, NearestWithinMatchesBruteForceWhateverTheLikelyRadius) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament ornament(region, 1e-9);
    acanthus::Random rng(41);
    std::vector<std::pair<Point, double>> dots;
    for (int k = 0; k < 300; ++k) {
        auto d = std::make_unique<dots::dot>();
        const Point c{rng.uniform(10, 190), rng.uniform(10, 190)};
        const double r = rng.uniform(0.5, 3);
        d->p0.set(c, r);
        ornament.add(std::move(d));
        dots.emplace_back(c, r);
    }
    for (int q = 0; q < 200; ++q) {
        const Point p{rng.uniform(0, 200), rng.uniform(0, 200)};
        double nearest = INFINITY;
        for (const auto& [c, r] : dots)
            nearest = std::min(nearest, std::max(0.0, std::hypot(p.x - c.x, p.y - c.y) - r));
        for (const double likely : {0.0, nearest * 0.5, nearest + 1, nearest * 3}) {
            double covered = -1;
            const auto hits = ornament.nearest_within(p, 0.5, &covered, likely);
            ASSERT_FALSE(hits.empty());
            EXPECT_NEAR(hits.front().second, nearest, 1e-9)
                << "query " << q << " likely " << likely;
            // Every element within the covered radius, nearest first.
            std::size_t within = 0;
            for (const auto& [c, r] : dots)
                within += std::max(0.0, std::hypot(p.x - c.x, p.y - c.y) - r) <= covered;
            EXPECT_EQ(hits.size(), within) << "query " << q << " likely " << likely;
            // A likely radius the nearest is within is where the search stops.
            if (likely > 0.5 && likely >= nearest) {
                EXPECT_LE(covered, likely) << "query " << q;
            }
        }
    }
}

// With a slack, the search measures no element whose bounds are farther than the nearest one
// plus the slack, and returns exactly the elements within the slack of the nearest, with the
// distances and the order the full search gives them.
TEST(Ornament, NearestWithinASlackKeepsWhatTheFullSearchHasWithinIt) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament ornament(region, 1e-9);
    acanthus::Random rng(43);
    for (int k = 0; k < 400; ++k) {
        auto d = std::make_unique<dots::dot>();
        // Coarse centres and radii: many elements tie on their distance.
        d->p0.set({std::round(rng.uniform(10, 190)), std::round(rng.uniform(10, 190))},
                  rng.uniform(0, 1) < 0.5 ? 1 : 2);
        ornament.add(std::move(d));
    }
    for (int q = 0; q < 300; ++q) {
        const Point p{std::round(rng.uniform(0, 200)), std::round(rng.uniform(0, 200))};
        const double hint = rng.uniform(0.5, 20);
        double covered_full = -1;
        const auto full = ornament.nearest_within(p, hint, &covered_full);
        ASSERT_FALSE(full.empty());
        for (const double slack : {0.0, 0.5, 2.0, 8.0}) {
            double covered = -1;
            const auto hits = ornament.nearest_within(p, hint, &covered, 0, slack);
            EXPECT_EQ(covered, covered_full) << "query " << q;
            std::vector<std::pair<int, double>> expected, got;
            for (const auto& [e, d] : full)
                if (d <= full.front().second + slack) expected.emplace_back(e->id, d);
            for (const auto& [e, d] : hits) got.emplace_back(e->id, d);
            EXPECT_EQ(got, expected) << "query " << q << " slack " << slack;
        }
        // nearest() measures with no slack: the nearest element, ties to the smaller id.
        EXPECT_EQ(ornament.nearest(p, hint).first, full.front().first) << "query " << q;
    }
}

// add_all() gives ids in order and answers the growth loop's searches as add() does.
TEST(Ornament, AddAllMatchesAddingOneByOne) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament one(region, 1e-9), all(region, 1e-9);
    acanthus::Random rng(7);
    std::vector<std::unique_ptr<acanthus::Element>> batch;
    for (int k = 0; k < 500; ++k) {
        const Point c{rng.uniform(10, 190), rng.uniform(10, 190)};
        const double r = rng.uniform(0.5, 3);
        auto a = std::make_unique<dots::dot>();
        a->p0.set(c, r);
        one.add(std::move(a));
        auto b = std::make_unique<dots::dot>();
        b->p0.set(c, r);
        if (k < 10) {
            all.add(std::move(b));  // a few first, so that the batch is packed with them
        } else {
            batch.push_back(std::move(b));
        }
    }
    const auto added = all.add_all(std::move(batch));
    ASSERT_EQ(added.size(), 490u);
    for (std::size_t k = 0; k < added.size(); ++k)
        EXPECT_EQ(added[k]->id, static_cast<int>(k + 10));
    ASSERT_EQ(all.size(), one.size());
    for (int q = 0; q < 100; ++q) {
        const Point p{rng.uniform(0, 200), rng.uniform(0, 200)};
        const auto a = one.within(p, 12), b = all.within(p, 12);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t k = 0; k < a.size(); ++k) {
            EXPECT_EQ(a[k].first->id, b[k].first->id);
            EXPECT_EQ(a[k].second, b[k].second);
        }
        dots::dot probe;
        probe.p0.set(p, 2);
        EXPECT_EQ(one.intersects(probe), all.intersects(probe));
    }
}

// add_all() hands back the bounds of the elements from `deferrable_from` on, in order, with a
// near zone or without one (the growth loop reads them for the field's test of each image).
TEST(Ornament, AddAllGivesTheBoundsOfTheDeferrableElements) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    for (const bool zoned : {false, true}) {
        Ornament ornament(region, 1e-9);
        if (zoned) {
            std::vector<bool> cells(20 * 20, false);
            for (int j = 0; j < 5; ++j)
                for (int i = 0; i < 5; ++i) cells[static_cast<std::size_t>(j * 20 + i)] = true;
            ornament.set_near_zone({0, 0}, 10, 20, cells);
        }
        acanthus::Random rng(5);
        std::vector<std::unique_ptr<acanthus::Element>> batch;
        std::vector<acanthus::Rect> expected;
        for (int k = 0; k < 50; ++k) {
            auto d = std::make_unique<dots::dot>();
            d->p0.set({rng.uniform(10, 190), rng.uniform(10, 190)}, rng.uniform(0.5, 3));
            if (k >= 20) expected.push_back(d->p0.bounds());
            batch.push_back(std::move(d));
        }
        std::vector<acanthus::Rect> bounds{{1, 2, 3, 4}};  // cleared first
        ornament.add_all(std::move(batch), 20, &bounds);
        ASSERT_EQ(bounds.size(), expected.size()) << "zoned " << zoned;
        for (std::size_t k = 0; k < bounds.size(); ++k) {
            EXPECT_EQ(bounds[k].x0, expected[k].x0) << k;
            EXPECT_EQ(bounds[k].y0, expected[k].y0) << k;
            EXPECT_EQ(bounds[k].x1, expected[k].x1) << k;
            EXPECT_EQ(bounds[k].y1, expected[k].y1) << k;
        }
    }
}

// Elements add_all() is told lie far from the near zone are deferred without the zone's test
// (one flagged inside the zone too, which only the flag defers), and a query reaching one beyond
// the zone finds it, as it finds one the zone's test deferred.
TEST(Ornament, AddAllDefersTheElementsFlaggedFar) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament ornament(region, 1e-9);
    std::vector<bool> cells(20 * 20, false);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) cells[static_cast<std::size_t>(j * 20 + i)] = true;
    ornament.set_near_zone({0, 0}, 10, 20, cells);
    const Point at[4] = {{20, 20}, {20, 25}, {150, 150}, {160, 40}};
    std::vector<std::unique_ptr<acanthus::Element>> batch;
    for (const Point p : at) {
        auto d = std::make_unique<dots::dot>();
        d->p0.set(p, 2);
        batch.push_back(std::move(d));
    }
    const std::vector<std::uint8_t> far{0, 1, 1, 0};  // in the zone, flagged in it, beyond it
    ornament.add_all(std::move(batch), 0, nullptr, &far);
    EXPECT_EQ(ornament.indexed(), 1u);  // the first alone
    EXPECT_TRUE(ornament.within({20, 20}, 1).size() == 1);
    for (const Point p : {at[2], at[3]}) {
        const auto hits = ornament.within(p, 1);
        ASSERT_EQ(hits.size(), 1u) << p.x << "," << p.y;
        EXPECT_EQ(hits[0].second, 0);
    }
    EXPECT_EQ(ornament.indexed(), 3u);
}
