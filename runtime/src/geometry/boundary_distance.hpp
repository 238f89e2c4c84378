// Signed distance to a set of boundary curves, and a certified search for where a curve gets
// farther than a threshold from them (docs/regions.md, "Exact boundary tests").
#pragma once

#include <2geom/curve.h>
#include <2geom/path.h>
#include <2geom/point.h>
#include <2geom/rect.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/spatial_index.hpp"

namespace acanthus::detail {

class BoundaryDistance {
  public:
    // Where the signed distance is positive; empty means everywhere (unsigned distance).
    using Side = std::function<bool(Geom::Point)>;

    struct Nearest {
        double distance = INFINITY;
        std::size_t curve = 0;  // index into curves()
        Geom::Point foot;       // nearest boundary point
    };

    BoundaryDistance(std::vector<const Geom::Curve*> curves, Side positive_side = {});

    Nearest nearest(Geom::Point p) const;
    bool positive(Geom::Point p) const { return !side_ || side_(p); }
    double signed_distance(Geom::Point p) const {
        double d = nearest(p).distance;
        return positive(p) ? d : -d;
    }
    const std::vector<const Geom::Curve*>& curves() const { return curves_; }
    // Indices of the curves whose fast bounds may meet `box`, ascending (with few curves,
    // all of them).
    std::vector<std::size_t> curves_meeting(const Geom::Rect& box) const;
    // Whether the fast bounds of any curve meet `box` (then some curve may pass through it).
    bool any_curve_meets(const Geom::Rect& box) const;
    // Calls f(index) for those curves; with few curves, no list is built (hot in growth).
    template <class F>
    void for_each_curve_meeting(const Geom::Rect& box, F&& f) const {
        if (!index_) {
            for (std::size_t i = 0; i < curves_.size(); ++i) f(i);
            return;
        }
        for (std::size_t i : curves_meeting(box)) f(i);
    }

  private:
    // Past this many curves, queries go through an R-tree of their bounds instead of a scan.
    static constexpr std::size_t kIndexedFrom = 64;

    std::vector<const Geom::Curve*> curves_;
    std::vector<Geom::Rect> bounds_;
    std::shared_ptr<const SpatialIndex> index_;
    Side side_;
};

struct ExcursionOptions {
    // Split the curve at its intersections with the boundary and skip negative pieces.
    bool split_at_crossings = true;
    // Report (nearly) the first excursion along the range instead of any: a witness within
    // about the threshold (in arc length) of the first place the curve exceeds it.
    bool first = false;
    // With `first`: walk the range backwards, from its end.
    bool from_end = false;
    // Evaluation budget; when spent the search reports no excursion (a contact so close to
    // the threshold along so long a stretch that it counts as touching).
    std::size_t max_evaluations = 200000;
};

// A time t of `curve` in [from, to] where target.signed_distance(curve(t)) > threshold, or
// nothing when the curve stays within the threshold (up to the floating point resolution).
std::optional<double> find_excursion(const Geom::Curve& curve, double from, double to,
                                     const BoundaryDistance& target, double threshold,
                                     const ExcursionOptions& options = {});

// The same over a path between two path times (curve index + t).
std::optional<Geom::PathTime> find_excursion(const Geom::Path& path, Geom::PathTime from,
                                             Geom::PathTime to, const BoundaryDistance& target,
                                             double threshold,
                                             const ExcursionOptions& options = {});
// Over a whole path (including a closing segment).
std::optional<Geom::PathTime> find_excursion(const Geom::Path& path, const BoundaryDistance& target,
                                             double threshold,
                                             const ExcursionOptions& options = {});

// A lower bound on the distance from p to the curve, cheap next to nearestTime(): for a
// Bézier, p's distance to the convex hull of its control points; for other curves, to their
// fast bounds.
double curve_distance_lower_bound(const Geom::Curve& c, Geom::Point p);

// The curves of a path; a closed path (or any path `as_closed`, as region subpaths are)
// includes its closing segment when that is not degenerate.
std::vector<const Geom::Curve*> path_curves(const Geom::Path& path, bool as_closed = false);

}  // namespace acanthus::detail
