// Images under symmetry, placed cheaply: the ornament's near zone (elements far from it are
// indexed only when a query reaches beyond it) answers every query as an ornament indexing
// everything; an image carried over by another transformation in place is the image built anew.
#include <gtest/gtest.h>

#include <acanthus/growth.hpp>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <cmath>
#include <memory>
#include <vector>

#include "fixtures/dots_pattern.hpp"
#include "fixtures/growth_tree.hpp"
#include "growth/ornament.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/orbit.hpp"

using acanthus::Point;
using acanthus::Rect;
using acanthus::detail::ImageElement;
using acanthus::detail::Isometry;
using acanthus::detail::Ornament;

namespace {

std::unique_ptr<acanthus::Element> dot(Point c, double r) {
    auto d = std::make_unique<dots::dot>();
    d->p0.set(c, r);
    return d;
}

// Ids and distances of a query's answer, comparable across two ornaments.
std::vector<std::pair<int, double>> ids(
    const std::vector<std::pair<acanthus::Element*, double>>& v) {
    std::vector<std::pair<int, double>> out;
    for (const auto& [e, d] : v) out.emplace_back(e->id, d);
    return out;
}

}  // namespace

// The zone: cells of 10 x 10 over [0, 200]^2 (a margin of two cells round it), the cells with
// x < 60 in it. Batches of dots go in all over the square, the first of each batch never deferred
// (as a fundamental element), the others deferred when they miss the zone; queries inside the
// zone and beyond it, between the batches, answer as the ornament without a zone does.
TEST(OrnamentNearZone, AnswersEveryQueryAsAnOrnamentIndexingEverything) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament zoned(region, 1e-9), plain(region, 1e-9);
    const int columns = 24, rows = 24;  // 20 cells and 2 on each side
    std::vector<bool> cells(static_cast<std::size_t>(columns * rows), false);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < 8; ++i) cells[static_cast<std::size_t>(j * columns + i)] = true;
    zoned.set_near_zone({-20, -20}, 10, columns, cells);
    acanthus::Random rng(31);
    int inside_queries = 0, beyond_queries = 0;
    for (int batch = 0; batch < 60; ++batch) {
        std::vector<std::unique_ptr<acanthus::Element>> a, b;
        for (int k = 0; k < 8; ++k) {
            const Point c{rng.uniform(2, 198), rng.uniform(2, 198)};
            const double r = rng.uniform(0.3, 2);
            a.push_back(dot(c, r));
            b.push_back(dot(c, r));
        }
        zoned.add_all(std::move(a), 1);
        plain.add_all(std::move(b));
        ASSERT_EQ(zoned.size(), plain.size());
        for (int q = 0; q < 6; ++q) {
            // Mostly within the zone (x < 40 and a radius under 10), now and then beyond it.
            const bool beyond = q == 5 && batch % 4 == 0;
            const Point p{rng.uniform(0, beyond ? 200 : 35), rng.uniform(0, 200)};
            const double radius = rng.uniform(0.5, beyond ? 60 : 4);
            (beyond ? beyond_queries : inside_queries)++;
            EXPECT_EQ(ids(zoned.within(p, radius)), ids(plain.within(p, radius)))
                << "batch " << batch << " query " << q;
            double covered_z = -1, covered_p = -1;
            EXPECT_EQ(ids(zoned.nearest_within(p, radius, &covered_z, radius * 2)),
                      ids(plain.nearest_within(p, radius, &covered_p, radius * 2)));
            EXPECT_EQ(covered_z, covered_p);
            dots::dot probe;
            probe.p0.set(p, radius);
            EXPECT_EQ(zoned.intersects(probe.p0), plain.intersects(probe.p0))
                << "batch " << batch << " query " << q;
            auto even = [](const acanthus::Element& e) { return e.id % 2 == 0; };
            EXPECT_EQ(zoned.overlaps_any(probe.p0, even), plain.overlaps_any(probe.p0, even));
        }
    }
    EXPECT_GT(inside_queries, 200);
    EXPECT_GT(beyond_queries, 10);
}

