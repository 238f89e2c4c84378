// Images under symmetry, placed cheaply: the ornament's near zone (elements far from it are
// indexed only when a query reaches beyond it) answers every query as an ornament indexing
// everything; an image carried over by another transformation in place is the image built anew.
#include <gtest/gtest.h>

#include <acanthus/growth.hpp>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "fixtures/dots_pattern.hpp"
#include "fixtures/growth_tree.hpp"
#include "growth/ornament.hpp"
#include "proxy/overlap.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/orbit.hpp"
#include "symmetry/symmetric_core.hpp"
#include "symmetry/translation_groups.hpp"

using acanthus::Point;
using acanthus::Rect;
using acanthus::detail::as_image;
using acanthus::detail::ImageElement;
using acanthus::detail::Isometry;
using acanthus::detail::original_of;
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

// Cells of 10 x 10 over [0, 200]^2 and two round it; those with x < 60 make the zone.
void set_zone_left_of_60(Ornament& ornament) {
    const int columns = 24, rows = 24;  // 20 cells and 2 on each side
    std::vector<bool> cells(static_cast<std::size_t>(columns * rows), false);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < 8; ++i) cells[static_cast<std::size_t>(j * columns + i)] = true;
    ornament.set_near_zone({-20, -20}, 10, columns, cells);
}

// `count` random dots in [2, 198]^2 of radius 0.3 to `largest`, the same in both ornaments: in
// `zoned` the first fundamental (never deferred), the others images.
void add_dots(Ornament& zoned, Ornament& plain, acanthus::Random& rng, int count, double largest) {
    std::vector<std::unique_ptr<acanthus::Element>> a, b;
    for (int k = 0; k < count; ++k) {
        const Point c{rng.uniform(2, 198), rng.uniform(2, 198)};
        const double r = rng.uniform(0.3, largest);
        a.push_back(dot(c, r));
        b.push_back(dot(c, r));
    }
    zoned.add_all(std::move(a), 1);
    plain.add_all(std::move(b));
}

}  // namespace

// The zone: cells of 10 x 10 over [0, 200]^2 (a margin of two cells round it), the cells with
// x < 60 in it. Batches of dots go in all over the square, the first of each batch never deferred
// (as a fundamental element), the others deferred when they miss the zone; queries inside the
// zone and beyond it, between the batches, answer as the ornament without a zone does.
TEST(OrnamentNearZone, AnswersEveryQueryAsAnOrnamentIndexingEverything) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament zoned(region, 1e-9), plain(region, 1e-9);
    set_zone_left_of_60(zoned);
    acanthus::Random rng(31);
    int inside_queries = 0, beyond_queries = 0;
    for (int batch = 0; batch < 60; ++batch) {
        add_dots(zoned, plain, rng, 8, 2);
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

// for_each_meeting() (the families near an element under a tile) visits every element with a
// proxy whose bounds meet the box, deferred ones beyond the zone too, and no other.
TEST(OrnamentNearZone, ForEachMeetingVisitsEveryElementWhoseBoundsMeetTheBox) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament zoned(region, 1e-9), plain(region, 1e-9);
    set_zone_left_of_60(zoned);
    acanthus::Random rng(7);
    add_dots(zoned, plain, rng, 300, 3);
    for (int q = 0; q < 40; ++q) {
        const double x = rng.uniform(0, q % 4 == 0 ? 200 : 35), y = rng.uniform(0, 200);
        const double w = rng.uniform(0.5, 12);
        const acanthus::Rect box{x, y, x + w, y + w};
        std::vector<int> seen;
        zoned.for_each_meeting(box, [&](const acanthus::Element& e) { seen.push_back(e.id); });
        std::sort(seen.begin(), seen.end());
        std::vector<int> expected;
        for (std::size_t id = 0; id < plain.size(); ++id) {
            const acanthus::Rect p = plain.at(static_cast<int>(id)).proxy(0).bounds();
            if (p.x0 <= box.x1 && box.x0 <= p.x1 && p.y0 <= box.y1 && box.y0 <= p.y1)
                expected.push_back(static_cast<int>(id));
        }
        EXPECT_EQ(seen, expected) << "query " << q;
    }
}

