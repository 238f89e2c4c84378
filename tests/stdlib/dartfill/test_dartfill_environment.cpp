// dartfill inside a rule body: the space is the room a (fake) growth engine leaves. With
// Environment::region() set, dartfill screens candidates with the region's own rings and asks the
// engine far less often; the result must still clear the engine's elements and stay in the panel.
#include <gtest/gtest.h>

#include <acanthus/environment.hpp>
#include <acanthus/partial_picture.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/dartfill.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "container.hpp"
#include "dartfill_oracle.hpp"
#include "methods.hpp"
#include "proxy/overlap.hpp"

using namespace acanthus;
using namespace acanthus::dartfill;
using acanthus::detail::distance_to;
using acanthus::detail::leaves_region;
using acanthus::detail::overlaps;

namespace {

struct Disc : Element {
    CircleProxy p0;
    const ElementType& type() const override {
        static const ElementType t{"disc", {ProxyKind::circle}, nullptr, nullptr, 0};
        return t;
    }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

// The queries of the growth engine over a region and a few discs, counting engine tests.
class FakeEnvironment : public Environment {
  public:
    // `discs`: false for a panel with nothing placed in it.
    FakeEnvironment(const Region& region, bool expose_region, bool discs = true)
        : region_(region), expose_(expose_region) {
        if (!discs) return;
        Rect b = region.bounds();
        Point c = b.center();
        for (auto [dx, dy, r] :
             {std::tuple{-0.3, -0.2, 9.0}, {0.25, 0.1, 14.0}, {0.0, 0.35, 6.0}}) {
            auto d = std::make_unique<Disc>();
            d->p0.set({c.x + dx * b.width(), c.y + dy * b.height()}, r);
            discs_.push_back(std::move(d));
        }
    }

    const std::vector<std::unique_ptr<Disc>>& discs() const { return discs_; }
    long engine_tests() const { return tests_; }

    Circle goal() const override { return {region_.bounds().center(), 5}; }
    bool intersects(const Element& e) const override {
        for (std::size_t k = 0; k < e.proxy_count(); ++k)
            if (intersects(e.proxy(k))) return true;
        return false;
    }
    bool intersects(const Proxy& p) const override {
        ++tests_;
        if (leaves_region(p, region_, 1e-6)) return true;
        for (const auto& d : discs_)
            if (overlaps(p, d->p0, 1e-6)) return true;
        return false;
    }
    bool inside(Point p) const override { return region_.contains(p); }
    double distance_to_boundary(Point p) const override { return region_.distance_to_boundary(p); }
    Element* nearest_element(Point p) const override {
        Element* best = nullptr;
        double dist = std::numeric_limits<double>::infinity();
        for (const auto& d : discs_) {
            double t = distance_to(d->p0, p);
            if (t < dist) {
                dist = t;
                best = d.get();
            }
        }
        return best;
    }
    void clear_exclude_list() override {}
    Random& random() override { return random_; }
    const Region* region() const override { return expose_ ? &region_ : nullptr; }

