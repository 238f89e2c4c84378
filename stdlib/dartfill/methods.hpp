// The three placement methods over one shared trial: transform a shape, test it exactly against
// the space and the shapes placed so far, keep it or cancel it.
#pragma once

#include <acanthus/environment.hpp>
#include <acanthus/random.hpp>
#include <acanthus/stdlib/dartfill.hpp>
#include <vector>

#include "container.hpp"
#include "layout.hpp"

namespace acanthus::dartfill {

// fill(shapes, options) in the room the running body's environment leaves; `in_hole`: the
// environment offers a hole of a symmetric ornament (detail::filling_hole()), where the shapes
// are halved, at most twice, while none fits.
FillResult fill_room(const ShapeSet& shapes, const Options& options, Environment& env,
                     bool in_hole);

class FillContext {
  public:
    FillContext(const std::vector<Shape>& shapes, const Container& container,
                const Options& options, Random& random);

    const std::vector<Shape>& shapes() const { return shapes_; }
    const Container& container() const { return container_; }
    const Options& options() const { return options_; }
    Random& random() { return random_; }
    double tolerance() const { return tolerance_; }
    // Distance-field pixels on the longer side: the option, or when it is 0, enough for the
    // smallest shape at the smallest scale to span about eight pixels (64 to 1024).
    int resolution() const;

    // The shape the cycle is at: it advances on every placement so that each shape is placed
    // equally often (section 3.2).
    int current_shape() const { return cycle_; }
    // Where the current shape's pole lies relative to pose.position under the pose.
    Vector pole_offset(const Pose& pose) const;
    // Random rotation and scale within the options' ranges.
    Pose random_pose(Point position);
    // One placement trial of the current shape; on success the shape joins `layout`, the cycle
    // advances and a pointer to the placed shape is returned, else null.
    const PlacedShape* try_place(Layout& layout, const Pose& pose);
    // The parts of try_place: an exact test of the current shape at `pose` (counted as a
    // trial), and committing a pose that fits.
    bool fits(const Layout& layout, const Pose& pose);
    const PlacedShape* place(Layout& layout, const Pose& pose);
    // Counts a trial cancelled before try_place (e.g. by a bounding-circle test).
    void count_cancelled_trial() { ++trials_; }
    bool full(const Layout& layout) const;
    long trials() const { return trials_; }

  private:
    const std::vector<Shape>& shapes_;
    const Container& container_;
    const Options& options_;
    Random& random_;
    double tolerance_;
    int cycle_ = 0;
    long trials_ = 0;
};

// What fill() returns of a placed shape.
Placement placement_of(const PlacedShape& s);

namespace detail {
// dartfill.acr's maker of partial pictures' elements, or null (set_partial_maker).
PartialMaker partial_maker() noexcept;
}  // namespace detail

// Section 3.2: darts at uniform positions until `naive_cancellations` consecutive cancellations.
void naive_dart_throwing(FillContext& context, Layout& layout);
// Section 4: Poisson-disk sparse placement, then one round of |P| candidates drawn by d^n from
// the distance field per placed shape.
void fill_gap(FillContext& context, Layout& layout, long& rounds);
// Candidates at ridge maxima of the distance field, largest gap first, several rotations each.
void medial_fill(FillContext& context, Layout& layout, long& rounds);

}  // namespace acanthus::dartfill
