// Friezes and wallpaper groups in the growth engine (docs/symmetry.md): the groups cut down to
// the region, their Dirichlet domains, the fixed sets points snap onto, and the dots grown under
// them (invariant, free of overlap, deterministic).
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fixtures/growth_tree.hpp"
#include "proxy/overlap.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/orbit.hpp"
#include "symmetry/symmetry_group.hpp"
#include "symmetry/translation_groups.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

const std::vector<std::string> kFriezes{"p1", "p11g", "p1m1", "p11m", "p2", "p2mg", "p2mm"};
const std::vector<std::string> kWallpapers{"p1",  "p2",   "pm",   "pg", "cm",  "pmm",
                                           "pmg", "pgg",  "cmm",  "p4", "p4m", "p4g",
                                           "p3",  "p3m1", "p31m", "p6", "p6m"};

Wallpaper wallpaper_of(const std::string& name) {
    const bool hexagonal = name[1] == '3' || name[1] == '6';
    const bool square = name[1] == '4';
    if (hexagonal) return {name, 60, 60, 60};
    if (square) return {name, 60, 60, 90};
    return {name, 70, 50, 90};
}

// How many of a point's images inside `box` lie in the domain (no widening).
int images_in_domain(const SymmetryGroup& g, Point p, const Rect& box) {
    int n = 0;
    for (const Isometry& t : g.transforms()) {
        const Point q = t.apply(p);
        if (box.contains(q) && g.in_domain(q, 0)) ++n;
    }
    return n;
}

}  // namespace

// Each orbit meets the Dirichlet domain once, for every frieze on a band and every wallpaper
// group on its tile (points sampled where all their images near the domain are in the list).
TEST(TranslationGroup, DomainHoldsOnePointOfEachOrbit) {
    std::mt19937 rng(3);
    const Region band = Region::from_spec("rect:400,60");
    for (const std::string& name : kFriezes) {
        const TranslationSetup s = frieze_setup({name, 50}, band, std::nullopt);
        const SymmetryGroup g(s.group, band);
        std::uniform_real_distribution<double> ux(150, 250), uy(0, 60);
        for (int n = 0; n < 300; ++n) {
            const Point p{ux(rng), uy(rng)};
            EXPECT_EQ(images_in_domain(g, p, band.bounds()), 1) << name << " " << p.x << "," << p.y;
        }
    }
    for (const std::string& name : kWallpapers) {
        const Wallpaper w = wallpaper_of(name);
        const TranslationSetup s = wallpaper_setup(w);
        const SymmetryGroup g(s.group, *s.box);
        std::uniform_real_distribution<double> u(0, 1);
        const Region tile = tile_region(w);
        for (int n = 0; n < 300; ++n) {
            const double angle = w.angle_degrees * M_PI / 180;
            const Point p{u(rng) * w.width + u(rng) * w.height * std::cos(angle),
                          u(rng) * w.height * std::sin(angle)};
            EXPECT_EQ(images_in_domain(g, p, s.box->bounds()), 1)
                << name << " " << p.x << "," << p.y;
        }
    }
}

// The list holds the catalog's isometries with their translates: the identity first, and every
// one maps the domain's point elsewhere (no two coincide).
TEST(TranslationGroup, TransformsAreDistinctAndStartWithTheIdentity) {
    const Region band = Region::from_spec("rect:300,40");
    const TranslationSetup s = frieze_setup({"p2mg", 60}, band, std::nullopt);
    const SymmetryGroup g(s.group, band);
    ASSERT_GT(g.size(), 4u * 5);
    const Isometry& id = g.transforms()[0];
    EXPECT_EQ(id.a, 1);
    EXPECT_EQ(id.e, 0);
    for (std::size_t i = 0; i < g.size(); ++i)
        for (std::size_t j = i + 1; j < g.size(); ++j)
            EXPECT_GT(
                distance(g.transforms()[i].apply(g.center()), g.transforms()[j].apply(g.center())),
                1e-6);
}

// Points near a mirror or a rotation centre snap onto it; a glide axis fixes no point.
TEST(TranslationGroup, SnapsOntoFixedSets) {
    const Region band = Region::from_spec("rect:300,40");  // centre line y = 20
    const SymmetryGroup p11m(frieze_setup({"p11m", 60}, band, std::nullopt).group, band);
    EXPECT_NEAR(p11m.snap({100, 20.4}, 0.5).y, 20, 1e-9);
    EXPECT_EQ(p11m.snap({100, 22}, 0.5).y, 22);
    const SymmetryGroup p11g(frieze_setup({"p11g", 60}, band, std::nullopt).group, band);
    EXPECT_EQ(p11g.snap({100, 20.4}, 0.5).y, 20.4);
    const SymmetryGroup p2(frieze_setup({"p2", 60}, band, std::nullopt).group, band);
    const Point c = p2.snap({120.3, 20.2}, 0.5);  // a half-turn centre at x = 0 mod 30
    EXPECT_NEAR(c.x, 120, 1e-9);
    EXPECT_NEAR(c.y, 20, 1e-9);
    EXPECT_TRUE(std::isinf(p2.clearance({120, 20}, 1e-9)) || p2.clearance({120, 20}, 1e-9) > 10);
    EXPECT_NEAR(p11m.clearance({100, 23}, 1e-9), 3, 1e-9);  // half way to its mirror image
}

