// Sakurai & Miyata section 4: sparse Poisson-disk placement with bounding circles (4.2), then
// rounds of |P| candidates drawn from Q, where a pixel joins Q with probability d^n of the
// normalized distance field (4.3).
#include <algorithm>
#include <cmath>

#include "gap_field.hpp"
#include "methods.hpp"

namespace acanthus::dartfill {
namespace {

// d^n from q = d^2 (q in [0, 1]): q^(n/2), by squaring when n/2 is a small integer.
double power_of_distance(double q, double exponent) {
    double half = exponent / 2;
    if (half == std::floor(half) && half >= 0 && half <= 64) {
        double result = 1, base = q;
        for (auto e = static_cast<unsigned>(half); e; e >>= 1) {
            if (e & 1u) result *= base;
            base *= base;
        }
        return result;
    }
    return std::pow(q, half);
}

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

std::vector<int> draw_candidates(const GapField& gaps, double exponent, Random& random) {
    std::vector<int> q;
    std::int64_t max = gaps.max_squared_distance();
    if (max == 0) return q;
    double inv = 1.0 / static_cast<double>(max);
    // Squared distances are integers up to max: tabulate alpha once per round. Pixels with
    // alpha below 1e-12 are skipped without drawing: over a million pixels they would add a
    // candidate once in a million rounds.
    std::vector<double> alpha(static_cast<std::size_t>(max) + 1);
    for (std::int64_t d2 = 0; d2 <= max; ++d2)
        alpha[d2] = d2 == 0 ? 0.0 : power_of_distance(static_cast<double>(d2) * inv, exponent);
    for (int i = 0, n = gaps.size(); i < n; ++i) {
        std::int64_t d2 = std::min(gaps.squared_distance(i), max);
        double a = alpha[d2];
        if (a >= 1e-12 && random.uniform() < a) q.push_back(i);
    }
    return q;
}

void fill_gap(FillContext& context, Layout& layout, long& rounds) {
    sparse_placement(context, layout);
    const Options& options = context.options();
    GapField gaps(context.container(), layout, context.resolution());
    Random& random = context.random();
    long cancellations = 0;
    while (cancellations < options.gap_cancellations && !context.full(layout)) {
        std::vector<int> q = draw_candidates(gaps, options.exponent, random);
        if (q.empty()) break;
        ++rounds;
        // P: |P| members of Q chosen uniformly without replacement.
        auto count = std::min<std::size_t>(
            static_cast<std::size_t>(std::max(options.candidates, 1)), q.size());
        for (std::size_t k = 0; k < count; ++k) {
            auto j = static_cast<std::size_t>(random.uniform_int(
                static_cast<long long>(k), static_cast<long long>(q.size()) - 1));
            std::swap(q[k], q[j]);
        }
        std::vector<std::int64_t> drawn(count);
        for (std::size_t k = 0; k < count; ++k) drawn[k] = gaps.squared_distance(q[k]);
        for (std::size_t k = 0; k < count; ++k) {
            // A placement earlier in this round covered the candidate or narrowed its gap: it no
            // longer stands for the gap it was drawn from, and the next round redraws there.
            if (gaps.squared_distance(q[k]) != drawn[k]) continue;
            // The candidate point receives the shape's pole (its most interior point); for a
            // concave shape the bounding-box centre may lie in a notch, outside the shape.
            Point point = gaps.point_in(q[k], random.uniform(), random.uniform());
            Pose pose = context.random_pose(point);
            pose.position = point - context.pole_offset(pose);
            if (const PlacedShape* placed = context.try_place(layout, pose)) {
                gaps.add(*placed);
                cancellations = 0;
                if (context.full(layout)) break;
            } else if (++cancellations >= options.gap_cancellations) {
                break;
            }
        }
    }
}

}  // namespace acanthus::dartfill
