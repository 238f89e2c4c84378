// The placed elements of a growing ornament: owns them in placement order (id = index) and
// answers the geometric questions of the growth loop and of rule bodies through a spatial
// index of proxy bounds (broad phase) and the exact tests of overlap.hpp.
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/region.hpp>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/spatial_index.hpp"

namespace acanthus::detail {

class Ornament {
  public:
    // `tolerance` (user units): touching closer than this is not overlap.
    Ornament(const Region& region, double tolerance);
    Ornament(const Ornament&) = delete;
    Ornament& operator=(const Ornament&) = delete;

    // Takes ownership, assigns the next id and indexes the proxies; returns the element.
    Element& add(std::unique_ptr<Element> e);
    // The same for many elements in order, indexed in one pass (a bulk placement).
    std::vector<Element*> add_all(std::vector<std::unique_ptr<Element>> elements);
    std::size_t size() const { return elements_.size(); }
    Element& at(int id) const { return *elements_[static_cast<std::size_t>(id)]; }
    std::vector<const Element*> view() const;
    double tolerance() const { return tolerance_; }
    // Frees the spatial index once the growth is over: the queries below answer nothing after.
    void release_index() { index_ = SpatialIndex(); }

    // Placed element nearest to p and its distance (ties to the smallest id), or null. The
    // search looks within `hint` first and widens fourfold until it finds one.
    std::pair<Element*, double> nearest(Point p, double hint = 0) const;
    // The same search, returning every element within the radius that found one, by
    // (distance, id), and that radius in `covered` (0 when none did: the nearest alone).
    // `likely`: a radius the nearest element is probably within; the search widens to it
    // before it widens fourfold.
    std::vector<std::pair<Element*, double>> nearest_within(Point p, double hint, double* covered,
                                                            double likely = 0) const;
    // Placed elements within `radius` of p with their distances, by (distance, id).
    std::vector<std::pair<Element*, double>> within(Point p, double radius) const;

    // True when the proxy overlaps a placed proxy or leaves the region. Throws
    // std::invalid_argument for a proxy that is not set or not finite.
    bool intersects(const Proxy& p) const;
    bool intersects(const Element& e) const;
    // True when the proxy overlaps a placed proxy of an element `which` accepts.
    bool overlaps_any(const Proxy& p, const std::function<bool(const Element&)>& which) const;

  private:
    const Region& region_;
    double tolerance_;
    std::vector<std::unique_ptr<Element>> elements_;
    detail::SpatialIndex index_;
};

}  // namespace acanthus::detail
