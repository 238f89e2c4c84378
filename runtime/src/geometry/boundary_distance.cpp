#include "geometry/boundary_distance.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "geometry/curve_intersection.hpp"

namespace acanthus::detail {

BoundaryDistance::BoundaryDistance(std::vector<const Geom::Curve*> curves, Side positive_side)
    : curves_(std::move(curves)), side_(std::move(positive_side)) {
    bounds_.reserve(curves_.size());
    for (const Geom::Curve* c : curves_) bounds_.push_back(c->boundsFast());
    if (curves_.size() >= kIndexedFrom) {
        std::vector<std::pair<SpatialIndex::Entry, Rect>> entries;
        entries.reserve(bounds_.size());
        for (std::size_t i = 0; i < bounds_.size(); ++i) {
            const Geom::Rect& b = bounds_[i];
            entries.push_back(
                {{static_cast<int>(i), 0}, Rect{b.left(), b.top(), b.right(), b.bottom()}});
        }
        index_ = std::make_shared<const SpatialIndex>(entries);
    }
}

std::vector<std::size_t> BoundaryDistance::curves_meeting(const Geom::Rect& box) const {
    std::vector<std::size_t> out;
    if (!index_) {  // few curves: all of them, as the exact tests reject far ones anyway
        out.resize(curves_.size());
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = i;
        return out;
    }
    for (const SpatialIndex::Entry& e :
         index_->query(Rect{box.left(), box.top(), box.right(), box.bottom()}))
        out.push_back(static_cast<std::size_t>(e.element));
    return out;
}

bool BoundaryDistance::any_curve_meets(const Geom::Rect& box) const {
    if (index_)
        return !index_->query(Rect{box.left(), box.top(), box.right(), box.bottom()}).empty();
    for (const Geom::Rect& b : bounds_)
        if (b.intersects(box)) return true;
    return false;
}

BoundaryDistance::Nearest BoundaryDistance::nearest(Geom::Point p) const {
    Nearest best;
    if (index_) {
        // Bounds nearest first; ties go to the lowest index, as in the scan below. A curve whose
        // lower bound is above a distance already found cannot be the nearest, nor tie: it is
        // left unsolved (an infinite distance is skipped).
        double found = INFINITY;
        auto hit = index_->nearest_entry(Point{p[Geom::X], p[Geom::Y]}, [&](SpatialIndex::Entry e) {
            const Geom::Curve& c = *curves_[static_cast<std::size_t>(e.element)];
            if (found < INFINITY && curve_distance_lower_bound(c, p) > found)
                return double{INFINITY};
            const double d = Geom::distance(p, c.pointAt(c.nearestTime(p)));
            found = std::min(found, d);
            return d;
        });
        if (hit) {
            const Geom::Curve& c = *curves_[static_cast<std::size_t>(hit->entry.element)];
            best = {hit->distance, static_cast<std::size_t>(hit->entry.element),
                    c.pointAt(c.nearestTime(p))};
        }
        return best;
    }
    // Nearest bounds first: a curve lies inside its fast bounds, so once a box is farther than
    // the best, no later curve can win; most calls then solve for one or two curves, not all.
    // Ties go to the lowest index, whatever the order.
    thread_local std::vector<std::pair<double, std::size_t>> order;
    order.clear();
    for (std::size_t i = 0; i < curves_.size(); ++i)
        order.emplace_back(Geom::distance(p, bounds_[i]), i);
    std::sort(order.begin(), order.end());
    for (const auto& [box, i] : order) {
        if (box > best.distance) break;
        const Geom::Curve& c = *curves_[i];
        if (best.distance < INFINITY && curve_distance_lower_bound(c, p) > best.distance) continue;
        Geom::Point foot = c.pointAt(c.nearestTime(p));
        double d = Geom::distance(p, foot);
        if (d < best.distance || (d == best.distance && i < best.curve)) best = {d, i, foot};
    }
    return best;
}

std::vector<const Geom::Curve*> path_curves(const Geom::Path& path, bool as_closed) {
    std::vector<const Geom::Curve*> out;
    std::size_t n = as_closed || path.closed() ? path.size_closed() : path.size_open();
    for (std::size_t i = 0; i < n; ++i) out.push_back(&path[i]);
    return out;
}

namespace {

double polyline_length(const std::vector<Geom::Point>& pts) {
    double l = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) l += Geom::distance(pts[i - 1], pts[i]);
    return l;
}

// Points whose convex hull contains curve[a, b]; empty when none is cheaply known.
std::vector<Geom::Point> hull_points(const Geom::Curve& c, double a, double b) {
    if (dynamic_cast<const Geom::BezierCurve*>(&c)) {
        std::unique_ptr<Geom::Curve> part(c.portion(a, b));
        return static_cast<const Geom::BezierCurve&>(*part).controlPoints();
    }
    if (const auto* arc = dynamic_cast<const Geom::EllipticalArc*>(&c)) {
        Geom::Point p0 = c.pointAt(a), p1 = c.pointAt(b);
        if (arc->isChord()) return {p0, p1};
        // A convex arc turning less than a half turn lies in the triangle of its end points
        // and the intersection of its end tangents.
        if (std::abs(arc->sweepAngle()) * (b - a) > 0.9 * M_PI) return {};
        Geom::Point d0 = c.unitTangentAt(a), d1 = c.unitTangentAt(b);
        double denom = Geom::cross(d0, d1);
        if (std::abs(denom) < 1e-12) return {p0, p1};
        double s = Geom::cross(p1 - p0, d1) / denom;
        Geom::Point apex = p0 + d0 * s;
        if (!std::isfinite(apex.x()) || !std::isfinite(apex.y())) return {};
        return {p0, apex, p1};
    }
    return {};
}

// Upper bound of the arc length of curve[a, b].
double length_bound(const Geom::Curve& c, double a, double b,
                    const std::vector<Geom::Point>& hull) {
    if (dynamic_cast<const Geom::BezierCurve*>(&c)) return polyline_length(hull);
    if (const auto* arc = dynamic_cast<const Geom::EllipticalArc*>(&c)) {
        if (arc->isChord()) return Geom::distance(c.pointAt(a), c.pointAt(b));
        return std::abs(arc->sweepAngle()) * (b - a) *
               std::max(arc->ray(Geom::X), arc->ray(Geom::Y));
    }
    std::unique_ptr<Geom::Curve> part(c.portion(a, b));
    return part->length(1e-9) * 1.001 + 1e-12;
}

double segment_distance(Geom::Point p, Geom::Point a, Geom::Point b) {
    Geom::Point ab = b - a;
    double len2 = Geom::dot(ab, ab);
    double t = len2 > 0 ? std::clamp(Geom::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return Geom::distance(p, a + ab * t);
}

// On a degenerate triangle every cross product may be 0: "inside", a bound of 0, still a bound.
bool in_triangle(Geom::Point p, Geom::Point a, Geom::Point b, Geom::Point c) {
    const double d1 = Geom::cross(b - a, p - a), d2 = Geom::cross(c - b, p - b),
                 d3 = Geom::cross(a - c, p - c);
    const bool negative = d1 < 0 || d2 < 0 || d3 < 0;
    const bool positive = d1 > 0 || d2 > 0 || d3 > 0;
    return !(negative && positive);
}

// Distance from c to the convex hull of the points (0 inside).
double hull_distance(Geom::Point c, std::vector<Geom::Point> pts) {
    // Andrew's monotone chain.
    std::sort(pts.begin(), pts.end(), [](Geom::Point a, Geom::Point b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    std::vector<Geom::Point> h;
    for (int pass = 0; pass < 2; ++pass) {
        std::size_t base = h.size();
        for (Geom::Point p : pts) {
            while (h.size() >= base + 2 &&
                   Geom::cross(h[h.size() - 1] - h[h.size() - 2], p - h[h.size() - 2]) <= 0) {
                h.pop_back();
            }
            h.push_back(p);
        }
        h.pop_back();
        std::reverse(pts.begin(), pts.end());
    }
    if (h.size() >= 3) {
        bool inside = true;
        for (std::size_t i = 0; i < h.size() && inside; ++i) {
            inside = Geom::cross(h[(i + 1) % h.size()] - h[i], c - h[i]) >= 0;
        }
        if (inside) return 0;
    }
    double best = INFINITY;
    for (std::size_t i = 0; i < h.size(); ++i) {
        best = std::min(best, segment_distance(c, h[i], h[(i + 1) % h.size()]));
    }
    return h.empty() ? Geom::distance(c, pts.front()) : best;
}

// For a circular arc of at most a half turn whose angular wedge holds every hull point, the
// distance to the arc is the radial distance | |p - c| - r |: convex outside, bounded inside
// by the hull's distance to the centre. Second order near tangency, where the Lipschitz
// bound is only first order.
std::optional<double> arc_hull_bound(const std::vector<Geom::Point>& hull,
                                     const Geom::EllipticalArc& arc) {
    double rx = arc.ray(Geom::X), ry = arc.ray(Geom::Y);
    if (arc.isChord() || std::abs(rx - ry) > 1e-12 * std::max(rx, ry)) return std::nullopt;
    if (std::abs(arc.sweepAngle()) > M_PI) return std::nullopt;
    Geom::Point c = arc.center(), a0 = arc.initialPoint() - c, a1 = arc.finalPoint() - c;
    // Inside the wedge: on the inner side of both bounding rays (orientation by the sweep).
    double sign = arc.sweep() ? 1.0 : -1.0;
    double far = 0;
    for (Geom::Point h : hull) {
        Geom::Point v = h - c;
        if (sign * Geom::cross(a0, v) < 0 || sign * Geom::cross(v, a1) < 0) return std::nullopt;
        far = std::max(far, Geom::L2(v) - rx);
    }
    return std::max(far, rx - hull_distance(c, hull));
}

// Upper bound of the (unsigned, hence also the signed) boundary distance over the hull:
// the distance to one boundary curve is at least the distance to the whole boundary; to a
// segment it is convex, to a fixed foot point it is convex.
double hull_bound(const std::vector<Geom::Point>& hull, const BoundaryDistance& target,
                  const BoundaryDistance::Nearest& n) {
    const Geom::Curve& e = *target.curves()[n.curve];
    double bound = 0;
    if (const auto* seg = dynamic_cast<const Geom::LineSegment*>(&e)) {
        for (Geom::Point h : hull) {
            bound = std::max(bound, segment_distance(h, seg->initialPoint(), seg->finalPoint()));
        }
        return bound;
    }
    for (Geom::Point h : hull) bound = std::max(bound, Geom::distance(h, n.foot));
    if (const auto* arc = dynamic_cast<const Geom::EllipticalArc*>(&e)) {
        if (auto radial = arc_hull_bound(hull, *arc)) bound = std::min(bound, *radial);
    }
    return bound;
}

class PieceSearch {
  public:
    PieceSearch(const Geom::Curve& curve, const BoundaryDistance& target, double threshold,
                const ExcursionOptions& options, std::size_t& evaluations)
        : curve_(curve),
          target_(target),
          threshold_(threshold),
          options_(options),
          evaluations_(evaluations) {
        Geom::Rect box = curve.boundsFast();
        double scale = std::max({1.0, std::abs(box.left()), std::abs(box.right()),
                                 std::abs(box.top()), std::abs(box.bottom())});
        min_length_ = 1e-12 * scale;
    }

    std::optional<double> run(double a, double b) {
        if (options_.from_end) std::swap(a, b);  // a is the near end, b the far end
        Sample sa = sample(a), sb = sample(b);
        if (sa.f > threshold_) return a;
        if (!options_.first && sb.f > threshold_) return b;
        // Witness resolution of the ordered search.
        double resolution = std::max(threshold_, min_length_ * 1e3);
        std::vector<Node> stack{{a, b, sa, sb}};
        while (!stack.empty()) {
            if (evaluations_ >= options_.max_evaluations) return std::nullopt;
            Node n = stack.back();
            stack.pop_back();
            double lo = std::min(n.a, n.b), hi = std::max(n.a, n.b);
            std::vector<Geom::Point> hull = hull_points(curve_, lo, hi);
            double length = length_bound(curve_, lo, hi, hull);
            // The far end exceeding keeps the bound above the threshold, so such a node is
            // refined until it is short enough to report its far end.
            if (options_.first && n.sb.f > threshold_ && length <= resolution) return n.b;
            double bound = (n.sa.f + n.sb.f + length) / 2;
            if (bound <= threshold_) continue;
            if (!hull.empty()) {
                bound = std::min({bound, hull_bound(hull, target_, n.sa.nearest),
                                  hull_bound(hull, target_, n.sb.nearest)});
                if (bound <= threshold_) continue;
            }
            // Shorter than the floating point resolution: the maximum is the threshold itself.
            if (length <= min_length_ || hi - lo <= 1e-15) {
                if (n.sb.f > threshold_) return n.b;
                continue;
            }
            double m = (n.a + n.b) / 2;
            Sample sm = sample(m);
            if (!options_.first && sm.f > threshold_) return m;
            // Pushed last is searched first: the near half.
            stack.push_back(Node{m, n.b, sm, n.sb});
            stack.push_back(Node{n.a, m, n.sa, sm});
        }
        return std::nullopt;
    }

  private:
    struct Sample {
        BoundaryDistance::Nearest nearest;
        double f = 0;
    };
    struct Node {
        double a, b;
        Sample sa, sb;
    };

    Sample sample(double t) {
        ++evaluations_;
        Geom::Point p = curve_.pointAt(t);
        Sample s{target_.nearest(p), 0};
        s.f = target_.positive(p) ? s.nearest.distance : -s.nearest.distance;
        return s;
    }

    const Geom::Curve& curve_;
    const BoundaryDistance& target_;
    double threshold_;
    const ExcursionOptions& options_;
    std::size_t& evaluations_;
    double min_length_ = 0;
};

std::optional<double> search(const Geom::Curve& curve, double from, double to,
                             const BoundaryDistance& target, double threshold,
                             const ExcursionOptions& options, std::size_t& evaluations) {
    if (!(from <= to)) return std::nullopt;
    std::vector<double> cuts{from, to};
    if (options.split_at_crossings) {
        target.for_each_curve_meeting(curve.boundsFast(), [&](std::size_t i) {
            for (const Geom::CurveIntersection& x : intersect_curves(curve, *target.curves()[i])) {
                if (x.first > from && x.first < to) cuts.push_back(x.first);
            }
        });
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    }
    PieceSearch piece(curve, target, threshold, options, evaluations);
    std::size_t pieces = cuts.size() - 1;
    for (std::size_t k = 0; k < pieces; ++k) {
        std::size_t i = options.from_end ? pieces - 1 - k : k;
        double a = cuts[i], b = cuts[i + 1];
        if (options.split_at_crossings) {
            // No crossing inside the piece: it lies on one side; skip the negative side.
            if (!target.positive(curve.pointAt((a + b) / 2))) continue;
        }
        if (auto t = piece.run(a, b)) return t;
    }
    return std::nullopt;
}

}  // namespace

// A Bézier lies inside the convex hull of its control points: outside the hull, the nearest
// hull edge is among the segments between control points (each inside the hull); inside, 0.
// Shaved by a relative 1e-12 so rounding never puts it above the distance nearestTime() finds.
double curve_distance_lower_bound(const Geom::Curve& c, Geom::Point p) {
    const auto* bezier = dynamic_cast<const Geom::BezierCurve*>(&c);
    if (!bezier || bezier->size() > 4) return Geom::distance(p, c.boundsFast());
    const unsigned n = bezier->size();
    Geom::Point q[4];
    for (unsigned i = 0; i < n; ++i) q[i] = (*bezier)[i];
    if (n >= 3 && in_triangle(p, q[0], q[1], q[2])) return 0;
    if (n == 4 && (in_triangle(p, q[0], q[1], q[3]) || in_triangle(p, q[0], q[2], q[3]) ||
                   in_triangle(p, q[1], q[2], q[3]))) {
        return 0;
    }
    double d = INFINITY;
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = i + 1; j < n; ++j) d = std::min(d, segment_distance(p, q[i], q[j]));
    }
    return d * (1 - 1e-12);
}

std::optional<double> find_excursion(const Geom::Curve& curve, double from, double to,
                                     const BoundaryDistance& target, double threshold,
                                     const ExcursionOptions& options) {
    std::size_t evaluations = 0;
    return search(curve, from, to, target, threshold, options, evaluations);
}

std::optional<Geom::PathTime> find_excursion(const Geom::Path& path, Geom::PathTime from,
                                             Geom::PathTime to, const BoundaryDistance& target,
                                             double threshold, const ExcursionOptions& options) {
    std::vector<const Geom::Curve*> curves = path_curves(path);
    if (curves.empty() || to < from) return std::nullopt;
    std::size_t first = from.curve_index, last = std::min(to.curve_index, curves.size() - 1);
    std::size_t evaluations = 0;
    for (std::size_t k = first; k <= last; ++k) {
        std::size_t i = options.from_end ? last - (k - first) : k;
        double a = i == from.curve_index ? from.t : 0.0;
        double b = i == to.curve_index ? to.t : 1.0;
        if (auto t = search(*curves[i], a, b, target, threshold, options, evaluations)) {
            return Geom::PathTime(i, *t);
        }
    }
    return std::nullopt;
}

std::optional<Geom::PathTime> find_excursion(const Geom::Path& path, const BoundaryDistance& target,
                                             double threshold, const ExcursionOptions& options) {
    std::size_t n = path_curves(path).size();
    if (n == 0) return std::nullopt;
    return find_excursion(path, Geom::PathTime(0, 0), Geom::PathTime(n - 1, 1), target, threshold,
                          options);
}

}  // namespace acanthus::detail
