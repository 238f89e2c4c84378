// The placed elements of a growing ornament: owns them in placement order (id = index) and
// answers the geometric questions of the growth loop and of rule bodies through a spatial
// index of proxy bounds (broad phase) and the exact tests of overlap.hpp.
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <cstdint>
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
    // The same for many elements in order, indexed in one pass (a bulk placement). Those from
    // `deferrable_from` on whose bounds miss the near zone (set_near_zone()) are indexed only
    // when a query reaches beyond the zone. `bounds`, when given, receives the bounds of the
    // elements from `deferrable_from` on, in order (the caller's own tests need them too).
    // `far`, when given, flags (from `deferrable_from` on) elements the caller knows to miss
    // the near zone: they are deferred without the zone's test.
    std::vector<Element*> add_all(std::vector<std::unique_ptr<Element>> elements,
                                  std::size_t deferrable_from = static_cast<std::size_t>(-1),
                                  std::vector<Rect>* bounds = nullptr,
                                  const std::vector<std::uint8_t>* far = nullptr);
    // The zone the growth loop's queries mostly stay in (under symmetry: round the fundamental
    // domain): `cells` (row by row, `columns` wide) flags the cells of side `cell` from
    // `origin` in it. A query within it needs no element whose bounds miss it.
    void set_near_zone(Point origin, double cell, int columns, const std::vector<bool>& cells);
    std::size_t size() const { return elements_.size(); }
    Element& at(int id) const { return *elements_[static_cast<std::size_t>(id)]; }
    std::vector<const Element*> view() const;
    double tolerance() const { return tolerance_; }
    // Proxies in the spatial index (deferred elements not yet indexed are not counted).
    std::size_t indexed() const { return index_.size(); }
    // Frees the spatial index once the growth is over: the queries below answer nothing after.
    void release_index() {
        index_ = SpatialIndex();
        buckets_.clear();
        waiting_.clear();
        deferred_ = 0;
    }

    // Placed element nearest to p and its distance (ties to the smallest id), or null. The
    // search looks within `hint` first and widens fourfold until it finds one.
    std::pair<Element*, double> nearest(Point p, double hint = 0) const;
    // The same search, returning every element within the radius that found one, by
    // (distance, id), and that radius in `covered` (0 when none did: the nearest alone).
    // `likely`: a radius the nearest element is probably within; the search widens to it
    // before it widens fourfold. Elements farther than the nearest by more than `slack` may be
    // left out.
    std::vector<std::pair<Element*, double>> nearest_within(Point p, double hint, double* covered,
                                                            double likely = 0,
                                                            double slack = INFINITY) const;
    // Placed elements within `radius` of p with their distances, by (distance, id); with
    // `slack`, only those within it of the nearest one (the others' distances are not measured).
    std::vector<std::pair<Element*, double>> within(Point p, double radius,
                                                    double slack = INFINITY) const;

    // True when the proxy overlaps a placed proxy or leaves the region. Throws
    // std::invalid_argument for a proxy that is not set or not finite.
    bool intersects(const Proxy& p) const;
    bool intersects(const Element& e) const;
    // True when the proxy overlaps a placed proxy of an element `which` accepts.
    bool overlaps_any(const Proxy& p, const std::function<bool(const Element&)>& which) const;
    // Calls `visit` for each placed element with a proxy whose bounds meet `box` (once per such
    // proxy).
    void for_each_meeting(const Rect& box, const std::function<void(const Element&)>& visit) const;

  private:
    // The near zone as a summed-area table of its cells: (columns + 1) x (rows + 1).
    struct Zone {
        Point origin;
        double cell = 0;
        int columns = 0, rows = 0;
        std::vector<int> sums;
        // Cells in [i0, i1] x [j0, j1] of the zone, clamped to the grid.
        int count(int i0, int j0, int i1, int j1) const;
        bool covers(const Rect& box) const;
        bool meets(const Rect& box) const;
    };
    // Indexes the deferred elements whose bounds may meet `box`, unless it lies within the
    // near zone.
    void cover(const Rect& box) const;
    // The buckets of deferred elements a box meets, [i0, i1] x [j0, j1]: squares of
    // kBucketCells zone cells, those beyond the zone's grid in its edge buckets.
    static constexpr int kBucketCells = 8;
    void buckets_of(const Rect& box, int& i0, int& j0, int& i1, int& j1) const;

    const Region& region_;
    double tolerance_;
    std::vector<std::unique_ptr<Element>> elements_;
    // Deferred elements are indexed when a query beyond the zone reaches their bucket (const
    // queries): the images far from the domain that no query reaches are never indexed.
    mutable detail::SpatialIndex index_;
    mutable std::vector<std::vector<int>> buckets_;  // the ids deferred there, row by row
    int buckets_w_ = 0, buckets_h_ = 0;
    mutable std::vector<std::uint8_t> waiting_;  // per id: deferred and not indexed yet
    mutable std::size_t deferred_ = 0;           // how many are waiting
    Zone zone_;
};

}  // namespace acanthus::detail
