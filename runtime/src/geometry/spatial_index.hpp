// Broad phase over placed proxies: axis-aligned bounds -> (element, proxy), on a Boost.Geometry
// R-tree with linear splits (growth inserts once per proxy, images by the thousand: R*
// insertion cost several times more for little faster queries, quadratic splits more than
// linear ones with no faster growth). Exact tests (overlaps, distance_to) are the caller's;
// every result order is deterministic (ties broken by element, then proxy).
#pragma once

#include <acanthus/point.hpp>
#include <compare>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace acanthus::detail {

class SpatialIndex {
  public:
    struct Entry {
        int element = -1;
        int proxy = -1;
        auto operator<=>(const Entry&) const = default;
    };
    struct Hit {
        Entry entry;
        double distance = 0;
    };

    SpatialIndex();
    // Bulk-loaded (packed) from all entries at once, far faster than inserting one by one.
    // Throws std::invalid_argument as insert() does.
    explicit SpatialIndex(const std::vector<std::pair<Entry, Rect>>& entries);
    SpatialIndex(SpatialIndex&&) noexcept;
    SpatialIndex& operator=(SpatialIndex&&) noexcept;
    ~SpatialIndex();

    // Throws std::invalid_argument for non-finite or inverted bounds.
    void insert(int element, int proxy, Rect bounds);
    // Inserts all the entries; as many as the index holds already or more, it is packed anew
    // from the old and the new entries at once. Throws as insert() does, inserting nothing.
    void insert_all(const std::vector<std::pair<Entry, Rect>>& entries);
    void clear();
    std::size_t size() const;

    // Entries whose bounds intersect `box` (touching counts), sorted by (element, proxy).
    std::vector<Entry> query(Rect box) const;
    // True when `test` holds for an entry whose bounds intersect `box` (touching counts). Stops
    // at the first; entries are visited in the tree's order, so `test` should have no effects.
    bool any_of(Rect box, const std::function<bool(Entry)>& test) const;
    // Entries whose bounds come within `radius` of p, sorted by (element, proxy).
    std::vector<Entry> within(Point p, double radius) const;
    // The same entries with the distance from p to their bounds, by (that distance, element,
    // proxy).
    std::vector<Hit> within_by_distance(Point p, double radius) const;
    // The k entries with the nearest bounds to p, by (bounds distance, element, proxy).
    std::vector<Entry> nearest(Point p, std::size_t k) const;
    // The entry minimizing the caller's exact distance (e.g. distance_to(proxy, p), which is
    // never less than the distance to the bounds). Bounds are visited nearest first until one
    // is farther than the best found; ties go to the smallest (element, proxy). Entries whose
    // distance is NaN or infinite (filtered out by the caller) are skipped.
    std::optional<Hit> nearest_entry(Point p, const std::function<double(Entry)>& distance) const;

  private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace acanthus::detail