// A closed band: the period is adjusted to divide its length, and images across its ends are
// kept (they finish the elements that cross them).
TEST(TranslationGroup, ClosedBandAdjustsThePeriod) {
    const Region band = Region::from_spec("rect:310,40");
    const TranslationSetup s = frieze_setup({"p1", 60}, band, 310.0);
    EXPECT_NEAR(s.period, 310.0 / 5, 1e-12);
    ASSERT_TRUE(s.box);
    EXPECT_LT(s.box->bounds().x0, 0);
    EXPECT_GT(s.box->bounds().x1, 310);
}

TEST(TranslationGroup, BadGroupsAreUsageErrors) {
    const Region band = Region::from_spec("rect:300,40");
    EXPECT_THROW(frieze_setup({"p4m", 60}, band, std::nullopt), UsageError);
    EXPECT_THROW(frieze_setup({"p1", 0}, band, std::nullopt), UsageError);
    EXPECT_THROW(wallpaper_setup({"p6m", 60, 60, 90}), UsageError);  // not hexagonal
    EXPECT_THROW(wallpaper_setup({"p4", 60, 50, 90}), UsageError);   // not square
}

namespace {

std::string describe(const Element& e) {
    const Rect b = e.proxy(0).bounds();
    std::string out = std::to_string(e.id) + " (" + e.type().name + " at " +
                      std::to_string(b.center().x) + "," + std::to_string(b.center().y) + " size " +
                      std::to_string(b.width());
    if (e.parent) out += " parent " + std::to_string(e.parent->id);
    if (const ImageElement* image = as_image(e)) {
        const auto m = image->transform().matrix();
        out += ", image of " + std::to_string(image->original().id) + " by [";
        for (double v : m) out += std::to_string(v) + " ";
        out += "]";
    }
    return out + ")";
}

// The expert's rules: every image that lies wholly in `inside` of every element is an element
// of the same type (1e-6 of the panel), and no two dots overlap.
void expect_invariant(const std::vector<const Element*>& elements, const SymmetryGroup& g,
                      const Rect& inside, const std::string& what) {
    const double tol = 1e-6 * std::max(inside.width(), inside.height());
    long images = 0;
    for (const Element* e : elements) {
        if (as_image(*e)) ++images;
        for (const Isometry& t : g.transforms()) {
            ImageElement image(*e, t);
            bool in = true;
            for (std::size_t k = 0; k < image.proxy_count(); ++k) {
                const Rect r = image.proxy(k).bounds();
                in = in && r.x0 >= inside.x0 && r.y0 >= inside.y0 && r.x1 <= inside.x1 &&
                     r.y1 <= inside.y1;
            }
            if (!in) continue;
            bool found = false;
            for (const Element* f : elements)
                found = found || (&f->type() == &e->type() && same_place(image, *f, tol));
            ASSERT_TRUE(found) << what << ": an image of element " << e->id << " is missing";
        }
    }
    EXPECT_GT(images, 0) << what;
    // Two elements may overlap only as the rule placed them: two fundamental elements, or their
    // images under one transformation (as without symmetry, dots placed against a parent that
    // is not the nearest element to C may overlap another: the rule's business).
    auto transform_of = [](const Element& e) {
        const ImageElement* image = as_image(e);
        return image ? image->transform() : Isometry{};
    };
    for (std::size_t i = 0; i < elements.size(); ++i)
        for (std::size_t j = i + 1; j < elements.size(); ++j) {
            const Element& a = *elements[i];
            const Element& b = *elements[j];
            if (a.type().name == "seed" || b.type().name == "seed") continue;
            const auto ma = transform_of(a).matrix(), mb = transform_of(b).matrix();
            bool same = true;
            for (int k = 0; k < 6; ++k) same = same && std::abs(ma[k] - mb[k]) < 1e-9;
            if (same) continue;
            for (std::size_t p = 0; p < a.proxy_count(); ++p)
                for (std::size_t q = 0; q < b.proxy_count(); ++q)
                    ASSERT_FALSE(overlaps(a.proxy(p), b.proxy(q), tol))
                        << what << ": elements " << describe(a) << " and " << describe(b)
                        << " overlap";
        }
}

}  // namespace

class FriezeGrowth : public ::testing::TestWithParam<std::string> {};