// Elements partly beyond the grid of cells, and an element larger than the zone: a query
// reaching them finds them.
TEST(OrnamentNearZone, FindsElementsBeyondTheCellsAndAroundTheZone) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament ornament(region, 1e-9);
    const int columns = 24, rows = 24;
    std::vector<bool> cells(static_cast<std::size_t>(columns * rows), false);
    cells[static_cast<std::size_t>(12 * columns + 12)] = true;  // the cell [100, 110]^2
    ornament.set_near_zone({-20, -20}, 10, columns, cells);
    std::vector<std::unique_ptr<acanthus::Element>> batch;
    batch.push_back(dot({105, 105}, 1));   // fundamental: never deferred
    batch.push_back(dot({-500, 90}, 3));   // far beyond the cells
    batch.push_back(dot({100, 100}, 90));  // round the zone
    batch.push_back(dot({150, 150}, 1));   // beside it
    ornament.add_all(std::move(batch), 1);
    // Within the zone: the fundamental dot and the disc round the zone.
    const auto near = ornament.within({105, 105}, 2);
    ASSERT_EQ(near.size(), 2u);
    EXPECT_EQ(near[0].first->id + near[1].first->id, 2);
    dots::dot probe;
    probe.p0.set({102, 102}, 0.5);
    EXPECT_TRUE(
        ornament.overlaps_any(probe.p0, [](const acanthus::Element& e) { return e.id == 2; }));
    EXPECT_FALSE(
        ornament.overlaps_any(probe.p0, [](const acanthus::Element& e) { return e.id != 2; }));
    // Beyond it.
    const auto far = ornament.within({-500, 90}, 4);
    ASSERT_EQ(far.size(), 1u);
    EXPECT_EQ(far.front().first->id, 1);
    EXPECT_EQ(ornament.within({150, 150}, 1.5).size(), 2u);  // the dot and the large one
    EXPECT_EQ(ornament.nearest({-600, 90}).first->id, 1);
}

// An image carried over by another transformation in place is the image built anew under it,
// for the point, circle, segment and polygon proxies.
TEST(ImageElement, SetTransformIsTheImageBuiltAnew) {
    struct Shapes : acanthus::Element {
        acanthus::PointProxy a;
        acanthus::CircleProxy b;
        acanthus::LineSegmentProxy c;
        acanthus::PolygonProxy d;
        const acanthus::ElementType& type() const override { return dots::dot().type(); }
        std::size_t proxy_count() const override { return 4; }
        acanthus::Proxy& proxy(std::size_t k) override {
            acanthus::Proxy* all[] = {&a, &b, &c, &d};
            return *all[k];
        }
    } e;
    e.a.set({3, 4});
    e.b.set({10, 2}, 1.5);
    e.c.set({0, 0}, {5, 7});
    e.d.set({{1, 1}, {4, 1}, {2, 5}});
    const Isometry rot = Isometry::rotation({50, 50}, 0.7);
    const Isometry mirror = Isometry::reflection({50, 0}, M_PI / 2);
    ImageElement moved(e, rot);
    moved.set_transform(mirror);
    const ImageElement fresh(e, mirror);
    EXPECT_TRUE(acanthus::detail::same_place(moved, fresh, 1e-12));
    EXPECT_FALSE(acanthus::detail::same_place(moved, ImageElement(e, rot), 1e-6));
    EXPECT_TRUE(acanthus::detail::same_isometry(moved.transform(), mirror, 1e-12));
}

// The incremental engine leaves out of the buffer the images that could lower no distance kept
// near the domain, and indexes far images only when a query reaches them; the reference engine
// draws every image into the buffer and measures every pixel. Both grow the same tree, under
// narrow and wide wedges, in a panel the group maps onto itself and in one it does not.
TEST(SymmetricGrowth, ImagesLeftOutOfTheBufferGrowTheReferenceOrnament) {
    struct Case {
        const char* region;
        const char* group;
    };
    for (const Case& c :
         {Case{"circle:60", "d8"}, Case{"circle:60", "d12"}, Case{"circle:60", "c6"},
          Case{"rect:120,90", "d2"}, Case{"rect:120,90", "c4"}}) {
        const acanthus::Region region = acanthus::Region::from_spec(c.region);
        acanthus::GrowthOptions o;
        o.resolution = 448;
        o.lazy_field_pixels = 0;  // lazy at any size
        o.symmetry = acanthus::Symmetry::parse(c.group);
        const auto fast = acanthus::test::grow(::dots::pattern(), region, o);
        EXPECT_GT(fast.size(), 300u) << c.region << " " << c.group;
        o.reference_engine = true;
        EXPECT_EQ(acanthus::test::grow(::dots::pattern(), region, o), fast)
            << c.region << " " << c.group;
    }
}
