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

double Edge::project(Point p) const {
    double best = 0, best_d = 1e300;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        double s = segments[i].project(p);
        double d = distance(segments[i].at(s), p);
        if (d < best_d) {
            best_d = d;
            best = offsets[i] + s;
        }
    }
    return best;
}

bool Edge::vertical() const {
    Vector chord = segments.back().b - segments.front().a;
    if (closed || chord.length() < 1e-12) return false;
    return std::abs(chord.y) > std::abs(chord.x);
}

}  // namespace acanthus::cells