TEST_P(FriezeGrowth, DotsAreInvariantAndFreeOfOverlap) {
    const Region band = Region::from_spec("rect:240,50");
    GrowthOptions o = test::small_options();
    o.resolution = 200;
    o.frieze = Frieze{GetParam(), 60};
    ::dots::dot_count = 0;
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, band, o);
    engine.run();
    const auto elements = engine.elements();
    ASSERT_GT(elements.size(), 40u);
    const SymmetryGroup g(frieze_setup(*o.frieze, band, std::nullopt).group, band);
    expect_invariant(elements, g, band.bounds(), "frieze " + GetParam());
    for (const Element* e : elements)
        for (std::size_t k = 0; k < e->proxy_count(); ++k)
            ASSERT_FALSE(leaves_region(e->proxy(k), band, 1e-6)) << "element " << e->id;
    ::dots::dot_count = 0;
    GrowthEngine again(pattern, band, o);
    again.run();
    EXPECT_EQ(test::snapshot(again), test::snapshot(engine));
}

INSTANTIATE_TEST_SUITE_P(Friezes, FriezeGrowth, ::testing::ValuesIn(kFriezes));

// A frieze on a rectangle fills it to both ends: the largest stretch of x that no element
// covers, at either end, is no longer than the largest element (8 periods of p2mm exactly, the
// docs' border's proportions).
TEST(FriezeGrowth, FillsToBothEnds) {
    const double length = 628.3;
    const Region band = Region::from_spec("rect:628.3,70");
    GrowthOptions o = test::small_options();
    o.resolution = 320;
    o.frieze = Frieze{"p2mm", 78.5375};
    ::dots::dot_count = 0;
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, band, o);
    engine.run();
    const auto elements = engine.elements();
    ASSERT_GT(elements.size(), 40u);
    double largest = 0, first = length, last = 0;
    for (const Element* e : elements)
        for (std::size_t k = 0; k < e->proxy_count(); ++k) {
            const Rect b = e->proxy(k).bounds();
            largest = std::max({largest, b.width(), b.height()});
            first = std::min(first, b.x0);
            last = std::max(last, b.x1);
        }
    EXPECT_LE(first, largest) << "the band's left end is left empty";
    EXPECT_GE(last, length - largest) << "the band's right end is left empty";
}

class WallpaperGrowth : public ::testing::TestWithParam<std::string> {};

TEST_P(WallpaperGrowth, DotsAreInvariantAndFreeOfOverlapAcrossTheSeams) {
    const Wallpaper w = wallpaper_of(GetParam());
    const Region tile = tile_region(w);
    GrowthOptions o = test::small_options();
    o.resolution = 100;
    o.wallpaper = w;
    ::dots::dot_count = 0;
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, tile, o);
    engine.run();
    const auto elements = engine.elements();
    ASSERT_GT(elements.size(), 40u);
    const TranslationSetup s = wallpaper_setup(w);
    const SymmetryGroup g(s.group, *s.box);
    // The tile's bounds: every image there is present, the 3 x 3 repeat included (the box).
    expect_invariant(elements, g, tile.bounds(), "wallpaper " + GetParam());
    ::dots::dot_count = 0;
    GrowthEngine again(pattern, tile, o);
    again.run();
    EXPECT_EQ(test::snapshot(again), test::snapshot(engine));
}

INSTANTIATE_TEST_SUITE_P(Wallpapers, WallpaperGrowth, ::testing::ValuesIn(kWallpapers));

// A closed band (wrap_x): x is periodic with the band's length; every element crossing an end
// has its translate by the length across the other, and the images keep the adjusted period.
TEST(FriezeGrowth, ClosedBandIsSeamless) {
    const Region band = Region::from_spec("rect:310,50");
    GrowthOptions o = test::small_options();
    o.resolution = 240;
    o.frieze = Frieze{"p2", 60};
    o.wrap_x = 310;
    ::dots::dot_count = 0;
    const Pattern pattern = ::dots::pattern();
    GrowthEngine engine(pattern, band, o);
    engine.run();
    const auto elements = engine.elements();
    ASSERT_GT(elements.size(), 40u);
    const TranslationSetup s = frieze_setup(*o.frieze, band, o.wrap_x);
    const SymmetryGroup g(s.group, *s.box);
    expect_invariant(elements, g, s.box->bounds(), "closed band p2");
    // Seamless: each element within the band's ends has its translates by +-L where they
    // stay in the box (the translations by the length are in the group: 310 / 62 = 5 periods).
    const double tol = 1e-6 * 310;
    long crossing = 0;
    for (const Element* e : elements) {
        const Rect b = e->proxy(0).bounds();
        if (b.x0 < 0 && b.x1 > 0) ++crossing;
    }
    EXPECT_GT(crossing, 0) << "no element crosses the seam at x = 0";
    for (const Element* e : elements) {
        const Rect b = e->proxy(0).bounds();
        if (b.x0 < 0 || b.x1 > 310) continue;
        for (double dx : {-310.0, 310.0}) {
            ImageElement image(*e, Isometry{1, 0, 0, 1, dx, 0});
            const Rect r = image.proxy(0).bounds();
            if (r.x0 < s.box->bounds().x0 || r.x1 > s.box->bounds().x1) continue;
            bool found = false;
            for (const Element* f : elements)
                found = found || (&f->type() == &e->type() && same_place(image, *f, tol));
            ASSERT_TRUE(found) << "the translate of element " << e->id << " by " << dx;
        }
    }
}
