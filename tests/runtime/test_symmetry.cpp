// Growth under a rosette group (docs/symmetry.md): the group and its fundamental domain, images
// of proxies, orbits, and the grown ornament checked as the expert would: the element set is
// invariant under the group, nothing overlaps anything (images included), every image lies in
// the region, and the run is deterministic.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "fixtures/dots_pattern.hpp"
#include "fixtures/growth_tree.hpp"
#include "growth/ornament.hpp"
#include "program/tree_json.hpp"
#include "proxy/overlap.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/orbit.hpp"
#include "symmetry/symmetric_core.hpp"
#include "symmetry/symmetry_group.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

bool same_isometry(const Isometry& a, const Isometry& b) {
    const auto x = a.matrix(), y = b.matrix();
    for (int k = 0; k < 6; ++k)
        if (std::abs(x[k] - y[k]) > 1e-9) return false;
    return true;
}

SymmetryGroup group_of(const std::string& name, Point center = {0, 0}) {
    return SymmetryGroup(Symmetry::parse(name), center);
}

}  // namespace

TEST(Symmetry, ParsesCyclicAndDihedralGroups) {
    EXPECT_EQ(Symmetry::parse("c6").name(), "c6");
    EXPECT_EQ(Symmetry::parse("D8").name(), "d8");
    EXPECT_EQ(Symmetry::parse("c1").order, 1);
    EXPECT_EQ(Symmetry::parse("d360").kind, Symmetry::Kind::dihedral);
    for (const char* bad : {"", "c", "d", "x6", "c0", "d0", "c-1", "c6.5", "c 6", "c361", "p4m",
                            "6", "cc6", "c99999999999999999999"})
        EXPECT_THROW(Symmetry::parse(bad), UsageError) << bad;
    try {
        Symmetry::parse("d0");
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("1 or more"), std::string::npos) << e.what();
    }
}

TEST(SymmetryGroup, IsClosedUnderCompositionAndInverse) {
    for (const char* name : {"c1", "c2", "c5", "d1", "d2", "d6", "c12"}) {
        const SymmetryGroup g = group_of(name, {3, -7});
        const auto& t = g.transforms();
        const std::size_t n = static_cast<std::size_t>(Symmetry::parse(name).order);
        EXPECT_EQ(t.size(), name[0] == 'c' ? n : 2 * n) << name;
        EXPECT_TRUE(same_isometry(t[0], Isometry{}));
        auto member = [&](const Isometry& x) {
            for (const Isometry& y : t)
                if (same_isometry(x, y)) return true;
            return false;
        };
        for (const Isometry& a : t) {
            EXPECT_TRUE(member(a.inverse())) << name;
            EXPECT_TRUE(same_isometry(a.then(a.inverse()), Isometry{}));
            for (const Isometry& b : t) EXPECT_TRUE(member(a.then(b))) << name;
            EXPECT_NEAR(distance(a.apply(g.center()), g.center()), 0, 1e-12);
        }
    }
}

// Each orbit of a point in general position meets the fundamental domain exactly once.
TEST(SymmetryGroup, DomainHoldsOnePointOfEachOrbit) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-50, 50);
    for (const char* name : {"c1", "c3", "c7", "d1", "d4", "d9"}) {
        const SymmetryGroup g = group_of(name, {10, 20});
        for (int n = 0; n < 500; ++n) {
            const Point p{u(rng), u(rng)};
            int inside = 0;
            for (const Isometry& t : g.transforms()) inside += g.in_domain(t.apply(p), 0) ? 1 : 0;
            EXPECT_EQ(inside, 1) << name << " at " << p.x << "," << p.y;
        }
    }
}

// The domain's pixels (where C may be centred) are those in_domain() accepts, pixel by pixel,
// for every kind of group, about the grid's centre and off it (the fast path decides most
// pixels without in_domain()).
TEST(SymmetryGroup, DomainPixelsAreThoseInTheDomain) {
    GridFrame grid;
    grid.width = 300;
    grid.height = 220;
    grid.pixel = 0.5;
    grid.x0 = -20;
    grid.y0 = -30;
    for (const char* name : {"c1", "c2", "c3", "c4", "c6", "d1", "d2", "d5", "d8", "d12", "c60"})
        for (Point c : {Point{55, 25}, Point{3.25, 71}, Point{60, 150}}) {
            const SymmetryGroup g = group_of(name, c);
            const std::vector<std::uint8_t> pixels = domain_pixels(grid, g);
            long mismatches = 0, in = 0;
            for (int j = 0; j < grid.height; ++j)
                for (int i = 0; i < grid.width; ++i) {
                    const bool want = g.in_domain(grid.center_of(i, j), grid.pixel);
                    const bool got = pixels[static_cast<std::size_t>(j * grid.width + i)] != 0;
                    mismatches += want != got;
                    in += got;
                }
            EXPECT_EQ(mismatches, 0) << name << " about " << c.x << "," << c.y;
            EXPECT_GT(in, 0) << name;
        }
}

