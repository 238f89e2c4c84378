// Overlap rules (tolerance t >= 0, user units). "Depth" of a point in an area is its distance
// to the area's boundary when inside, negative outside.
//
//   point - point, point - curve   never overlap (a point has no extent to share).
//   point - area                   the point is deeper than t inside the area.
//   curve - area                   some point of the curve is deeper than t inside the area
//                                  (circle: the curve comes closer than r - t to the centre).
//                                  A curve touching or grazing the boundary, or ending on it,
//                                  is touching.
//   circle - circle                d < r1 + r2 - t (penetration deeper than t).
//   circle - polygon               D < r - t, or the centre is inside and D > t or r > t,
//                                  with D the centre's distance to the polygon boundary.
//   polygon - polygon              a point of one boundary is deeper than t inside the other,
//                                  or (containment of near-equal shapes) a deep interior point
//                                  of one is deeper than t inside the other.
//   curve - curve                  the curves cross properly: at an exact intersection point,
//                                  each curve goes farther than t from the other on both sides
//                                  of the intersection (before its next intersection or end),
//                                  ending up on opposite sides. Tangency, shared end points,
//                                  T-junctions (a branch starting on a stem) and ends poking
//                                  through by no more than t are touching. Curves running
//                                  along each other without crossing are touching too.
//   leaves_region                  some point of the proxy lies outside the region farther
//                                  than t from its boundary, or (areas) some point of the region
//                                  boundary lies deeper than t inside the proxy (a hole or a
//                                  notch of the panel inside a circle or polygon).
//
// Everything is evaluated on exact lib2geom curves: exact intersections and nearest points,
// winding numbers, and the certified branch and bound of boundary_distance.hpp.
#include "proxy/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/boundary_distance.hpp"
#include "geometry/curve_intersection.hpp"
#include "proxy/proxy_path.hpp"
#include "region/boundary.hpp"
#include "region/region_data.hpp"

namespace acanthus::detail {

namespace {

enum class Category { point, curve, area };

Category category(ProxyKind kind) {
    if (kind == ProxyKind::point) return Category::point;
    return is_area(kind) ? Category::area : Category::curve;
}

// A proxy with its exact curves; polygons also carry their signed boundary distance.
class Shape {
  public:
    explicit Shape(const Proxy& proxy)
        : kind_(proxy.kind()),
          path_(detail::proxy_path(proxy)),
          curves_(detail::path_curves(path_)),
          boundary_(curves_, inside_side()) {
        if (kind_ == ProxyKind::point) point_ = static_cast<const PointProxy&>(proxy).point();
        if (kind_ == ProxyKind::circle) {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            point_ = c.center;
            radius_ = c.radius;
        }
    }
    Shape(const Shape&) = delete;
    Shape& operator=(const Shape&) = delete;

    ProxyKind kind() const { return kind_; }
    Category category() const { return detail::category(kind_); }
    const Geom::Path& path() const { return path_; }
    Point point() const { return point_; }     // point proxy, circle centre
    double radius() const { return radius_; }  // circle
    // Signed distance to the polygon boundary (positive inside).
    const BoundaryDistance& boundary() const { return boundary_; }

    bool inside(Geom::Point p) const {
        if (kind_ == ProxyKind::circle) return Geom::distance(p, to_geom(point_)) < radius_;
        return kind_ == ProxyKind::polygon && path_.winding(p) != 0;
    }
    // Depth of p in this area (negative outside).
    double depth(Geom::Point p) const {
        if (kind_ == ProxyKind::circle) return radius_ - Geom::distance(p, to_geom(point_));
        return boundary_.signed_distance(p);
    }

  private:
    BoundaryDistance::Side inside_side() const {
        return [this](Geom::Point p) { return path_.winding(p) != 0; };
    }