  private:
    const Region& region_;
    bool expose_;
    std::vector<std::unique_ptr<Disc>> discs_;
    mutable long tests_ = 0;
    Random random_{7};
};

ShapeSet leaves() {
    ShapeSet set;
    set.add_path("leaf", "M 0 0 C 5 -7 15 -7 20 0 C 15 7 5 7 0 0 Z");
    set.add_points("c", {{0, 0}, {12, 0}, {12, 3}, {3, 3}, {3, 9}, {12, 9}, {12, 12}, {0, 12}});
    return set;
}

void expect_clear(const FillResult& r, const Region& region, const FakeEnvironment& env) {
    for (std::size_t i = 0; i < r.placements.size(); ++i) {
        const auto& outline = r.placements[i].outline;
        for (Point v : outline)
            ASSERT_TRUE(region.contains(v) || region.distance_to_boundary(v) < 1e-6)
                << "placement " << i << " leaves the panel";
        for (const auto& d : env.discs()) {
            Point c = d->p0.center;
            bool inside = dartfill_oracle::in_ring(outline, c);
            double gap = dartfill_oracle::distance_to_ring(outline, c);
            ASSERT_FALSE(inside) << "placement " << i << " covers a disc centre";
            ASSERT_GE(gap, d->p0.radius - 1e-6) << "placement " << i << " overlaps a disc";
        }
        for (std::size_t j = i + 1; j < r.placements.size(); ++j)
            ASSERT_LT(dartfill_oracle::intersection_area(outline, r.placements[j].outline), 1e-6)
                << "placements " << i << " and " << j << " overlap";
    }
}

Options options_for(Method method, int resolution) {
    Options o;
    o.method = method;
    o.resolution = resolution;
    o.naive_cancellations = 300;
    o.scale_min = 0.6;
    o.scale_max = 1.0;
    return o;
}

FillResult fill_in(FakeEnvironment& env, Method method, int resolution = 96) {
    Environment::Scope scope(&env);
    return fill(leaves(), options_for(method, resolution));
}

}  // namespace

class DartfillEnvironment : public ::testing::TestWithParam<Method> {};

TEST_P(DartfillEnvironment, WithTheRegionTheFillClearsElementsAndStaysInThePanel) {
    Region region = Region::from_spec("ellipse:70,50");
    FakeEnvironment env(region, true);
    FillResult r = fill_in(env, GetParam());
    EXPECT_GT(r.placements.size(), 15u);
    expect_clear(r, region, env);
    EXPECT_GT(r.stats.space_area, 0.8 * (M_PI * 70 * 50 - M_PI * (81 + 196 + 36)));
    EXPECT_LT(r.stats.space_area, 1.05 * M_PI * 70 * 50);
}

TEST_P(DartfillEnvironment, TheRegionPathIsDeterministic) {
    Region region = Region::from_spec("circle:45");
    FakeEnvironment one(region, true), two(region, true);
    FillResult a = fill_in(one, GetParam());
    FillResult b = fill_in(two, GetParam());
    ASSERT_EQ(a.placements.size(), b.placements.size());
    for (std::size_t i = 0; i < a.placements.size(); ++i)
        EXPECT_EQ(a.placements[i].outline, b.placements[i].outline);
}

INSTANTIATE_TEST_SUITE_P(All, DartfillEnvironment,
                         ::testing::Values(Method::naive, Method::fill_gap, Method::medial),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(DartfillEnvironmentPaths, WithoutTheRegionEveryTestGoesToTheEngine) {
    Region region = Region::from_spec("ellipse:70,50");
    FakeEnvironment fast(region, true), slow(region, false);
    // A coarse grid: without the region every pixel costs the engine an exact curve test.
    FillResult a = fill_in(fast, Method::fill_gap, 40);
    FillResult b = fill_in(slow, Method::fill_gap, 40);
    EXPECT_GT(b.placements.size(), 15u);
    expect_clear(b, region, slow);
    // The slow path asks the engine about every pixel and every candidate; the fast one only
    // about candidates that already fit the panel and dartfill's own shapes.
    EXPECT_LT(fast.engine_tests() * 5, slow.engine_tests())
        << "fast " << fast.engine_tests() << ", slow " << slow.engine_tests();
    // Both see about the same room.
    EXPECT_NEAR(a.stats.space_area, b.stats.space_area, 0.1 * b.stats.space_area);
}

// In a hole of a symmetric ornament too small for the shapes at the options' scale (0.6 to 1:
// the leaf 12 long, the square's diagonal 10.2, in a disc of radius 5), the fill halves them
// until some fit; elsewhere it places none.
TEST(DartfillEnvironmentPaths, InAHoleOfASymmetricOrnamentSmallerShapesFill) {
    Region region = Region::from_spec("circle:5");
    FakeEnvironment panel(region, true, false), hole(region, true, false);
    EXPECT_TRUE(fill_in(panel, Method::fill_gap).placements.empty());
    Environment::Scope scope(&hole);
    const FillResult r = fill_room(leaves(), options_for(Method::fill_gap, 96), hole, true);
    ASSERT_FALSE(r.placements.empty());
    for (const Placement& p : r.placements) {
        EXPECT_GE(p.scale, 0.15 - 1e-9);
        EXPECT_LE(p.scale, 0.5 + 1e-9);
    }
    expect_clear(r, region, hole);
}

// A fill reports the shapes it placed so far (report_partial) for the program's partial
// pictures: each report has one more, made by dartfill.acr's maker as elements with the
// outlines the finished fill returns, in its order; the result is the same with the reports.
struct Piece : Element {
    PolygonProxy p0;
    int shape = 0;
    double rotation = 0, scale = 0;
    const ElementType& type() const override {
        static const ElementType t{"aggregate", {ProxyKind::polygon}, nullptr, nullptr, 0};
        return t;
    }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

TEST(DartfillPartialPictures, EachReportHasTheShapesPlacedSoFar) {
    Region region = Region::from_spec("circle:45");
    FakeEnvironment plain_env(region, true), env(region, true);
    const FillResult plain = fill_in(plain_env, Method::fill_gap);

    struct Seen {
        std::vector<long> placed;
        std::vector<std::vector<std::vector<Point>>> outlines;
    } seen;
    acanthus::detail::set_partial_handler(
        [](void* context, long placed, const PartialElements& extra) {
            Seen& s = *static_cast<Seen*>(context);
            std::vector<const Element*> made;
            extra(made);
            s.placed.push_back(placed);
            s.outlines.emplace_back();
            for (const Element* e : made) {
                s.outlines.back().push_back(static_cast<const Piece*>(e)->p0.points);
                delete e;
            }
        },
        &seen);
    dartfill::detail::set_partial_maker(
        [](const Placement& p) -> const Element* { return new_aggregate<Piece>(p); });
    const FillResult reported = fill_in(env, Method::fill_gap);
    acanthus::detail::set_partial_handler(nullptr, nullptr);
    dartfill::detail::set_partial_maker(nullptr);

    ASSERT_EQ(reported.placements.size(), plain.placements.size());
    for (std::size_t i = 0; i < plain.placements.size(); ++i)
        EXPECT_EQ(reported.placements[i].outline, plain.placements[i].outline);
    ASSERT_EQ(seen.placed.size(), plain.placements.size());
    for (std::size_t k = 0; k < seen.placed.size(); ++k) {
        EXPECT_EQ(seen.placed[k], static_cast<long>(k + 1));
        ASSERT_EQ(seen.outlines[k].size(), k + 1);
        EXPECT_EQ(seen.outlines[k].back(), plain.placements[k].outline);
    }
}

// Without a maker (a fill outside a rule file that imports dartfill), nothing is reported.
TEST(DartfillPartialPictures, NoMakerNoReport) {
    Region region = Region::from_spec("circle:45");
    FakeEnvironment env(region, true);
    long reports = 0;
    acanthus::detail::set_partial_handler(
        [](void* context, long, const PartialElements&) { ++*static_cast<long*>(context); },
        &reports);
    fill_in(env, Method::fill_gap);
    acanthus::detail::set_partial_handler(nullptr, nullptr);
    EXPECT_EQ(reports, 0);
}