// The near zone: the cells (the field's 8 x 8 tiles, on the grid widened by `cells` cells on
// every side) within `cells` cells of a domain pixel, as a brute force over the domain's
// pixels finds them, for a wedge's domain and a scattered one, on grids not a whole number of
// tiles across.
TEST(SymmetryGroup, NearZoneIsTheCellsNearTheDomain) {
    GridFrame grid;
    grid.width = 203;
    grid.height = 149;
    grid.pixel = 1;
    std::mt19937 rng(3);
    for (int scene = 0; scene < 4; ++scene) {
        std::vector<std::uint8_t> domain(static_cast<std::size_t>(grid.width) * grid.height, 0);
        if (scene == 0) {
            domain = domain_pixels(grid, group_of("d8", {100, 70}));
        } else {
            std::uniform_int_distribution<int> at(0, grid.width * grid.height - 1);
            for (int k = 0; k < 3 * scene; ++k) domain[static_cast<std::size_t>(at(rng))] = 1;
        }
        for (const int cells : {1, 4}) {
            const std::vector<bool> zone = near_zone(grid, domain, cells);
            const int cw = (grid.width + 7) / 8 + 2 * cells, ch = (grid.height + 7) / 8 + 2 * cells;
            ASSERT_EQ(zone.size(), static_cast<std::size_t>(cw) * ch);
            std::vector<bool> want(zone.size(), false);
            for (int j = 0; j < grid.height; ++j)
                for (int i = 0; i < grid.width; ++i) {
                    if (!domain[static_cast<std::size_t>(j) * grid.width + i]) continue;
                    const int x = i / 8 + cells, y = j / 8 + cells;
                    for (int b = y - cells; b <= y + cells; ++b)
                        for (int a = x - cells; a <= x + cells; ++a)
                            want[static_cast<std::size_t>(b) * cw + a] = true;
                }
            long mismatches = 0, in = 0;
            for (std::size_t k = 0; k < zone.size(); ++k) {
                mismatches += zone[k] != want[k];
                in += zone[k];
            }
            EXPECT_EQ(mismatches, 0) << "scene " << scene << ", cells " << cells;
            EXPECT_GT(in, 0);
        }
    }
    EXPECT_TRUE(near_zone(grid, {}, 4).empty());
}

// domain_gap() is never more than the distance to the rosette's wedge (brute force: points along
// its edges 0.025 apart, 0 for a point in_domain() holds) and within that spacing of it; 0
// for a wedge of a half-plane or more. The growth loop leaves images farther than its margins
// out of the near zone's and the field's tests.
TEST(SymmetryGroup, DomainGapIsNoMoreThanTheDistanceToTheWedge) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-60, 60);
    const Point centre{3, -2};
    for (const char* name : {"c3", "c6", "d2", "d4", "d8", "d12"}) {
        const SymmetryGroup g = group_of(name, centre);
        const auto edges = g.domain_edges(100);
        int outside = 0;
        for (int k = 0; k < 150; ++k) {
            const Point p{centre.x + u(rng), centre.y + u(rng)};
            const double gap = g.domain_gap(p);
            if (g.in_domain(p, 0)) {
                EXPECT_EQ(gap, 0) << name << " " << p.x << "," << p.y;
                continue;
            }
            double d = INFINITY;
            for (const auto& [a, b] : edges)
                for (int s = 0; s <= 4000; ++s)
                    d = std::min(d, distance(p, a + (b - a) * (s / 4000.0)));
            EXPECT_LE(gap, d) << name << " " << p.x << "," << p.y;
            EXPECT_GE(gap, d - 0.03) << name << " " << p.x << "," << p.y;
            ++outside;
        }
        EXPECT_GT(outside, 60) << name;
    }
    for (const char* name : {"c1", "c2", "d1"})
        EXPECT_EQ(group_of(name, centre).domain_gap({centre.x + 40, centre.y + 30}), 0) << name;
}

