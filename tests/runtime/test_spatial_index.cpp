// SpatialIndex against brute force on random boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "geometry/spatial_index.hpp"

namespace acanthus::detail {
namespace {

struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) / 9007199254740992.0;
    }
    double in(double a, double b) { return a + (b - a) * next(); }
};

struct Item {
    SpatialIndex::Entry entry;
    Rect box;
};

double box_distance(Point p, Rect r) {
    double dx = std::max({r.x0 - p.x, 0.0, p.x - r.x1});
    double dy = std::max({r.y0 - p.y, 0.0, p.y - r.y1});
    return std::hypot(dx, dy);
}

bool intersects(Rect a, Rect b) {
    return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

class SpatialIndexRandom : public ::testing::Test {
  protected:
    void SetUp() override {
        Lcg rng{17};
        for (int e = 0; e < 400; ++e) {
            int proxies = 1 + static_cast<int>(rng.next() * 3);
            for (int k = 0; k < proxies; ++k) {
                double x = rng.in(0, 100), y = rng.in(0, 100);
                Rect box{x, y, x + rng.in(0, 8), y + rng.in(0, 8)};
                // Insert in a scrambled order: results must not depend on it.
                items.push_back({{e, k}, box});
            }
        }
        std::vector<std::size_t> order(items.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = (i * 7919) % order.size();
        for (std::size_t i : order)
            index.insert(items[i].entry.element, items[i].entry.proxy, items[i].box);
    }
    std::vector<Item> items;
    SpatialIndex index;
    Point current;
};

TEST_F(SpatialIndexRandom, QueryMatchesBruteForce) {
    Lcg rng{5};
    ASSERT_EQ(index.size(), items.size());
    for (int i = 0; i < 200; ++i) {
        double x = rng.in(-10, 110), y = rng.in(-10, 110);
        Rect q{x, y, x + rng.in(0, 20), y + rng.in(0, 20)};
        std::vector<SpatialIndex::Entry> expected;
        for (const Item& it : items) {
            if (intersects(it.box, q)) expected.push_back(it.entry);
        }
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(index.query(q), expected);
    }
}

TEST_F(SpatialIndexRandom, WithinMatchesBruteForce) {
    Lcg rng{6};
    for (int i = 0; i < 200; ++i) {
        Point p{rng.in(-10, 110), rng.in(-10, 110)};
        double radius = rng.in(0, 15);
        std::vector<SpatialIndex::Entry> expected;
        for (const Item& it : items) {
            if (box_distance(p, it.box) <= radius) expected.push_back(it.entry);
        }
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(index.within(p, radius), expected);
    }
}

TEST_F(SpatialIndexRandom, NearestMatchesBruteForce) {
    Lcg rng{8};
    for (int i = 0; i < 100; ++i) {
        Point p{rng.in(-10, 110), rng.in(-10, 110)};
        std::vector<std::pair<double, SpatialIndex::Entry>> ranked;
        for (const Item& it : items) ranked.emplace_back(box_distance(p, it.box), it.entry);
        std::sort(ranked.begin(), ranked.end());
        std::vector<SpatialIndex::Entry> got = index.nearest(p, 5);
        ASSERT_EQ(got.size(), 5u);
        for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(got[k], ranked[k].second) << i << " " << k;
    }
}

TEST_F(SpatialIndexRandom, NearestEntryUsesTheExactDistance) {
    // The "exact" distance: to the box's centre, which is never less than to the box.
    auto centre_distance = [&](SpatialIndex::Entry e) {
        for (const Item& it : items) {
            if (it.entry == e) return distance(it.box.center(), current);
        }
        return static_cast<double>(INFINITY);
    };
    Lcg rng{9};
    for (int i = 0; i < 100; ++i) {
        current = {rng.in(-10, 110), rng.in(-10, 110)};
        const Item* best = nullptr;
        for (const Item& it : items) {
            double d = distance(it.box.center(), current);
            if (!best || d < distance(best->box.center(), current)) best = &it;
        }
        auto hit = index.nearest_entry(current, centre_distance);
        ASSERT_TRUE(hit.has_value());
        EXPECT_EQ(hit->entry, best->entry);
        EXPECT_DOUBLE_EQ(hit->distance, distance(best->box.center(), current));
    }
}

TEST(SpatialIndex, TiesAndFilteringAreDeterministic) {
    SpatialIndex index;
    index.insert(3, 0, {0, 0, 1, 1});
    index.insert(1, 1, {0, 0, 1, 1});
    index.insert(1, 0, {0, 0, 1, 1});
    index.insert(2, 0, {5, 5, 6, 6});
    auto all = index.query({0, 0, 1, 1});
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[0], (SpatialIndex::Entry{1, 0}));
    EXPECT_EQ(all[1], (SpatialIndex::Entry{1, 1}));
    EXPECT_EQ(all[2], (SpatialIndex::Entry{3, 0}));
    auto near = index.nearest({0.5, 0.5}, 2);
    ASSERT_EQ(near.size(), 2u);
    EXPECT_EQ(near[0], (SpatialIndex::Entry{1, 0}));
    EXPECT_EQ(near[1], (SpatialIndex::Entry{1, 1}));
    // Equal exact distances: the smallest (element, proxy) wins; filtered entries are skipped.
    auto hit = index.nearest_entry({0.5, 0.5}, [](SpatialIndex::Entry e) {
        return e.element == 1 ? static_cast<double>(INFINITY) : 10.0;
    });
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->entry, (SpatialIndex::Entry{2, 0}));
    EXPECT_EQ(hit->distance, 10.0);
    index.clear();
    EXPECT_EQ(index.size(), 0u);
    EXPECT_FALSE(index.nearest_entry({0, 0}, [](SpatialIndex::Entry) { return 0.0; }));
    EXPECT_TRUE(index.nearest({0, 0}, 3).empty());
}

