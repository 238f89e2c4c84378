// The Environment a rule body sees while the growth engine runs it: the goal circle C and the
// queries of the support library, answered by the ornament, the region and the exclude list.
#pragma once

#include <acanthus/environment.hpp>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <functional>

#include "growth/exclude_list.hpp"
#include "growth/ornament.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/orbit.hpp"
#include "symmetry/symmetric_core.hpp"
#include "symmetry/symmetry_group.hpp"

namespace acanthus::detail {

class GrowthEnvironment : public Environment {
  public:
    GrowthEnvironment(const Region& region, const Ornament& ornament, ExcludeList& exclude,
                      std::uint64_t rng_seed, const SymmetryGroup* group = nullptr,
                      const Region* const* core_region = nullptr)
        : region_(region),
          ornament_(ornament),
          exclude_(exclude),
          random_(rng_seed),
          group_(group),
          core_region_(core_region) {}

    void set_goal(Circle c) { goal_ = c; }

    Circle goal() const override { return goal_; }
    // Under symmetry the placed elements include their images, and an element also intersects
    // when one of its own images overlaps it or leaves the region: the region is its core.
    bool intersects(const Element& e) const override {
        if (ornament_.intersects(e)) return true;
        return group_ &&
               count_orbit(orbit_intersects(e, *group_, *core_region_, ornament_.tolerance()));
    }
    bool intersects(const Proxy& p) const override {
        if (ornament_.intersects(p)) return true;
        return group_ &&
               count_orbit(orbit_intersects(p, *group_, *core_region_, ornament_.tolerance()));
    }
    // How many times intersection() said yes only because of the element's own images: a rule
    // that failed so may fit a smaller circle (GrowthEngine tries one).
    long orbit_refusals() const { return orbit_refusals_; }
    // The core is the region itself when the group maps the region onto itself (then no
    // image needs measuring).
    bool inside(Point p) const override {
        return core_differs() ? core_contains(region_, *group_, p) : region_.contains(p);
    }
    double distance_to_boundary(Point p) const override {
        return core_differs() ? core_distance_to_boundary(region_, *group_, p)
                              : region_.distance_to_boundary(p);
    }
    // An image stands for its original (the element a rule body can read).
    Element* nearest_element(Point p) const override {
        Element* e = ornament_.nearest(p).first;
        return e ? &ornament_.at(original_of(*e).id) : nullptr;
    }
    void clear_exclude_list() override { exclude_.clear(); }
    Random& random() override { return random_; }
    // During a restart on a hole (GrowthEngine's centre_seed()) a fill library sees the hole
    // as its panel, and fills it alone rather than the whole region again. The panel is made
    // on the first call (most rules never read it).
    void set_panel(std::function<const Region*()> panel) { panel_ = std::move(panel); }
    const Region* region() const override { return panel_ ? panel_() : &region_; }
    bool symmetric() const override { return group_ != nullptr; }
    bool filling_hole() const { return static_cast<bool>(panel_); }

  private:
    const Region& region_;
    const Ornament& ornament_;
    ExcludeList& exclude_;
    Random random_;
    const SymmetryGroup* group_;
    std::function<const Region*()> panel_;  // set_panel()
    const Region* const* core_region_;      // the engine's: null when images never leave R
    mutable long orbit_refusals_ = 0;
    bool core_differs() const { return group_ && core_region_ && *core_region_; }
    bool count_orbit(bool refused) const {
        if (refused) ++orbit_refusals_;
        return refused;
    }
    Circle goal_;
};

}  // namespace acanthus::detail
