// Arc-length parameterization of edges [3.2]: segments are lines or exact circular arcs.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>

namespace acanthus::cells {

double Segment::length() const { return arc ? radius * std::abs(sweep) : distance(a, b); }

Point Segment::at(double s) const {
    double len = length();
    double u = len > 0 ? std::clamp(s / len, 0.0, 1.0) : 0.0;
    if (!arc) return lerp(a, b, u);
    double angle = start + sweep * u;
    return {center.x + radius * std::cos(angle), center.y + radius * std::sin(angle)};
}

Vector Segment::tangent(double s) const {
    if (!arc) return (b - a).normalized();
    double len = length();
    double angle = start + sweep * (len > 0 ? std::clamp(s / len, 0.0, 1.0) : 0.0);
    Vector t{-std::sin(angle), std::cos(angle)};
    return sweep >= 0 ? t : -t;
}

double Segment::project(Point p) const {
    if (!arc) {
        Vector d = b - a;
        double l2 = d.dot(d);
        double u = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
        return u * std::sqrt(l2);
    }
    double angle = std::atan2(p.y - center.y, p.x - center.x);
    // The angle along the sweep, in [0, |sweep|] when on the arc; else the nearer end.
    double rel = (angle - start) * (sweep >= 0 ? 1 : -1);
    rel = std::fmod(rel, 2 * M_PI);
    if (rel < 0) rel += 2 * M_PI;
    double span = std::abs(sweep);
    if (rel > span) rel = (rel - span < 2 * M_PI - rel) ? span : 0.0;
    return rel * radius;
}

namespace {
std::size_t segment_at(const Edge& e, double s) {
    auto it = std::upper_bound(e.offsets.begin(), e.offsets.end(), s);
    std::size_t i =
        it == e.offsets.begin() ? 0 : static_cast<std::size_t>(it - e.offsets.begin()) - 1;
    return std::min(i, e.segments.size() - 1);
}
}  // namespace

Point Edge::at(double s) const {
    std::size_t i = segment_at(*this, s);
    return segments[i].at(s - offsets[i]);
}

Vector Edge::tangent(double s) const {
    std::size_t i = segment_at(*this, s);
    return segments[i].tangent(s - offsets[i]);
}

Vector Edge::inward(double s) const {
    Vector t = tangent(s);
    return interior_left ? t.perp() : -t.perp();
}

namespace {
// A lower bound of the distance from p to any point Segment::at gives: the distance to the
// segment's box (an arc's: its ends and the axis extremes it sweeps over), widened a little for
// the rounding of at().
double box_distance(const Segment& seg, Point p) {
    double x0 = std::min(seg.a.x, seg.b.x), x1 = std::max(seg.a.x, seg.b.x);
    double y0 = std::min(seg.a.y, seg.b.y), y1 = std::max(seg.a.y, seg.b.y);
    double scale = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
    if (seg.arc) {
        // Not every arc's `a` and `b` are at() of its ends to the last bit: take those too.
        Point e0 = seg.at(0), e1 = seg.at(seg.length());
        x0 = std::min({x0, e0.x, e1.x}), x1 = std::max({x1, e0.x, e1.x});
        y0 = std::min({y0, e0.y, e1.y}), y1 = std::max({y1, e0.y, e1.y});
        double lo = std::min(seg.start, seg.start + seg.sweep);
        double hi = std::max(seg.start, seg.start + seg.sweep);
        for (double k = std::ceil(lo / (M_PI / 2)); k * (M_PI / 2) <= hi; ++k) {
            switch (((static_cast<long>(k) % 4) + 4) % 4) {
                case 0:
                    x1 = std::max(x1, seg.center.x + seg.radius);
                    break;
                case 1:
                    y1 = std::max(y1, seg.center.y + seg.radius);
                    break;
                case 2:
                    x0 = std::min(x0, seg.center.x - seg.radius);
                    break;
                default:
                    y0 = std::min(y0, seg.center.y - seg.radius);
                    break;
            }
        }
        scale = std::max(scale, std::abs(seg.center.x) + std::abs(seg.center.y) + seg.radius);
    }
    double margin = 1e-9 * (scale + 1);
    double dx = std::max({x0 - p.x, p.x - x1, 0.0});
    double dy = std::max({y0 - p.y, p.y - y1, 0.0});
    return std::max(0.0, std::hypot(dx, dy) - margin);
}
}  // namespace

double Edge::project(Point p) const {
    // The nearest box's segment first; then only segments whose box is no farther than the best
    // distance so far. The same answer as trying all: the least distance, the first segment on
    // a tie.
    const std::size_t n = segments.size();
    std::size_t first = 0;
    double first_box = 1e300;
    if (n > 1)
        for (std::size_t i = 0; i < n; ++i) {
            double b = box_distance(segments[i], p);
            if (b < first_box) first_box = b, first = i;
        }
    double best = 0, best_d = 1e300;
    std::size_t best_i = n;
    auto try_segment = [&](std::size_t i) {
        double s = segments[i].project(p);
        double d = distance(segments[i].at(s), p);
        if (d < best_d || (d == best_d && i < best_i)) {
            best_d = d;
            best = offsets[i] + s;
            best_i = i;
        }
    };
    if (n > 0) try_segment(first);
    for (std::size_t i = 0; i < n; ++i)
        if (i != first && (n == 1 || box_distance(segments[i], p) <= best_d)) try_segment(i);
    return best;
}

bool Edge::vertical() const {
    Vector chord = segments.back().b - segments.front().a;
    if (closed || chord.length() < 1e-12) return false;
    return std::abs(chord.y) > std::abs(chord.x);
}

}  // namespace acanthus::cells
