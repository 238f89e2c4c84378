#include "guided_panel.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::growth::detail {
namespace {

double distance_to_segment(Point p, Point a, Point b) {
    Vector ab = b - a;
    double len2 = ab.dot(ab);
    double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * t);
}

// Proper or touching crossing of segments pq and ab.
bool segments_meet(Point p, Point q, Point a, Point b) {
    auto side = [](Point o, Point u, Point v) { return (u - o).cross(v - o); };
    double d1 = side(a, b, p), d2 = side(a, b, q), d3 = side(p, q, a), d4 = side(p, q, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    // Collinear or touching: an end point on the other segment.
    return distance_to_segment(p, a, b) == 0 || distance_to_segment(q, a, b) == 0 ||
           distance_to_segment(a, p, q) == 0 || distance_to_segment(b, p, q) == 0;
}

}  // namespace

GuidedPanel::GuidedPanel(const Panel& base, const Options& options) : base_(base) {
    for (const auto& line : options.boundary_strokes)
        for (std::size_t i = 1; i < line.size(); ++i) boundary_.push_back({line[i - 1], line[i]});
    for (const Options::Spray& s : options.spray_strokes) {
        if (s.points.size() == 1) spray_.push_back({s.points[0], s.points[0], s.width / 2});
        for (std::size_t i = 1; i < s.points.size(); ++i)
            spray_.push_back({s.points[i - 1], s.points[i], s.width / 2});
    }
}

bool GuidedPanel::contains(Point p) const {
    if (!base_.contains(p)) return false;
    if (spray_.empty()) return true;
    return std::any_of(spray_.begin(), spray_.end(), [&](const Segment& s) {
        return distance_to_segment(p, s.a, s.b) <= s.half_width;
    });
}

bool GuidedPanel::admits(Circle motif, double tolerance) const {
    if (!base_.admits(motif, tolerance)) return false;
    return std::none_of(boundary_.begin(), boundary_.end(), [&](const Segment& s) {
        return distance_to_segment(motif.center, s.a, s.b) < motif.radius - tolerance;
    });
}

bool GuidedPanel::reaches(Point from, Point to) const {
    return std::none_of(boundary_.begin(), boundary_.end(),
                        [&](const Segment& s) { return segments_meet(from, to, s.a, s.b); });
}

}  // namespace acanthus::growth::detail