// A box farther than near_zone_reach() pixels from the centre of every domain pixel misses the
// near zone as the ornament tests a box (widened by a cell): an element with such bounds, added
// as deferrable, is not indexed. The zone is set up as the growth loop sets it.
TEST(SymmetryGroup, BoxesBeyondTheNearZoneReachMissTheZone) {
    GridFrame grid;
    grid.x0 = -7.5;
    grid.y0 = 3.25;
    grid.width = 203;
    grid.height = 149;
    grid.pixel = 0.75;
    const Region region = Region::from_spec("rect:400,400");
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> along(-60, 260), half(0, 4);
    for (int scene = 0; scene < 3; ++scene) {
        std::vector<std::uint8_t> domain(static_cast<std::size_t>(grid.width) * grid.height, 0);
        if (scene == 0) {
            domain = domain_pixels(grid, group_of("d8", grid.center_of(100, 70)));
        } else {
            std::uniform_int_distribution<int> at(0, grid.width * grid.height - 1);
            for (int k = 0; k < 4 * scene; ++k) domain[static_cast<std::size_t>(at(rng))] = 1;
        }
        std::vector<Point> centres;
        for (int j = 0; j < grid.height; ++j)
            for (int i = 0; i < grid.width; ++i)
                if (domain[static_cast<std::size_t>(j) * grid.width + i])
                    centres.push_back(grid.center_of(i, j));
        for (const int cells : {1, 4}) {
            Ornament ornament(region, 1e-9);
            const double cell = grid.pixel * 8;
            ornament.set_near_zone({grid.x0 - cells * cell, grid.y0 - cells * cell}, cell,
                                   ((grid.width - 1) >> 3) + 1 + 2 * cells,
                                   near_zone(grid, domain, cells));
            int beyond = 0;
            for (int q = 0; q < 1500; ++q) {
                const Point c{grid.x0 + along(rng) * grid.pixel, grid.y0 + along(rng) * grid.pixel};
                const double r = half(rng) * grid.pixel;
                double d = INFINITY;  // pixels from the box [c - r, c + r] to a domain pixel
                for (const Point p : centres) {
                    const double dx = std::max(0.0, std::abs(p.x - c.x) - r);
                    const double dy = std::max(0.0, std::abs(p.y - c.y) - r);
                    d = std::min(d, std::sqrt(dx * dx + dy * dy) / grid.pixel);
                }
                if (!(d > near_zone_reach(cells))) continue;
                ++beyond;
                auto dot = std::make_unique<dots::dot>();
                dot->p0.set(c, r);
                std::vector<std::unique_ptr<Element>> one;
                one.push_back(std::move(dot));
                const std::size_t before = ornament.indexed();
                ornament.add_all(std::move(one), 0);
                EXPECT_EQ(ornament.indexed(), before)
                    << "scene " << scene << ", cells " << cells << ", " << d << " pixels";
            }
            EXPECT_GT(beyond, 100) << "scene " << scene << ", cells " << cells;
        }
    }
}

// A batch of children under a rosette: each is checked against the images of those before it
// (the batch's own index, made only for a batch of several) and against placed images; a
// child alone, or clear of the others' images, is placed with its images.
TEST(SymmetryGroup, PlaceableOrbitsCheckAChildAgainstTheImagesOfThoseBefore) {
    const SymmetryGroup g = group_of("c4", {0, 0});
    auto dot = [](Point c) {
        auto d = std::make_unique<dots::dot>();
        d->p0.set(c, 1);
        return d;
    };
    const auto a = dot({10, 3});     // images about (-3, 10), (-10, -3), (3, -10)
    const auto b = dot({-3, 10.5});  // on a's first image
    const auto c = dot({20, 5});     // clear of everything
    const auto none_placed = [](const acanthus::Proxy&) { return false; };
    const auto both = placeable_orbits({a.get(), b.get()}, g, nullptr, 1e-6, none_placed);
    ASSERT_EQ(both.size(), 2u);
    ASSERT_TRUE(both[0].has_value());
    EXPECT_EQ(both[0]->elements.size(), 3u);
    EXPECT_FALSE(both[1].has_value());
    const auto alone = placeable_orbits({b.get()}, g, nullptr, 1e-6, none_placed);
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_TRUE(alone[0].has_value());
    const auto clear = placeable_orbits({a.get(), c.get(), b.get()}, g, nullptr, 1e-6, none_placed);
    ASSERT_EQ(clear.size(), 3u);
    EXPECT_TRUE(clear[0].has_value());
    EXPECT_TRUE(clear[1].has_value());
    EXPECT_FALSE(clear[2].has_value());
    // A placed image where the child lies refuses it.
    const auto placed =
        placeable_orbits({c.get()}, g, nullptr, 1e-6, [](const acanthus::Proxy&) { return true; });
    EXPECT_FALSE(placed[0].has_value());
}