// A query beyond the zone indexes only the deferred elements near it (their buckets of 8 x 8
// cells): the images far from it, all over the grid, stay out of the index until a query
// reaches them (or the whole grid is searched).
TEST(OrnamentNearZone, AQueryBeyondTheZoneIndexesOnlyTheDeferredElementsNearIt) {
    const acanthus::Region region = acanthus::Region::from_spec("rect:200,200");
    Ornament ornament(region, 1e-9);
    set_zone_left_of_60(ornament);
    std::vector<std::unique_ptr<acanthus::Element>> batch;
    batch.push_back(dot({20, 20}, 1));     // fundamental: indexed
    batch.push_back(dot({190, 10}, 1));    // deferred, top right
    batch.push_back(dot({190, 190}, 1));   // deferred, bottom right
    batch.push_back(dot({-300, 100}, 1));  // deferred, beyond the cells on the left
    ornament.add_all(std::move(batch), 1);
    EXPECT_EQ(ornament.indexed(), 1u);
    const auto top = ornament.within({185, 10}, 5);
    ASSERT_EQ(top.size(), 1u);
    EXPECT_EQ(top.front().first->id, 1);
    EXPECT_EQ(ornament.indexed(), 2u);  // not the dot at the bottom, nor the far one
    EXPECT_EQ(ornament.within({190, 185}, 5).size(), 1u);
    EXPECT_EQ(ornament.indexed(), 3u);
    EXPECT_EQ(ornament.nearest({-400, 100}).first->id, 3);
    EXPECT_EQ(ornament.indexed(), 4u);
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

// Images share chunks of storage: thousands built and freed in a shuffled order, over several
// chunks and after every image was freed once, each keeps its own proxy and transformation.
TEST(ImageElement, ImagesBuiltAndFreedInAnyOrderKeepTheirOwnProxies) {
    dots::dot e;
    e.p0.set({10, 0}, 1);
    std::mt19937 rng(5);
    for (int round = 0; round < 3; ++round) {
        std::vector<std::unique_ptr<acanthus::Element>> images;
        for (int k = 0; k < 3000; ++k) {
            images.push_back(
                std::make_unique<ImageElement>(e, Isometry::rotation({0, 0}, k * 1e-3)));
            if (k % 7 == 3) {  // free one now and then, reused by later images
                std::uniform_int_distribution<std::size_t> pick(0, images.size() - 1);
                images.erase(images.begin() + static_cast<std::ptrdiff_t>(pick(rng)));
            }
        }
        std::shuffle(images.begin(), images.end(), rng);
        images.resize(images.size() / 2);
        for (const auto& x : images) {
            const auto& image = static_cast<const ImageElement&>(*x);
            const double angle = std::atan2(image.transform().b, image.transform().a);
            const auto& c = static_cast<const acanthus::CircleProxy&>(
                const_cast<ImageElement&>(image).proxy(0));
            EXPECT_NEAR(c.center.x, 10 * std::cos(angle), 1e-9);
            EXPECT_NEAR(c.center.y, 10 * std::sin(angle), 1e-9);
            EXPECT_EQ(&image.original(), &e);
        }
    }
}

// The shared storage is taken and given back under a lock: images built and freed on several
// threads at once, interleaved, each keep their own proxy (a lost lock corrupts the free list).
TEST(ImageElement, ImagesBuiltAndFreedOnSeveralThreadsKeepTheirOwnProxies) {
    constexpr int kThreads = 4;
    std::vector<std::thread> threads;
    std::vector<int> wrong(kThreads, 0);
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([t, &wrong] {
            dots::dot e;
            e.p0.set({10.0 + t, 0}, 1);
            std::mt19937 rng(static_cast<unsigned>(t));
            std::vector<std::unique_ptr<acanthus::Element>> images;
            for (int k = 0; k < 20000; ++k) {
                images.push_back(
                    std::make_unique<ImageElement>(e, Isometry::rotation({0, 0}, k * 1e-4)));
                if (k % 3 == 1) {
                    std::uniform_int_distribution<std::size_t> pick(0, images.size() - 1);
                    images.erase(images.begin() + static_cast<std::ptrdiff_t>(pick(rng)));
                }
            }
            for (const auto& x : images) {
                auto& image = static_cast<ImageElement&>(*x);
                const double angle = std::atan2(image.transform().b, image.transform().a);
                const auto& c = static_cast<const acanthus::CircleProxy&>(image.proxy(0));
                if (std::abs(c.center.x - (10.0 + t) * std::cos(angle)) > 1e-9 ||
                    &image.original() != &e)
                    ++wrong[static_cast<std::size_t>(t)];
            }
        });
    for (auto& th : threads) th.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(wrong[static_cast<std::size_t>(t)], 0) << t;
}

// as_image() tells an image from a fundamental element by its exact type: an image of an image
// is an image, and the element an image stands for is not one.
TEST(ImageElement, AsImageTellsImagesFromFundamentalElements) {
    dots::dot e;
    e.p0.set({10, 0}, 1);
    const ImageElement image(e, Isometry::rotation({0, 0}, 0.5));
    const ImageElement twice(image, Isometry::rotation({0, 0}, 0.5));
    const acanthus::Element& as_base = image;
    EXPECT_EQ(as_image(as_base), &image);
    EXPECT_EQ(as_image(twice), &twice);
    EXPECT_EQ(as_image(e), nullptr);
    EXPECT_EQ(&original_of(image), &e);
    EXPECT_EQ(&original_of(e), &e);
    dots::seed s;
    EXPECT_EQ(as_image(s), nullptr);
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

namespace {

// Groups of every kind placed as the engine places them: rosettes about a point, friezes on a
// band (no window), wallpaper groups on their tiles' boxes (a window), square, hexagonal and
// oblique lattices.
struct PlacedGroup {
    std::string name;
    acanthus::Region region;
    std::unique_ptr<acanthus::detail::SymmetryGroup> group;
};

std::vector<PlacedGroup> placed_groups() {
    using acanthus::Region;
    using acanthus::detail::SymmetryGroup;
    std::vector<PlacedGroup> out;
    out.reserve(13);  // a frieze's group keeps its region by reference
    for (const char* name : {"d8", "c5", "d3"}) {
        out.push_back({name, Region::from_spec("circle:100"), nullptr});
        out.back().group = std::make_unique<SymmetryGroup>(acanthus::Symmetry::parse(name),
                                                           out.back().region.bounds().center());
    }
    for (const char* name : {"p1", "p2mg", "p11g", "p2mm"}) {
        out.push_back({std::string("frieze ") + name, Region::from_spec("rect:400,60"), nullptr});
        out.back().group = std::make_unique<SymmetryGroup>(
            acanthus::detail::frieze_setup({name, 50}, out.back().region, std::nullopt).group,
            out.back().region);
    }
    for (const acanthus::Wallpaper& w :
         {acanthus::Wallpaper{"p4m", 60, 60, 90}, acanthus::Wallpaper{"p6m", 60, 60, 60},
          acanthus::Wallpaper{"pgg", 70, 50, 90}, acanthus::Wallpaper{"p2", 70, 50, 75},
          acanthus::Wallpaper{"p31m", 60, 60, 120}, acanthus::Wallpaper{"cm", 70, 50, 90}}) {
        acanthus::detail::TranslationSetup s = acanthus::detail::wallpaper_setup(w);
        out.push_back({"wallpaper " + w.group, *s.box, nullptr});
        out.back().group = std::make_unique<SymmetryGroup>(std::move(s.group), out.back().region);
    }
    return out;
}

}  // namespace

// moves_apart() says every isometry moves a point by more than d only when each listed one does
// (points anywhere, on mirrors, at rotation centres and a fraction of d beside them), and says
// so of most points of a group with translations; point_orbit(), which takes its images without
// comparing them when it does, keeps the images a pairwise comparison keeps, in order.
TEST(SymmetryGroup, MovesApartAndPointOrbitUnderEveryKindOfGroup) {
    using acanthus::Vector;
    using acanthus::detail::point_orbit;
    using acanthus::detail::SymmetryGroup;
    std::mt19937 rng(13);
    for (const PlacedGroup& pg : placed_groups()) {
        const SymmetryGroup& g = *pg.group;
        const Rect b = pg.region.bounds();
        const double tol = 1e-6 * std::max(b.width(), b.height());
        std::uniform_real_distribution<double> x(b.x0, b.x1), y(b.y0, b.y1);
        std::vector<Point> points;
        for (int k = 0; k < 60; ++k) points.push_back({x(rng), y(rng)});
        for (const Point c : g.centre_classes(tol))
            for (double d : {0.0, 0.4, 0.6, 1.2, 3.0}) points.push_back(c + Vector(d * tol, 0));
        for (const Isometry& t : g.transforms()) {
            if (!t.reverses() || points.size() > 400) continue;
            const Point p{x(rng), y(rng)};
            const Point on = p + (t.apply(p) - p) * 0.5;
            const Vector off =
                (p - on).length() > 0 ? (p - on) * (1 / (p - on).length()) : Vector(1, 0);
            for (double d : {0.0, 0.3, 0.49, 0.51, 0.9, 1.1, 2.5})
                points.push_back(on + off * (d * tol));
        }
        int apart = 0;
        for (const Point p : points) {
            const double d = 2 * tol;
            if (g.moves_apart(p, d)) {
                ++apart;
                for (std::size_t k = 1; k < g.transforms().size(); ++k)
                    EXPECT_GT(distance(g.transforms()[k].apply(p), p), d)
                        << pg.name << " at " << p.x << "," << p.y << " by " << k;
            }
            std::vector<Point> want{p};
            for (std::size_t k = 1; k < g.transforms().size(); ++k) {
                const Point q = g.transforms()[k].apply(p);
                if (!g.rosette() && !b.contains(q)) continue;
                bool seen = false;
                for (const Point o : want) seen = seen || distance(o, q) <= tol;
                if (!seen) want.push_back(q);
            }
            const std::vector<Point> got = point_orbit(g, p, tol, b);
            ASSERT_EQ(got.size(), want.size()) << pg.name << " at " << p.x << "," << p.y;
            for (std::size_t k = 0; k < got.size(); ++k) {
                EXPECT_EQ(got[k].x, want[k].x) << pg.name;
                EXPECT_EQ(got[k].y, want[k].y) << pg.name;
            }
        }
        EXPECT_GT(apart, 40) << pg.name;
    }
}

// The domain's pixels under friezes and wallpaper groups (found a row's run at a time) are those
// in_domain() accepts, pixel by pixel, on grids whose origin and pixel fall anywhere.
TEST(SymmetryDomainPixels, RowRunsAreThePixelsInTheDomain) {
    for (const PlacedGroup& pg : placed_groups()) {
        const Rect b = pg.region.bounds();
        for (double pixel : {0.37, 1.0, 2.5}) {
            acanthus::GridFrame grid;
            grid.pixel = pixel;
            grid.x0 = b.x0 - 3.3;
            grid.y0 = b.y0 - 1.7;
            grid.width = static_cast<int>((b.width() + 7) / pixel);
            grid.height = static_cast<int>((b.height() + 4) / pixel);
            const std::vector<std::uint8_t> pixels =
                acanthus::detail::domain_pixels(grid, *pg.group);
            long mismatches = 0, in = 0;
            for (int j = 0; j < grid.height; ++j)
                for (int i = 0; i < grid.width; ++i) {
                    const bool want = pg.group->in_domain(grid.center_of(i, j), grid.pixel);
                    const bool got = pixels[static_cast<std::size_t>(j) * grid.width + i] != 0;
                    mismatches += want != got;
                    in += got;
                }
            EXPECT_EQ(mismatches, 0) << pg.name << " at pixel " << pixel;
            EXPECT_GT(in, 0) << pg.name;
            EXPECT_LT(in, static_cast<long>(grid.width) * grid.height) << pg.name;
        }
    }
}

// orbit_of() decides most images from their box alone; its orbit is the one found by building
// every image: those kept and not in the element's place (once each when some image coincides
// with it), and clear when no image but those in its place overlaps it.
TEST(OrbitOf, ImagesDecidedByTheirBoxAreThoseOfEveryImageBuilt) {
    std::mt19937 rng(11);
    for (const PlacedGroup& pg : placed_groups()) {
        const acanthus::detail::SymmetryGroup& g = *pg.group;
        const Rect b = pg.region.bounds();
        const double tol = 1e-6 * std::max(b.width(), b.height());
        std::uniform_real_distribution<double> ux(b.x0, b.x1), uy(b.y0, b.y1), ur(0.2, 25);
        std::vector<std::pair<Point, double>> dots_at;
        for (int n = 0; n < 150; ++n) dots_at.push_back({{ux(rng), uy(rng)}, ur(rng)});
        dots_at.push_back({g.center(), 3});                       // on the rosette's centre
        dots_at.push_back({g.snap({ux(rng), uy(rng)}, 1e9), 2});  // on a mirror or a centre
        for (const auto& [c, r] : dots_at) {
            const auto e = dot(c, r);
            const acanthus::detail::Orbit orbit = acanthus::detail::orbit_of(*e, g, tol);
            std::vector<std::unique_ptr<ImageElement>> built;
            std::vector<const Isometry*> kept;
            bool fixed = false, clear = true;
            for (std::size_t k = 1; k < g.size(); ++k) {
                auto image = std::make_unique<ImageElement>(*e, g.transforms()[k]);
                if (acanthus::detail::same_place(*image, *e, tol)) {
                    fixed = true;
                    continue;
                }
                if (acanthus::detail::overlaps(image->proxy(0), e->proxy(0), tol)) clear = false;
                if (!g.keeps(*image, tol)) continue;
                built.push_back(std::move(image));
                kept.push_back(&g.transforms()[k]);
            }
            std::vector<const Isometry*> want;
            for (std::size_t k = 0; k < built.size(); ++k) {
                bool repeated = false;
                for (std::size_t m = 0; fixed && m < k; ++m)
                    repeated = repeated || acanthus::detail::same_place(*built[k], *built[m], tol);
                if (!repeated) want.push_back(kept[k]);
            }
            ASSERT_EQ(orbit.images.size(), want.size())
                << pg.name << " dot at " << c.x << "," << c.y << " r " << r;
            for (std::size_t k = 0; k < want.size(); ++k)
                EXPECT_TRUE(acanthus::detail::same_isometry(orbit.images[k], *want[k], 0))
                    << pg.name;
            EXPECT_EQ(orbit.clear, clear) << pg.name << " dot at " << c.x << "," << c.y;
        }
    }
}

// clearance() measures most images by their squared distance; it answers, to the bit, half
// the distance to the nearest image beyond the tolerance measured image by image, on random
// points, on the rotation centres and on points snapped onto mirrors (some images there
// coincide, others lie about the tolerance away).
TEST(SymmetryClearance, IsHalfTheNearestImageDistanceToTheBit) {
    std::mt19937 rng(5);
    for (const PlacedGroup& pg : placed_groups()) {
        const acanthus::detail::SymmetryGroup& g = *pg.group;
        const Rect b = pg.region.bounds();
        std::uniform_real_distribution<double> x(b.x0, b.x1), y(b.y0, b.y1);
        for (int n = 0; n < 400; ++n) {
            Point p{x(rng), y(rng)};
            if (n % 4 == 1) p = g.snap(p, 5);
            if (n % 4 == 2) p = g.snap(p, 1e-3) + acanthus::Vector(1e-3, -2e-3) * (n % 3);
            if (n == 3) p = g.center();
            for (double tol : {1e-9, 1e-3, 2e-3, 0.5}) {
                double want = std::numeric_limits<double>::infinity();
                for (std::size_t k = 1; k < g.size(); ++k) {
                    const double d = acanthus::distance(g.transforms()[k].apply(p), p);
                    if (d > tol) want = std::min(want, d / 2);
                }
                EXPECT_EQ(g.clearance(p, tol), want) << pg.name << " at " << p.x << "," << p.y;
            }
        }
    }
}

// With `at_most` the answer is the clearance when it is above at_most, else at most at_most;
// a hint (the transformation that ended the last search, however stale) changes nothing.
TEST(SymmetryClearance, AtMostAndItsHintGiveTheSameAnswers) {
    std::mt19937 rng(8);
    for (const PlacedGroup& pg : placed_groups()) {
        const acanthus::detail::SymmetryGroup& g = *pg.group;
        const Rect b = pg.region.bounds();
        std::uniform_real_distribution<double> x(b.x0, b.x1), y(b.y0, b.y1);
        std::uniform_real_distribution<double> bar(0, 0.2 * std::max(b.width(), b.height()));
        std::size_t hint = 0;
        int cut = 0;
        for (int n = 0; n < 400; ++n) {
            Point p{x(rng), y(rng)};
            if (n % 4 == 1) p = g.snap(p, 5);
            if (n % 7 == 3) hint = static_cast<std::size_t>(n) % (g.size() + 2);  // stale, wild
            for (double tol : {1e-9, 1e-3, 0.5}) {
                const double at_most = bar(rng);
                const double exact = g.clearance(p, tol);
                const double plain = g.clearance(p, tol, at_most);
                const double hinted = g.clearance(p, tol, at_most, &hint);
                EXPECT_EQ(hinted, plain) << pg.name << " at " << p.x << "," << p.y;
                if (exact > at_most) {
                    EXPECT_EQ(hinted, exact) << pg.name << " at " << p.x << "," << p.y;
                } else {
                    EXPECT_LE(hinted, at_most) << pg.name << " at " << p.x << "," << p.y;
                    ++cut;
                }
            }
        }
        EXPECT_GT(cut, 0) << pg.name;
    }
}
