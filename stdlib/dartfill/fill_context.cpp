#include <acanthus/partial_maker.hpp>
#include <acanthus/partial_picture.hpp>
#include <acanthus/progress.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "methods.hpp"

namespace acanthus::dartfill {

FillContext::FillContext(const std::vector<Shape>& shapes, const Container& container,
                         const Options& options, Random& random)
    : shapes_(shapes), container_(container), options_(options), random_(random) {
    Rect b = container.bounds();
    tolerance_ =
        options.tolerance >= 0 ? options.tolerance : 1e-6 * std::max(b.width(), b.height());
}

int FillContext::resolution() const {
    if (options_.resolution > 0) return options_.resolution;
    double smallest = std::numeric_limits<double>::infinity();
    for (const Shape& s : shapes_)
        smallest = std::min({smallest, s.bounds().width(), s.bounds().height()});
    Rect b = container_.bounds();
    double pixels = std::max(b.width(), b.height()) / (smallest * options_.scale_min / 8);
    return static_cast<int>(std::clamp(std::isfinite(pixels) ? pixels : 1024.0, 64.0, 1024.0));
}

Vector FillContext::pole_offset(const Pose& pose) const {
    const Shape& shape = shapes_[cycle_];
    return (shape.pole() - shape.center()).rotated(pose.rotation) * pose.scale;
}

Pose FillContext::random_pose(Point position) {
    Pose pose;
    pose.position = position;
    pose.rotation = random_.uniform(options_.rotation_min, options_.rotation_max);
    pose.scale = random_.uniform(options_.scale_min, options_.scale_max);
    return pose;
}

const PlacedShape* FillContext::try_place(Layout& layout, const Pose& pose) {
    return fits(layout, pose) ? place(layout, pose) : nullptr;
}

bool FillContext::fits(const Layout& layout, const Pose& pose) {
    ++trials_;
    PlacedShape candidate(shapes_[cycle_], cycle_, pose);
    // The layout test is cheap; the container's may ask the growth engine (exact curve tests).
    return !layout.collides(candidate) && container_.admits(candidate, tolerance_);
}

const PlacedShape* FillContext::place(Layout& layout, const Pose& pose) {
    layout.add(PlacedShape(shapes_[cycle_], cycle_, pose));
    cycle_ = (cycle_ + 1) % static_cast<int>(shapes_.size());
    // A whole fill is one rule body: each placement is progress to the watchdog.
    report_progress("shapes", static_cast<long>(layout.shapes().size()), options_.max_elements);
    // The shapes so far, for a partial picture while the fill goes on (the elements are made
    // only by the copy of the program that draws it).
    if (detail::PartialMaker make = detail::partial_maker())
        report_partial(static_cast<long>(layout.shapes().size()),
                       [&layout, make](std::vector<const Element*>& out) {
                           for (const PlacedShape& s : layout.shapes())
                               out.push_back(make(placement_of(s)));
                       });
    return &layout.shapes().back();
}

bool FillContext::full(const Layout& layout) const {
    return options_.max_elements > 0 &&
           static_cast<long>(layout.shapes().size()) >= options_.max_elements;
}

Placement placement_of(const PlacedShape& s) {
    const Pose& pose = s.pose();
    return {s.shape_index(), pose.position, pose.rotation, pose.scale, s.area(), s.outline()};
}

namespace detail {

namespace {
PartialMakerSlot<Placement> g_partial_maker;
}  // namespace

bool set_partial_maker(PartialMaker maker) noexcept { return g_partial_maker.set(maker); }
PartialMaker partial_maker() noexcept { return g_partial_maker.get(); }

}  // namespace detail

}  // namespace acanthus::dartfill