// A point's orbit: the point and its images, those within the tolerance of one before left
// out, as comparing every image with those kept finds them; points anywhere, on the centre and
// on mirrors, and within a few tolerances of them (where images nearly coincide).
TEST(SymmetryGroup, PointOrbitKeepsTheDistinctImagesInOrder) {
    const double tol = 1e-3;
    const Rect bounds{-1000, -1000, 1000, 1000};
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> at(-50, 50);
    for (const char* name : {"c1", "c2", "c5", "c6", "d1", "d4", "d8", "d12"}) {
        const SymmetryGroup g = group_of(name, {3, -7});
        std::vector<Point> points{g.center(), g.center() + Vector(0.4 * tol, 0),
                                  g.center() + Vector(1.5 * tol, -0.5 * tol)};
        for (int k = 0; k < 40; ++k) points.push_back({at(rng), at(rng)});
        // On each mirror and beside it, at distances about the tolerance.
        for (const Isometry& t : g.transforms()) {
            if (!t.reverses()) continue;
            const Point p{at(rng), at(rng)};
            const Point on = p + (t.apply(p) - p) * 0.5;
            const Vector off =
                (p - on).length() > 0 ? (p - on) * (1 / (p - on).length()) : Vector(1, 0);
            for (double d : {0.0, 0.3, 0.49, 0.51, 0.9, 1.1, 2.5})
                points.push_back(on + off * (d * tol));
        }
        for (const Point p : points) {
            std::vector<Point> want{p};
            for (std::size_t k = 1; k < g.transforms().size(); ++k) {
                const Point q = g.transforms()[k].apply(p);
                bool seen = false;
                for (const Point o : want) seen = seen || distance(o, q) <= tol;
                if (!seen) want.push_back(q);
            }
            const std::vector<Point> got = point_orbit(g, p, tol, bounds);
            ASSERT_EQ(got.size(), want.size()) << name << " at " << p.x << "," << p.y;
            for (std::size_t k = 0; k < got.size(); ++k) {
                EXPECT_EQ(got[k].x, want[k].x) << name;
                EXPECT_EQ(got[k].y, want[k].y) << name;
            }
        }
    }
}

// Whether a group maps a panel onto itself (then the core is the whole panel).
TEST(SymmetryGroup, KnowsWhenItMapsTheRegionOntoItself) {
    const Region circle = Region::from_spec("circle:100");
    const Point o = circle.bounds().center();
    const Region rect = Region::from_spec("rect:200,100");
    const Point m = rect.bounds().center();
    const double tol = 0.25;
    EXPECT_TRUE(maps_onto_itself(circle, group_of("c7", o), tol));
    EXPECT_TRUE(maps_onto_itself(circle, group_of("d12", o), tol));
    EXPECT_FALSE(maps_onto_itself(circle, group_of("c7", o + Vector(1, 0)), tol));
    EXPECT_TRUE(maps_onto_itself(rect, group_of("d2", m), tol));
    EXPECT_TRUE(maps_onto_itself(rect, group_of("c2", m), tol));
    EXPECT_FALSE(maps_onto_itself(rect, group_of("c4", m), tol));
    EXPECT_FALSE(maps_onto_itself(rect, group_of("d1", m + Vector(0.5, 0)), tol));
    EXPECT_TRUE(maps_onto_itself(rect, group_of("d1", m + Vector(0, 7)), tol));
}

