// The exclude list of Wong et al. section 4.1: centres of empty circles on which every rule
// failed. No circle containing one of these points may be chosen as C until a success nearby
// (or a rule body) removes it.
#pragma once

#include <acanthus/point.hpp>
#include <cstddef>
#include <memory>
#include <vector>

#include "field/circle_blocker.hpp"

namespace acanthus::detail {

class ExcludeList final : public CircleBlocker {
  public:
    ExcludeList();
    ~ExcludeList();
    ExcludeList(const ExcludeList&) = delete;
    ExcludeList& operator=(const ExcludeList&) = delete;

    // Adds a point and returns its id (ids count up from 0 and are never reused).
    int add(Point p);
    // Id of a point strictly inside the circle (distance < radius), or -1 when there is none.
    int find_inside(const Circle& c) const;
    bool any_inside(const Circle& c) const { return find_inside(c) >= 0; }
    int blocker_inside(const Circle& c) const override { return find_inside(c); }
    // Removes every point within `epsilon` of p (distance <= epsilon), appending their ids to
    // `removed` when it is not null.
    void remove_within(Point p, double epsilon, std::vector<int>* removed);
    // Removes every point.
    void clear();

    std::size_t size() const;
    // How many times clear() ran, so the engine can notice a rule body clearing the list.
    long clear_count() const { return clears_; }
    // The points in the list, in the order they were added.
    std::vector<Point> points() const;

  private:
    struct Index;
    std::unique_ptr<Index> index_;
    long clears_ = 0;
};

}  // namespace acanthus::detail
