// growth inside a rule body: the panel and the ornament already placed come from the running
// Environment (a fake growth engine here). Motifs must clear its elements and stay in its panel,
// and the engine's random source makes the result repeatable.
#include <gtest/gtest.h>

#include <acanthus/environment.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "growth_fixtures.hpp"
#include "proxy/overlap.hpp"

using namespace acanthus;
using namespace acanthus::growth;
using acanthus::growth::Options;

namespace {

struct SeedPoint : Element {
    PointProxy p0;
    const ElementType& type() const override {
        static const ElementType t{"seed", {ProxyKind::point}, nullptr, nullptr, 0};
        return t;
    }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

struct Disc : Element {
    CircleProxy p0;
    const ElementType& type() const override {
        static const ElementType t{"disc", {ProxyKind::circle}, nullptr, nullptr, 0};
        return t;
    }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

// A region with the seed point synthesis starts on, two discs and a small disc that a motif
// circle could swallow whole; answers through the engine's exact overlap tests.
class FakeEnvironment : public Environment {
  public:
    explicit FakeEnvironment(const Region& region) : region_(region) {
        seed_.p0.set({75, 50});
        for (auto [x, y, r] :
             {std::tuple{40.0, 40.0, 15.0}, {110.0, 70.0, 22.0}, {83.5, 50.3, 0.4}}) {
            auto d = std::make_unique<Disc>();
            d->p0.set({x, y}, r);
            discs_.push_back(std::move(d));
        }
    }
    const std::vector<std::unique_ptr<Disc>>& discs() const { return discs_; }

    Circle goal() const override { return {{75, 50}, 5}; }
    bool intersects(const Element& e) const override {
        for (std::size_t k = 0; k < e.proxy_count(); ++k)
            if (intersects(e.proxy(k))) return true;
        return false;
    }
    bool intersects(const Proxy& p) const override {
        if (acanthus::detail::leaves_region(p, region_, 1e-6)) return true;
        for (const auto& d : discs_)
            if (acanthus::detail::overlaps(p, d->p0, 1e-6)) return true;
        return acanthus::detail::overlaps(p, seed_.p0, 1e-6);
    }
    bool inside(Point p) const override { return region_.contains(p); }
    double distance_to_boundary(Point p) const override { return region_.distance_to_boundary(p); }
    Element* nearest_element(Point p) const override {
        Element* best = const_cast<SeedPoint*>(&seed_);
        double best_d = distance(p, seed_.p0.point());
        for (const auto& d : discs_) {
            double t = acanthus::detail::distance_to(d->p0, p);
            if (t < best_d) best_d = t, best = d.get();
        }
        return best;
    }
    void clear_exclude_list() override {}
    Random& random() override { return random_; }
    const Region* region() const override { return &region_; }
    void reseed(std::uint64_t s) { random_.reseed(s); }

  private:
    const Region& region_;
    SeedPoint seed_;
    std::vector<std::unique_ptr<Disc>> discs_;
    Random random_{7};
};

TEST(GrowthEnvironment, MotifsClearTheOrnamentAndStayInThePanel) {
    Region region = Region::from_spec("rect:150,100");
    FakeEnvironment env(region);
    Reference ref = Reference::from_elements(growth_fixtures::triangular_lattice(7, 7, 8));
    SynthesisResult r;
    {
        Environment::Scope scope(&env);
        r = synthesize(ref, Options{});
    }
    ASSERT_GT(r.motifs.size(), 80u);
    // Starts at the goal's centre, on the seed point, which it replaces.
    EXPECT_EQ(r.motifs.front().position, (Point{75, 50}));
    for (std::size_t i = 0; i < r.motifs.size(); ++i) {
        const Motif& m = r.motifs[i];
        ASSERT_TRUE(region.contains(m.position));
        ASSERT_GE(region.distance_to_boundary(m.position), m.radius - 1e-6) << i;
        for (const auto& d : env.discs())
            ASSERT_GE(distance(m.position, d->p0.center), m.radius + d->p0.radius - 1e-6)
                << "motif " << i << " overlaps a placed element";
        for (std::size_t j = i + 1; j < r.motifs.size(); ++j)
            ASSERT_GE(distance(m.position, r.motifs[j].position),
                      m.radius + r.motifs[j].radius - 1e-6);
    }
}

TEST(GrowthEnvironment, UsesTheProgramsRandomSource) {
    Region region = Region::from_spec("rect:150,100");
    FakeEnvironment env(region);
    Reference ref = Reference::from_elements(growth_fixtures::triangular_lattice(7, 7, 8));
    Options o;
    o.scale_min = 0.7;
    auto run = [&](std::uint64_t seed) {
        env.reseed(seed);
        Environment::Scope scope(&env);
        return synthesize(ref, o, {30, 80});
    };
    SynthesisResult a = run(3), b = run(3), c = run(4);
    ASSERT_EQ(a.motifs.size(), b.motifs.size());
    for (std::size_t i = 0; i < a.motifs.size(); ++i) {
        EXPECT_EQ(a.motifs[i].position, b.motifs[i].position);
        EXPECT_EQ(a.motifs[i].scale, b.motifs[i].scale);
    }
    ASSERT_FALSE(c.motifs.empty());
    EXPECT_NE(a.motifs.front().scale, c.motifs.front().scale);
}

TEST(GrowthEnvironment, OutsideARuleBodyIsALogicError) {
    Reference ref = Reference::from_elements(growth_fixtures::triangular_lattice(4, 4, 8));
    EXPECT_THROW(synthesize(ref, Options{}), std::logic_error);
}

}  // namespace
