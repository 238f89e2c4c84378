// ExcludeList: circle queries, removal near a point, clear.
#include <gtest/gtest.h>

#include <acanthus/random.hpp>
#include <algorithm>
#include <vector>

#include "growth/exclude_list.hpp"

using acanthus::Circle;
using acanthus::Point;
using acanthus::detail::ExcludeList;

TEST(ExcludeList, EmptyListContainsNothing) {
    ExcludeList list;
    EXPECT_EQ(list.size(), 0u);
    EXPECT_FALSE(list.any_inside(Circle{{0, 0}, 100}));
    EXPECT_EQ(list.find_inside(Circle{{0, 0}, 100}), -1);
}

TEST(ExcludeList, PointInsideIsFoundStrictly) {
    ExcludeList list;
    const int a = list.add({10, 10});
    EXPECT_EQ(a, 0);
    EXPECT_EQ(list.find_inside(Circle{{10, 10}, 0.5}), a);  // the centre itself
    EXPECT_EQ(list.find_inside(Circle{{13, 14}, 5.0001}), a);
    EXPECT_EQ(list.find_inside(Circle{{13, 14}, 5.0}), -1);  // on the circle is not inside
    EXPECT_FALSE(list.any_inside(Circle{{30, 30}, 5}));
    EXPECT_FALSE(list.any_inside(Circle{{10, 10}, 0}));  // a circle with no radius holds nothing
}

TEST(ExcludeList, RemoveWithinEpsilonRemovesOnlyNearPoints) {
    ExcludeList list;
    const int a = list.add({0, 0});
    const int b = list.add({1, 0});
    const int c = list.add({3, 0});
    std::vector<int> removed;
    list.remove_within({0, 0}, 1.0, &removed);  // distance <= epsilon
    std::sort(removed.begin(), removed.end());
    EXPECT_EQ(removed, (std::vector<int>{a, b}));
    EXPECT_EQ(list.size(), 1u);
    EXPECT_EQ(list.find_inside(Circle{{0, 0}, 10}), c);
    EXPECT_EQ(list.points(), (std::vector<Point>{{3, 0}}));
    // Ids are never reused.
    EXPECT_EQ(list.add({0, 0}), 3);
}

TEST(ExcludeList, ClearEmptiesAndCounts) {
    ExcludeList list;
    list.add({1, 1});
    list.add({2, 2});
    EXPECT_EQ(list.clear_count(), 0);
    list.clear();
    EXPECT_EQ(list.size(), 0u);
    EXPECT_EQ(list.clear_count(), 1);
    EXPECT_FALSE(list.any_inside(Circle{{0, 0}, 100}));
}

TEST(ExcludeList, MatchesBruteForceOnRandomPoints) {
    acanthus::Random rng(5);
    ExcludeList list;
    std::vector<std::pair<int, Point>> alive;
    for (int step = 0; step < 2000; ++step) {
        const Point p{rng.uniform(0, 100), rng.uniform(0, 100)};
        if (rng.chance(0.7)) {
            alive.emplace_back(list.add(p), p);
        } else {
            const double eps = rng.uniform(0, 8);
            std::vector<int> removed;
            list.remove_within(p, eps, &removed);
            std::vector<int> expected;
            for (const auto& [id, q] : alive)
                if (acanthus::distance(p, q) <= eps) expected.push_back(id);
            std::erase_if(alive,
                          [&](const auto& x) { return acanthus::distance(p, x.second) <= eps; });
            std::sort(removed.begin(), removed.end());
            ASSERT_EQ(removed, expected);
        }
        const Circle c{{rng.uniform(0, 100), rng.uniform(0, 100)}, rng.uniform(0, 10)};
        const bool expected = std::any_of(alive.begin(), alive.end(), [&](const auto& x) {
            return acanthus::distance(x.second, c.center) < c.radius;
        });
        const int id = list.find_inside(c);
        ASSERT_EQ(id >= 0, expected);
        if (id >= 0) {
            const auto it = std::find_if(alive.begin(), alive.end(),
                                         [&](const auto& x) { return x.first == id; });
            ASSERT_NE(it, alive.end());
            ASSERT_LT(acanthus::distance(it->second, c.center), c.radius);
        }
        ASSERT_EQ(list.size(), alive.size());
    }
}