TEST(SpatialIndex, RejectsBadBounds) {
    SpatialIndex index;
    EXPECT_THROW(index.insert(0, 0, {NAN, 0, 1, 1}), std::invalid_argument);
    EXPECT_THROW(index.insert(0, 0, {2, 0, 1, 1}), std::invalid_argument);
    EXPECT_EQ(index.size(), 0u);
}

// insert_all() in batches small (one at a time) and large (packed anew with what is there)
// answers every query as inserting one by one does.
TEST_F(SpatialIndexRandom, InsertAllInBatchesMatchesOneByOne) {
    SpatialIndex batched;
    std::vector<std::pair<SpatialIndex::Entry, Rect>> batch;
    std::size_t next = 0;
    for (const std::size_t size : {std::size_t{5}, std::size_t{100}, std::size_t{3}, items.size()}) {
        batch.clear();
        for (; next < items.size() && batch.size() < size; ++next)
            batch.push_back({items[next].entry, items[next].box});
        batched.insert_all(batch);
    }
    ASSERT_EQ(batched.size(), index.size());
    Lcg rng{5};
    for (int q = 0; q < 200; ++q) {
        const double x = rng.in(-5, 105), y = rng.in(-5, 105);
        const Rect box{x, y, x + rng.in(0, 20), y + rng.in(0, 20)};
        EXPECT_EQ(batched.query(box), index.query(box));
        EXPECT_EQ(batched.within({x, y}, 7), index.within({x, y}, 7));
        EXPECT_EQ(batched.nearest({x, y}, 4), index.nearest({x, y}, 4));
    }
}

TEST(SpatialIndex, InsertAllRejectsBadBoundsAndInsertsNothing) {
    SpatialIndex index;
    std::vector<std::pair<SpatialIndex::Entry, Rect>> batch;
    for (int e = 0; e < 100; ++e) batch.push_back({{e, 0}, {0.0 + e, 0, 1.0 + e, 1}});
    batch[70].second = {0, NAN, 1, 1};
    EXPECT_THROW(index.insert_all(batch), std::invalid_argument);
    EXPECT_EQ(index.size(), 0u);
}

}  // namespace
}  // namespace acanthus::detail