TEST(SymmetryGroup, SnapsOntoMirrorsAndTheCentre) {
    const SymmetryGroup d4 = group_of("d4", {0, 0});
    // The first mirror is vertical; the others every 45 degrees.
    EXPECT_NEAR(d4.snap({0.3, -20}, 0.5).x, 0, 1e-12);
    const Point diagonal = d4.snap({10.2, 10}, 0.5);
    EXPECT_NEAR(diagonal.x, diagonal.y, 1e-12);
    EXPECT_EQ(d4.snap({3, 9}, 0.5).x, 3);  // far from every mirror
    const Point centre = group_of("c5", {4, 4}).snap({4.2, 3.9}, 0.5);
    EXPECT_EQ(centre.x, 4);
    EXPECT_EQ(centre.y, 4);
    EXPECT_EQ(group_of("c5").snap({0.3, -20}, 0.5).x, 0.3);  // no mirrors in cN
    // On a mirror a point is its own image; off it, the clearance is half the way to it.
    EXPECT_TRUE(std::isinf(group_of("d1").clearance({0, 5}, 1e-9)));
    EXPECT_NEAR(group_of("d1").clearance({2, 5}, 1e-9), 2, 1e-12);
}

// Distances are kept: the image of a proxy is as far from the image of a point as the proxy
// is from the point, for every kind, rotations and reflections alike.
TEST(ImageElement, ProxiesAreCarriedOverRigidly) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-30, 30);
    CircleProxy circle;
    circle.set({4, 5}, 3);
    ArcProxy arc;
    arc.set({-3, 2}, 6, 0.3, 2.2);
    LineSegmentProxy segment;
    segment.set({1, 1}, {9, -4});
    BezierProxy bezier;
    bezier.set({0, 0}, {5, 9}, {10, -3}, {14, 2});
    PolygonProxy polygon;
    polygon.set({{0, 0}, {8, 1}, {6, 7}, {1, 5}});
    PointProxy point;
    point.set({7, -2});
    const std::vector<const Proxy*> proxies{&circle, &arc, &segment, &bezier, &polygon, &point};
    const SymmetryGroup g = group_of("d5", {2, 3});
    for (const Proxy* p : proxies) {
        CircleProxy c2;
        ArcProxy a2;
        LineSegmentProxy s2;
        BezierProxy b2;
        PolygonProxy q2;
        PointProxy p2;
        Proxy* out = &p2;
        switch (p->kind()) {
            case ProxyKind::circle:
                out = &c2;
                break;
            case ProxyKind::arc:
                out = &a2;
                break;
            case ProxyKind::linesegment:
                out = &s2;
                break;
            case ProxyKind::bezier:
                out = &b2;
                break;
            case ProxyKind::polygon:
                out = &q2;
                break;
            case ProxyKind::point:
                break;
        }
        for (const Isometry& t : g.transforms()) {
            transform_proxy(*p, t, *out);
            for (int n = 0; n < 40; ++n) {
                const Point q{u(rng), u(rng)};
                EXPECT_NEAR(distance_to(*out, t.apply(q)), distance_to(*p, q), 1e-9)
                    << to_string(p->kind()) << (t.reverses() ? " reflected" : " rotated");
            }
        }
    }
}

TEST(Orbit, ElementsOnTheCentreOrAMirrorHaveFewerImages) {
    ::dots::dot on_centre, on_mirror, off, big;
    static_cast<CircleProxy&>(on_centre.proxy(0)).set({0, 0}, 5);
    static_cast<CircleProxy&>(on_mirror.proxy(0)).set({0, -20}, 2);
    static_cast<CircleProxy&>(off.proxy(0)).set({5, -20}, 2);
    static_cast<CircleProxy&>(big.proxy(0)).set({5, -20}, 8);
    const SymmetryGroup d4 = group_of("d4");
    const double tol = 1e-9;
    EXPECT_TRUE(orbit_of(on_centre, d4, tol).images.empty());
    EXPECT_TRUE(orbit_of(on_centre, d4, tol).clear);
    EXPECT_EQ(orbit_of(on_mirror, d4, tol).images.size(), 3u);  // 8 / 2 - 1
    EXPECT_EQ(orbit_of(off, d4, tol).images.size(), 7u);
    EXPECT_TRUE(orbit_of(off, d4, tol).clear);
    EXPECT_FALSE(orbit_of(big, d4, tol).clear);  // overlaps its mirror image
    // In a disc of radius 100 about (100, 100): clear about its centre, not about another point.
    const Region disc = Region::from_spec("circle:100");
    ::dots::dot inside;
    static_cast<CircleProxy&>(inside.proxy(0)).set({105, 80}, 2);
    EXPECT_FALSE(orbit_intersects(inside, group_of("d4", {100, 100}), &disc, tol));
    EXPECT_TRUE(orbit_intersects(inside, group_of("d4", {180, 100}), &disc, tol));
    EXPECT_TRUE(orbit_intersects(big, d4, nullptr, tol));  // overlaps its mirror image
}