    ProxyKind kind_;
    Geom::Path path_;
    std::vector<const Geom::Curve*> curves_;
    BoundaryDistance boundary_;
    Point point_;
    double radius_ = 0;
};

// path_distance() of a path of one curve, without building the path.
double curve_distance(const Geom::Curve& c, Geom::Point p, double limit) {
    const double box = Geom::distance(p, c.boundsFast());
    if (box > limit) return INFINITY;
    if (limit < INFINITY && detail::curve_distance_lower_bound(c, p) > limit) return INFINITY;
    return Geom::distance(p, c.pointAt(c.nearestTime(p)));
}

double path_distance(const Geom::Path& path, Geom::Point p, double limit = INFINITY) {
    // Nearest bounds first, and none whose bounds are no nearer than the best or beyond `limit`:
    // the same minimum (when it is within the limit) for fewer of lib2geom's nearest-point
    // solves. A box near enough still leaves a Bézier unsolved when its control hull is not.
    thread_local std::vector<std::pair<double, const Geom::Curve*>> order;
    order.clear();
    for (const Geom::Curve* c : detail::path_curves(path))
        order.emplace_back(Geom::distance(p, c->boundsFast()), c);
    std::sort(order.begin(), order.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    double best = INFINITY;
    for (const auto& [box, c] : order) {
        if (box >= best || box > limit) break;
        // Nothing to compare the hull with before a first distance or under no limit.
        if (best < INFINITY || limit < INFINITY) {
            const double hull = detail::curve_distance_lower_bound(*c, p);
            if (hull >= best || hull > limit) continue;
        }
        best = std::min(best, Geom::distance(p, c->pointAt(c->nearestTime(p))));
    }
    return best;
}

// Some point of `curve` lies deeper than tol inside `area`.
bool enters(const Geom::Path& curve, const Shape& area, double tol) {
    if (area.kind() == ProxyKind::circle) {
        const double depth = area.radius() - tol;
        return path_distance(curve, to_geom(area.point()), depth) < depth;
    }
    return detail::find_excursion(curve, area.boundary(), tol).has_value();
}

// A point well inside a polygon: the midpoint of the widest horizontal chord at a few heights.
Geom::Point polygon_witness(const Shape& polygon) {
    Geom::OptRect box = polygon.path().boundsFast();
    Geom::Point best = box ? box->midpoint() : Geom::Point(0, 0);
    double best_depth = -INFINITY;
    if (!box) return best;
    for (double f : {0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875}) {
        double y = box->top() + f * box->height();
        std::vector<double> xs;
        for (const Geom::Curve* c : detail::path_curves(polygon.path())) {
            Geom::Point a = c->initialPoint(), b = c->finalPoint();
            if ((a.y() <= y) != (b.y() <= y)) {
                xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
            }
        }
        std::sort(xs.begin(), xs.end());
        for (std::size_t i = 0; i + 1 < xs.size(); i += 1) {
            Geom::Point m((xs[i] + xs[i + 1]) / 2, y);
            double d = polygon.depth(m);
            if (d > best_depth) {
                best_depth = d;
                best = m;
            }
        }
    }
    return best;
}

bool finite_circle(const CircleProxy& c) {
    return std::isfinite(c.center.x) && std::isfinite(c.center.y) && std::isfinite(c.radius);
}

bool circles_overlap(const Shape& a, const Shape& b, double tol) {
    return distance(a.point(), b.point()) < a.radius() + b.radius() - tol;
}

bool circle_polygon_overlap(const Shape& circle, const Shape& polygon, double tol) {
    Geom::Point c = to_geom(circle.point());
    double d = polygon.boundary().nearest(c).distance;
    if (d < circle.radius() - tol) return true;
    return polygon.inside(c) && std::max(d, circle.radius()) > tol;
}

bool polygons_overlap(const Shape& a, const Shape& b, double tol) {
    if (enters(a.path(), b, tol) || enters(b.path(), a, tol)) return true;
    for (const Shape* s : {&a, &b}) {
        Geom::Point w = polygon_witness(*s);
        if (a.depth(w) > tol && b.depth(w) > tol) return true;
    }
    return false;
}

bool areas_overlap(const Shape& a, const Shape& b, double tol) {
    bool ca = a.kind() == ProxyKind::circle, cb = b.kind() == ProxyKind::circle;
    if (ca && cb) return circles_overlap(a, b, tol);
    if (ca) return circle_polygon_overlap(a, b, tol);
    if (cb) return circle_polygon_overlap(b, a, tol);
    return polygons_overlap(a, b, tol);
}

// --- curve - curve -----------------------------------------------------------------------

Geom::PathTime path_time(const Geom::Path& path, double s) {
    std::size_t n = detail::path_curves(path).size();
    double i = std::floor(s);
    if (i >= static_cast<double>(n)) return Geom::PathTime(n - 1, 1.0);
    if (i < 0) return Geom::PathTime(0, 0.0);
    return Geom::PathTime(static_cast<std::size_t>(i), s - i);
}

// Which side of `other` the point lies on: +1, -1, or 0 when it lies beyond an end of
// `other` (no side there).
int side_of(const Geom::Path& other, Geom::Point w) {
    Geom::PathTime s = other.nearestTime(w);
    const Geom::Curve& c = other[s.curve_index];
    Geom::Point foot = c.pointAt(s.t);
    Geom::Point away = w - foot;
    double len = Geom::L2(away);
    if (!(len > 0)) return 0;
    double sine = Geom::cross(c.unitTangentAt(s.t), away) / len;
    if (std::abs(sine) < 0.5) return 0;
    return sine > 0 ? 1 : -1;
}

// Around the intersection at time x of `path` (sorted distinct intersection times `cuts`),
// the path goes farther than tol from `other` on both sides, ending on opposite sides.
bool crosses_through(const Geom::Path& path, const std::vector<double>& cuts, double x,
                     const Geom::Path& other, const BoundaryDistance& other_distance, double tol) {
    double end = static_cast<double>(detail::path_curves(path).size());
    // The cluster of merged times that holds x.
    auto it = std::upper_bound(cuts.begin(), cuts.end(), x + 1e-9);
    if (it == cuts.begin()) return false;
    --it;
    double prev = it == cuts.begin() ? 0.0 : *(it - 1);
    double next = it + 1 == cuts.end() ? end : *(it + 1);
    detail::ExcursionOptions before_options;
    before_options.split_at_crossings = false;
    before_options.first = true;
    before_options.from_end = true;
    detail::ExcursionOptions after_options = before_options;
    after_options.from_end = false;
    auto before = detail::find_excursion(path, path_time(path, prev), path_time(path, x),
                                         other_distance, tol, before_options);
    if (!before) return false;
    auto after = detail::find_excursion(path, path_time(path, x), path_time(path, next),
                                        other_distance, tol, after_options);
    if (!after) return false;
    int s0 = side_of(other, path.pointAt(*before));
    int s1 = side_of(other, path.pointAt(*after));
    return s0 != 0 && s1 != 0 && s0 != s1;
}

// Sorted intersection times with near-equal ones (joins between pieces) merged.
std::vector<double> distinct_times(std::vector<double> times) {
    std::sort(times.begin(), times.end());
    std::vector<double> out;
    for (double t : times) {
        if (out.empty() || t - out.back() > 1e-9) out.push_back(t);
    }
    return out;
}

bool curves_overlap(const Shape& a, const Shape& b, double tol) {
    std::vector<const Geom::Curve*> ca = detail::path_curves(a.path());
    std::vector<const Geom::Curve*> cb = detail::path_curves(b.path());
    std::vector<double> ta, tb;  // path times (curve index + curve time) of each intersection
    for (std::size_t i = 0; i < ca.size(); ++i) {
        for (std::size_t j = 0; j < cb.size(); ++j) {
            for (const Geom::CurveIntersection& x : detail::intersect_curves(*ca[i], *cb[j])) {
                ta.push_back(static_cast<double>(i) + x.first);
                tb.push_back(static_cast<double>(j) + x.second);
            }
        }
    }
    if (ta.empty()) return false;
    std::vector<double> cuts_a = distinct_times(ta), cuts_b = distinct_times(tb);
    BoundaryDistance to_a(ca), to_b(cb);
    for (std::size_t i = 0; i < ta.size(); ++i) {
        // The same point reported again (at a join between pieces, or by both pieces).
        bool seen = false;
        for (std::size_t k = 0; k < i && !seen; ++k) {
            seen = std::abs(ta[k] - ta[i]) <= 1e-9 && std::abs(tb[k] - tb[i]) <= 1e-9;
        }
        if (seen) continue;
        if (crosses_through(b.path(), cuts_b, tb[i], a.path(), to_a, tol) &&
            crosses_through(a.path(), cuts_a, ta[i], b.path(), to_b, tol)) {
            return true;
        }
    }
    return false;
}

// --- region ------------------------------------------------------------------------------

}  // namespace

bool overlaps(const Proxy& a, const Proxy& b, double tolerance) {
    Category ca = category(a.kind()), cb = category(b.kind());
    if (ca == Category::point && cb == Category::point) return false;
    if ((ca == Category::point && cb == Category::curve) ||
        (ca == Category::curve && cb == Category::point)) {
        return false;
    }
    // Two circles, or a point and a circle: the rules below on the centres and radii alone,
    // without building the exact curves (the same arithmetic, so the same answer to the bit).
    // Most proxies of a growth are circles or points, and images are tested against their
    // element one pair at a time.
    const bool cira = a.kind() == ProxyKind::circle, cirb = b.kind() == ProxyKind::circle;
    if ((cira || ca == Category::point) && (cirb || cb == Category::point) && (cira || cirb)) {
        const CircleProxy& c = static_cast<const CircleProxy&>(cira ? a : b);
        const Proxy& o = cira ? b : a;
        if (finite_circle(c)) {
            if (o.kind() == ProxyKind::circle) {
                const auto& d = static_cast<const CircleProxy&>(o);
                if (finite_circle(d)) {
                    const CircleProxy& first = static_cast<const CircleProxy&>(a);
                    const CircleProxy& second = static_cast<const CircleProxy&>(b);
                    return distance(first.center, second.center) <
                           first.radius + second.radius - tolerance;
                }
            } else if (const Point p = static_cast<const PointProxy&>(o).point(); p.finite()) {
                return c.radius - Geom::distance(to_geom(p), to_geom(c.center)) > tolerance;
            }
        }
    }
    Shape sa(a), sb(b);
    if (ca == Category::point) return sb.depth(to_geom(sa.point())) > tolerance;
    if (cb == Category::point) return sa.depth(to_geom(sb.point())) > tolerance;
    if (ca == Category::area && cb == Category::area) return areas_overlap(sa, sb, tolerance);
    if (ca == Category::area) return enters(sb.path(), sa, tolerance);
    if (cb == Category::area) return enters(sa.path(), sb, tolerance);
    return curves_overlap(sa, sb, tolerance);
}

namespace {

// Bounds holding every point of the proxy's exact shape, for the kinds whose bounds are cheap
// (a Bézier's control points); nothing for the others.
std::optional<Geom::Rect> plain_bounds(const Proxy& p) {
    if (!p.finite()) return std::nullopt;
    Rect r;
    switch (p.kind()) {
        case ProxyKind::circle:
        case ProxyKind::linesegment:
        case ProxyKind::polygon:
            r = p.bounds();
            break;
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(p);
            r = {b.c[0].x, b.c[0].y, b.c[0].x, b.c[0].y};
            for (const Point& q : b.c)
                r = {std::min(r.x0, q.x), std::min(r.y0, q.y), std::max(r.x1, q.x),
                     std::max(r.y1, q.y)};
            break;
        }
        default:
            return std::nullopt;
    }
    if (!(r.x0 <= r.x1 && r.y0 <= r.y1)) return std::nullopt;
    return Geom::Rect(r.x0, r.y0, r.x1, r.y1);
}

}  // namespace

bool leaves_region(const Proxy& p, const detail::RegionData& region, double tolerance) {
    const BoundaryDistance& outside = region.boundary->outside();
    // A shape whose bounds no boundary curve comes near lies wholly on one side of the
    // boundary: inside, every point's signed distance is at most 0, so no excursion beyond a
    // tolerance of 0 or more, and no boundary curve within its bounds to enter an area. The
    // exact tests below would answer no for it, after intersecting it with every boundary
    // curve (a third of hierarchical's intersection tests' time). The margin covers rounding
    // in the curves' points.
    if (tolerance >= 0) {
        if (std::optional<Geom::Rect> box = plain_bounds(p)) {
            const double margin =
                1e-9 * (1 + std::max({std::abs(box->left()), std::abs(box->right()),
                                      std::abs(box->top()), std::abs(box->bottom())}));
            box->expandBy(margin);
            if (!outside.any_curve_meets(*box) && !outside.positive(box->midpoint())) return false;
        }
    }
    Shape shape(p);
    if (shape.category() == Category::point) {
        return outside.signed_distance(to_geom(shape.point())) > tolerance;
    }
    if (detail::find_excursion(shape.path(), outside, tolerance)) return true;
    if (shape.category() == Category::area) {
        // Only boundary curves that meet the area's bounds can enter it.
        Geom::OptRect box = shape.path().boundsFast();
        if (!box) return false;
        for (std::size_t i : outside.curves_meeting(*box)) {
            const Geom::Curve& c = *outside.curves()[i];
            if (shape.kind() == ProxyKind::circle) {
                const Geom::Point centre = to_geom(shape.point());
                if (detail::curve_distance_lower_bound(c, centre) >= shape.radius() - tolerance)
                    continue;
                if (Geom::distance(centre, c.pointAt(c.nearestTime(centre))) <
                    shape.radius() - tolerance)
                    return true;
            } else if (detail::find_excursion(c, 0, 1, shape.boundary(), tolerance)) {
                return true;
            }
        }
    }
    return false;
}

bool leaves_region(const Proxy& p, const Region& region, double tolerance) {
    return leaves_region(p, region.data(), tolerance);
}

double distance_to(const Proxy& p, Point q, double limit) {
    Geom::Point g = to_geom(q);
    switch (p.kind()) {
        case ProxyKind::point:
            return distance(static_cast<const PointProxy&>(p).point(), q);
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(p);
            return std::max(0.0, distance(c.center, q) - c.radius);
        }
        case ProxyKind::polygon: {
            Shape s(p);
            return s.inside(g) ? 0.0 : s.boundary().nearest(g).distance;
        }
        // A segment or a Bézier is one curve: measured as its path would be, without the
        // path's allocations (this is the growth's most frequent distance).
        case ProxyKind::linesegment: {
            const auto& s = static_cast<const LineSegmentProxy&>(p);
            return curve_distance(Geom::LineSegment(to_geom(s.p0), to_geom(s.p1)), g, limit);
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(p);
            return curve_distance(Geom::CubicBezier(to_geom(b.c[0]), to_geom(b.c[1]),
                                                    to_geom(b.c[2]), to_geom(b.c[3])),
                                  g, limit);
        }
        default:
            return path_distance(detail::proxy_path(p), g, limit);
    }
}

}  // namespace acanthus::detail
