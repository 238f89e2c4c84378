#include "neighbourhood_match.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace acanthus::growth::detail {

std::vector<int> ccw_from_widest_gap(const std::vector<Vector>& offsets) {
    std::vector<int> order(offsets.size());
    std::iota(order.begin(), order.end(), 0);
    if (order.size() < 2) return order;
    auto angle = [&](int i) { return std::atan2(offsets[i].y, offsets[i].x); };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return angle(a) < angle(b); });
    std::size_t start = 0;
    double widest = -1;
    for (std::size_t k = 0; k < order.size(); ++k) {
        double from = angle(order[k]);
        double to = angle(order[(k + 1) % order.size()]);
        double gap = to - from;
        if (gap <= 0) gap += 2 * M_PI;
        if (gap > widest) {
            widest = gap;
            start = (k + 1) % order.size();
        }
    }
    std::rotate(order.begin(), order.begin() + static_cast<long>(start), order.end());
    return order;
}

double alignment_error(const std::vector<RingEntry>& target,
                       const std::vector<RingEntry>& reference, int shift, double rotation,
                       const Weights& w) {
    const std::size_t m = reference.size();
    double error = 0;
    for (std::size_t i = 0; i < target.size(); ++i) {
        const RingEntry& t = target[i];
        const RingEntry& r = reference[(static_cast<std::size_t>(shift) + i) % m];
        error += w.w1 * (t.offset - r.offset.rotated(rotation)).length();
        if (t.symbol >= 0 && t.symbol != r.symbol) error += w.w2;
        if (t.sub >= 0 && t.sub == r.sub) error += w.w3;
    }
    return error;
}

double alignment_error_within(const std::vector<RingEntry>& target, const RingEntry* reference,
                              std::size_t m, int shift, double cos_r, double sin_r,
                              const Weights& w, double bound) {
    double error = 0;
    for (std::size_t i = 0; i < target.size(); ++i) {
        const RingEntry& t = target[i];
        const RingEntry& r = reference[(static_cast<std::size_t>(shift) + i) % m];
        const Vector turned{cos_r * r.offset.x - sin_r * r.offset.y,
                            sin_r * r.offset.x + cos_r * r.offset.y};
        error += w.w1 * (t.offset - turned).length();
        if (t.symbol >= 0 && t.symbol != r.symbol) error += w.w2;
        if (t.sub >= 0 && t.sub == r.sub) error += w.w3;
        if (error > bound) return INFINITY;
    }
    return error;
}

double best_fit_rotation(const std::vector<RingEntry>& target,
                         const std::vector<RingEntry>& reference, int shift) {
    // argmin over theta of sum |t - R(theta) r|^2 = atan2(sum r x t, sum r . t).
    double s = 0, c = 0;
    for (std::size_t i = 0; i < target.size(); ++i) {
        const Vector& r =
            reference[(static_cast<std::size_t>(shift) + i) % reference.size()].offset;
        s += r.cross(target[i].offset);
        c += r.dot(target[i].offset);
    }
    return s == 0 && c == 0 ? 0.0 : std::atan2(s, c);
}

RingMatch match_ring(const std::vector<RingEntry>& target, const std::vector<RingEntry>& reference,
                     const Weights& w, bool rotate, double rotation) {
    RingMatch best;
    if (target.size() > reference.size()) return best;
    if (target.empty()) return {0.0, 0, rotation};
    for (int k = 0; k < static_cast<int>(reference.size()); ++k) {
        double turn = rotate ? best_fit_rotation(target, reference, k) : rotation;
        double error = alignment_error(target, reference, k, turn, w);
        if (error < best.error) best = {error, k, turn};
    }
    return best;
}

double outer_ring_error(const std::vector<OuterEntry>& target,
                        const std::vector<OuterEntry>& reference, double rotation, double reach,
                        const Weights& w) {
    // Symbols only: position is the 1-ring's job, and summing a dozen position residuals here
    // outweighed the 1-ring's symbol evidence (tricolour got worse; measured in bench/growth).
    const double c = std::cos(rotation), s = std::sin(rotation);
    double error = 0;
    for (const OuterEntry& t : target) {
        double nearest = reach;
        int symbol = -2;  // none within reach
        for (const OuterEntry& r : reference) {
            Vector turned{c * r.offset.x - s * r.offset.y, s * r.offset.x + c * r.offset.y};
            double d = (t.offset - turned).length();
            if (d < nearest) {
                nearest = d;
                symbol = r.symbol;
            }
        }
        if (symbol == -2 || (t.symbol >= 0 && symbol != t.symbol)) error += w.w2;
    }
    return error;
}

RingMatch match_two_ring(const std::vector<RingEntry>& target,
                         const std::vector<RingEntry>& reference,
                         const std::vector<OuterEntry>& target_outer,
                         const std::vector<OuterEntry>& reference_outer, const Weights& w,
                         bool rotate, double rotation, double reach, double bound) {
    RingMatch best;
    if (target.size() > reference.size()) return best;
    const int shifts = target.empty() ? 1 : static_cast<int>(reference.size());
    for (int k = 0; k < shifts; ++k) {
        double turn =
            rotate && !target.empty() ? best_fit_rotation(target, reference, k) : rotation;
        double error = alignment_error(target, reference, k, turn, w);
        if (error >= std::min(bound, best.error)) continue;
        error += outer_ring_error(target_outer, reference_outer, turn, reach, w);
        if (error < best.error) best = {error, k, turn};
    }
    return best;
}

RingMatch match_by_position(const std::vector<RingEntry>& target,
                            const std::vector<RingEntry>& reference, const Weights& w, double reach,
                            std::vector<int>& slots) {
    slots.assign(target.size(), -1);
    if (target.size() > reference.size()) return {};
    std::vector<double> taken(reference.size(), INFINITY);  // distance of the target holding it
    std::vector<int> holder(reference.size(), -1);
    std::vector<double> nearest(target.size(), INFINITY);
    for (std::size_t i = 0; i < target.size(); ++i) {
        int best = -1;
        for (std::size_t k = 0; k < reference.size(); ++k) {
            double d = (target[i].offset - reference[k].offset).length();
            if (d < nearest[i]) {
                nearest[i] = d;
                best = static_cast<int>(k);
            }
        }
        if (best < 0 || nearest[i] > reach || !(nearest[i] < taken[best])) continue;
        if (holder[best] >= 0) slots[holder[best]] = -1;
        holder[best] = static_cast<int>(i);
        taken[best] = nearest[i];
        slots[i] = best;
    }
    double error = 0;
    for (std::size_t i = 0; i < target.size(); ++i) {
        const RingEntry& t = target[i];
        if (slots[i] < 0) {
            error += w.w2 + w.w1 * (std::isfinite(nearest[i]) ? nearest[i] : t.offset.length());
            continue;
        }
        const RingEntry& r = reference[static_cast<std::size_t>(slots[i])];
        error += w.w1 * (t.offset - r.offset).length();
        if (t.symbol >= 0 && t.symbol != r.symbol) error += w.w2;
        if (t.sub >= 0 && t.sub == r.sub) error += w.w3;
    }
    return {error, 0, 0.0};
}

}  // namespace acanthus::growth::detail