namespace {

struct Grown {
    std::vector<std::unique_ptr<GrowthEngine>> keep;
    std::vector<const Element*> elements;
};

// The expert's rules for an ornament grown under a group: every image of every element is an
// element of the same type (to 1e-6 of the panel size), no two elements overlap, every element
// lies in the region, images name their original and are sterile.
void expect_symmetric_ornament(const std::vector<const Element*>& elements,
                               const SymmetryGroup& group, const Region& region,
                               const std::string& what) {
    const Rect b = region.bounds();
    const double size = std::max(b.width(), b.height());
    const double tol = 1e-6 * size;
    std::size_t images = 0;
    for (const Element* e : elements) {
        if (const ImageElement* image = as_image(*e)) {
            ++images;
            EXPECT_TRUE(e->sterile) << what;
            EXPECT_FALSE(as_image(image->original())) << what;
            EXPECT_LT(image->original().id, e->id) << what;
        }
        for (const Isometry& g : group.transforms()) {
            const ImageElement image(*e, g);
            bool found = false;
            for (const Element* f : elements)
                if (&f->type() == &e->type() && same_place(image, *f, tol)) {
                    found = true;
                    break;
                }
            ASSERT_TRUE(found) << what << ": an image of element " << e->id << " is missing";
        }
        for (std::size_t k = 0; k < e->proxy_count(); ++k)
            ASSERT_FALSE(leaves_region(e->proxy(k), region, tol))
                << what << ": element " << e->id << " leaves the region";
    }
    if (group.size() > 1) {
        EXPECT_GT(images, 0u) << what;
    }
    // Seeds are markers under the first dot (as without symmetry): the dots must not overlap.
    for (std::size_t i = 0; i < elements.size(); ++i)
        for (std::size_t j = i + 1; j < elements.size(); ++j)
            if (elements[i]->type().name != "seed" && elements[j]->type().name != "seed") {
                for (std::size_t p = 0; p < elements[i]->proxy_count(); ++p)
                    for (std::size_t q = 0; q < elements[j]->proxy_count(); ++q)
                        ASSERT_FALSE(overlaps(elements[i]->proxy(p), elements[j]->proxy(q), tol))
                            << what << ": elements " << elements[i]->id << " and "
                            << elements[j]->id << " overlap";
            }
}

struct Case {
    std::string region;
    std::string group;
    std::optional<Point> center;
};

}  // namespace

class SymmetricGrowth : public ::testing::TestWithParam<Case> {};

TEST_P(SymmetricGrowth, OrnamentIsInvariantAndFreeOfOverlap) {
    const Case& c = GetParam();
    const Region region = test::region_named(c.region);
    GrowthOptions o = test::small_options();
    o.resolution = 160;
    o.symmetry = Symmetry::parse(c.group);
    o.symmetry->center = c.center;
    ::dots::dot_count = 0;
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, region, o);
    engine.run();
    const auto elements = engine.elements();
    ASSERT_GT(elements.size(), 60u) << engine.stats().iterations << " iterations";
    EXPECT_EQ(engine.stats().stop_reason, "exhausted");
    const Point center =
        c.center ? *c.center : region.largest_inscribed_circle(engine.grid().pixel / 4).center;
    const SymmetryGroup group(*o.symmetry, center);
    expect_symmetric_ornament(elements, group, region, c.region + " " + c.group);

    // The same seed grows the same ornament.
    ::dots::dot_count = 0;
    GrowthEngine again(pattern, region, o);
    again.run();
    EXPECT_EQ(test::snapshot(again), test::snapshot(engine));
}

