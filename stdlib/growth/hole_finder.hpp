// Where growth restarts when its front dies: the largest empty circle that can hold a motif,
// searched on a grid of sample points over the panel. Only samples reached from a start without
// crossing a boundary stroke count, so the tools keep growth on its side.
#pragma once

#include <acanthus/point.hpp>
#include <vector>

#include "arrangement.hpp"
#include "panel.hpp"

namespace acanthus::growth::detail {

struct Hole {
    Point center;
    double radius = 0;  // distance to the nearest placed motif's centre
};

class HoleFinder {
  public:
    // `spacing`: the reference's nearest-neighbour distance; `motif_radius`: the smallest motif
    // that may go in a hole; `max_samples`: the grid is coarser beyond it (each asks the panel).
    HoleFinder(const Panel& panel, const std::vector<Point>& starts, double spacing,
               double motif_radius, double tolerance, double max_samples = 2.5e5);

    // The sample that can hold a motif farthest from every placed node (ties: deepest in the
    // panel), when its distance reaches `at_least`; samples nearer than that are done for good.
    bool find(const Arrangement& pattern, double at_least, Hole& hole);
    // Never offer this sample's neighbourhood again (a restart there placed nothing).
    void exclude(Point p, double radius);
    // Samples set aside because a motif was near are asked again: relaxation moves motifs, so
    // one may have left. Excluded samples stay out.
    void reopen_covered();
    // The largest empty circle over all samples that can hold a motif (0 when none).
    double largest(const Arrangement& pattern);

  private:
    struct Sample {
        Point at;
        double depth = -1;     // panel clearance, for ties (-1: not asked yet)
        signed char fits = 0;  // a motif fits here: 1 yes, -1 no, 0 not asked yet
        bool open = true;
        bool excluded = false;
    };
    class Placed;  // the placed motifs' centres, for nearest queries
    // Asked of the panel only for samples that could win: most never are.
    bool fits(Sample& s) const;
    double depth(Sample& s) const;

    const Panel& panel_;
    double spacing_, motif_radius_, tolerance_;
    std::vector<Sample> samples_;  // reached from a start, in grid order
};

}  // namespace acanthus::growth::detail
