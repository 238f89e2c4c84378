// The question the empty-circle search asks before it hands out a circle: does a point that
// must not lie inside C (the growth loop's exclude list) lie inside this one? The search keeps
// no such points itself.
#pragma once

#include <acanthus/point.hpp>

namespace acanthus::detail {

class CircleBlocker {
  public:
    // Id of a point strictly inside the circle, or -1 when there is none. Ids name the points
    // when they are removed again (CircleSource::release()).
    virtual int blocker_inside(const Circle& c) const = 0;

  protected:
    ~CircleBlocker() = default;
};

}  // namespace acanthus::detail
