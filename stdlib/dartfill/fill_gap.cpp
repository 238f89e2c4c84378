// Sakurai & Miyata section 4: sparse Poisson-disk placement with bounding circles (4.2), then
// rounds of |P| candidates drawn from Q, where a pixel joins Q with probability d^n of the
// normalized distance field (4.3).
#include <algorithm>
#include <cmath>

#include "candidate_sampler.hpp"
#include "gap_field.hpp"
#include "methods.hpp"

namespace acanthus::dartfill {
namespace {

void sparse_placement(FillContext& context, Layout& layout) {
    Rect b = context.container().bounds();
    long cancellations = 0;
    while (cancellations < context.options().sparse_cancellations && !context.full(layout)) {
        Point position{context.random().uniform(b.x0, b.x1), context.random().uniform(b.y0, b.y1)};
        Pose pose = context.random_pose(position);
        const Shape& shape = context.shapes()[context.current_shape()];
        if (layout.circle_collides({position, shape.radius() * pose.scale})) {
            context.count_cancelled_trial();
            ++cancellations;
        } else if (context.try_place(layout, pose)) {
            cancellations = 0;
        } else {
            ++cancellations;
        }
    }
}

}  // namespace

void fill_gap(FillContext& context, Layout& layout, long& rounds) {
    sparse_placement(context, layout);
    const Options& options = context.options();
    GapField gaps(context.container(), layout, context.resolution());
    CandidateSampler sampler(gaps);
    Random& random = context.random();
    std::vector<int> changed;
    long cancellations = 0;
    // One round per exclusive region placed: "we prepared the set of candidate points P where the
    // exclusive region could be placed ... our method specified the number of P to 100, thereby
    // limiting the number of consecutive cancellations to 100" (section 4). A round ends at the
    // first candidate that fits; the field is updated and the next region gets a fresh P. A round
    // whose every candidate fails is followed by a fresh draw from the same field, until
    // `gap_cancellations` consecutive cancellations (200, section 4) end the fill.
    while (cancellations < options.gap_cancellations && !context.full(layout)) {
        std::vector<int> candidates = sampler.draw(options.exponent, options.candidates, random);
        if (candidates.empty()) break;
        ++rounds;
        for (int pixel : candidates) {
            // The candidate point receives the centre of transformation, as every placement
            // does: "The center of transformation is the center of the bounding box of an
            // exclusive region" (3.1); "The value of T is determined by the position of a
            // placed point" (4.2). The point is jittered within its pixel.
            Point point = gaps.point_in(pixel, random.uniform(), random.uniform());
            Pose pose = context.random_pose(point);
            if (const PlacedShape* placed = context.try_place(layout, pose)) {
                changed.clear();
                gaps.add(*placed, &changed);
                sampler.update(changed);
                cancellations = 0;
                break;
            }
            if (++cancellations >= options.gap_cancellations) break;
        }
    }
}

}  // namespace acanthus::dartfill
