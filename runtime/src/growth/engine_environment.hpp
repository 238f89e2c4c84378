// The Environment a rule body sees while the growth engine runs it: the goal circle C and the
// queries of the support library, answered by the ornament, the region and the exclude list.
#pragma once

#include <acanthus/environment.hpp>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>

#include "growth/exclude_list.hpp"
#include "growth/ornament.hpp"

namespace acanthus::detail {

class GrowthEnvironment : public Environment {
  public:
    GrowthEnvironment(const Region& region, const Ornament& ornament, ExcludeList& exclude,
                      std::uint64_t rng_seed)
        : region_(region), ornament_(ornament), exclude_(exclude), random_(rng_seed) {}

    void set_goal(Circle c) { goal_ = c; }

    Circle goal() const override { return goal_; }
    bool intersects(const Element& e) const override { return ornament_.intersects(e); }
    bool intersects(const Proxy& p) const override { return ornament_.intersects(p); }
    bool inside(Point p) const override { return region_.contains(p); }
    double distance_to_boundary(Point p) const override { return region_.distance_to_boundary(p); }
    Element* nearest_element(Point p) const override { return ornament_.nearest(p).first; }
    void clear_exclude_list() override { exclude_.clear(); }
    Random& random() override { return random_; }
    const Region* region() const override { return &region_; }

  private:
    const Region& region_;
    const Ornament& ornament_;
    ExcludeList& exclude_;
    Random random_;
    Circle goal_;
};

}  // namespace acanthus::detail