INSTANTIATE_TEST_SUITE_P(
    Rosettes, SymmetricGrowth,
    ::testing::Values(Case{"circle:50", "d8", {}}, Case{"circle:50", "c5", {}},
                      Case{"circle:50", "c1", {}}, Case{"rect:120,80", "d2", {}},
                      Case{"rect:120,80", "c3", Point{50, 45}}, Case{"hole", "d4", Point{50, 40}},
                      Case{"ellipse:60,40", "d1", {}}, Case{"circle:50", "c12", {}}),
    [](const auto& info) {
        std::string name = info.param.region + "_" + info.param.group;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

TEST(SymmetricGrowth, ReferenceEngineGrowsTheSameOrnament) {
    const Region region = Region::from_spec("circle:40");
    GrowthOptions o = test::small_options();
    o.symmetry = Symmetry::parse("d6");
    const auto fast = test::grow(::dots::pattern(), region, o);
    o.reference_engine = true;
    EXPECT_EQ(test::grow(::dots::pattern(), region, o), fast);
}

// The lazy field leaves out the tiles far from the fundamental domain (docs/symmetry.md,
// "Speed"): at 384 px the grid has 48 x 48 tiles of 8 px, most of them out of reach of a d6 or
// c5 wedge, and the tree must still be the reference engine's, which measures every pixel.
TEST(SymmetricGrowth, LazyFieldOverTheDomainGrowsTheReferenceOrnament) {
    struct Case {
        const char* region;
        const char* group;
        std::optional<Point> center;
    };
    for (const Case& c : {Case{"circle:40", "d6", {}}, Case{"circle:40", "c5", {}},
                          Case{"rect:120,80", "c3", Point{50, 45}}}) {
        const Region region = Region::from_spec(c.region);
        GrowthOptions o;
        o.resolution = 384;
        o.lazy_field_pixels = 0;  // lazy at any size
        o.symmetry = Symmetry::parse(c.group);
        o.symmetry->center = c.center;
        const auto fast = test::grow(::dots::pattern(), region, o);
        EXPECT_GT(fast.size(), 100u) << c.region << " " << c.group;
        o.reference_engine = true;
        EXPECT_EQ(test::grow(::dots::pattern(), region, o), fast) << c.region << " " << c.group;
    }
}

TEST(SymmetricGrowth, SeedWhoseImagesLeaveTheRegionIsRefused) {
    const Region region = Region::from_spec("rect:100,60");
    GrowthOptions o = test::small_options();
    o.symmetry = Symmetry::parse("c4");
    o.symmetry->center = Point{150, 30};
    o.symmetry->center = Point{50, 30};
    o.seeds = {Point{5, 5}};  // inside the rectangle, but its quarter turns are not
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, region, o);
    try {
        engine.run();
        FAIL() << "a seed whose images leave the region was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("image"), std::string::npos) << e.what();
    }
}

// The debug frame carries the fundamental domain's edges; --json marks every image with its
// original and the transformation that carries the original onto it.
TEST(SymmetricGrowth, DebugFrameAndJsonShowTheImages) {
    const Region region = Region::from_spec("circle:40");
    GrowthOptions o = test::small_options();
    o.symmetry = Symmetry::parse("d6");
    ::dots::dot_count = 0;
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, region, o);
    std::size_t edges = 0, images_seen = 0;
    engine.on_debug_frame(6, [&](const DebugFrame& frame) {
        edges = frame.domain.size();
        for (const Element* e : frame.placed) images_seen += as_image(*e) ? 1 : 0;
    });
    engine.run();
    EXPECT_EQ(edges, 2u);
    EXPECT_GT(images_seen, 0u);

    const auto elements = engine.elements();
    const auto tree = nlohmann::json::parse(tree_json(region, elements));
    std::size_t marked = 0;
    for (const auto& j : tree.at("elements")) {
        const Element& e = *elements.at(j.at("id").get<std::size_t>());
        ASSERT_EQ(j.contains("image_of"), as_image(e) != nullptr);
        if (!j.contains("image_of")) continue;
        ++marked;
        const Element& original = *elements.at(j.at("image_of").get<std::size_t>());
        const auto& m = j.at("transform");
        const Isometry t{m[0], m[1], m[2], m[3], m[4], m[5]};
        if (e.type().name != "dot") continue;
        const Point c = static_cast<const CircleProxy&>(original.proxy(0)).center;
        const Point image = static_cast<const CircleProxy&>(e.proxy(0)).center;
        EXPECT_NEAR(distance(t.apply(c), image), 0, 1e-9);
    }
    EXPECT_GT(marked, 0u);
}
