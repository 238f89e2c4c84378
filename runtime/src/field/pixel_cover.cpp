#include "field/pixel_cover.hpp"

#include <algorithm>
#include <cmath>

#include "proxy/proxy_path.hpp"

namespace acanthus::detail {
namespace {

// Integer conversion that survives far-away coordinates.
int clamp_index(double x, int lo, int hi) {
    if (!(x > lo)) return lo;
    if (!(x < hi)) return hi;
    return static_cast<int>(x);
}

double segment_distance(Point p, Point a, Point b) {
    const Vector ab = b - a;
    const double len2 = ab.dot(ab);
    double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return distance(p, a + ab * t);
}

void subdivide(Point c0, Point c1, Point c2, Point c3, double tolerance, int depth,
               std::vector<Point>& out) {
    const bool flat =
        segment_distance(c1, c0, c3) <= tolerance && segment_distance(c2, c0, c3) <= tolerance;
    if (flat || depth >= 24) {
        out.push_back(c3);
        return;
    }
    // de Casteljau at t = 1/2.
    const Point a = midpoint(c0, c1), b = midpoint(c1, c2), c = midpoint(c2, c3);
    const Point d = midpoint(a, b), e = midpoint(b, c), m = midpoint(d, e);
    subdivide(c0, a, d, m, tolerance, depth + 1, out);
    subdivide(m, e, c, c3, tolerance, depth + 1, out);
}

}  // namespace

void PixelCover::span(int j, double ua, double ub, std::vector<int>& out) const {
    if (j < 0 || j >= grid_.height) return;
    const int i0 = clamp_index(std::ceil(ua) - 1, 0, grid_.width);
    const int i1 = clamp_index(std::floor(ub), -1, grid_.width - 1);
    const int base = j * grid_.width;
    for (int i = i0; i <= i1; ++i) out.push_back(base + i);
}

void PixelCover::segment_px(double u0, double v0, double u1, double v1,
                            std::vector<int>& out) const {
    const double vmin = std::min(v0, v1), vmax = std::max(v0, v1);
    const int j0 = clamp_index(std::ceil(vmin) - 1, 0, grid_.height);
    const int j1 = clamp_index(std::floor(vmax), -1, grid_.height - 1);
    for (int j = j0; j <= j1; ++j) {
        double ua, ub;
        if (v0 == v1) {
            ua = std::min(u0, u1);
            ub = std::max(u0, u1);
        } else {
            // The part of the segment inside the closed band j <= v <= j + 1.
            const double ta = std::clamp((j - v0) / (v1 - v0), 0.0, 1.0);
            const double tb = std::clamp((j + 1 - v0) / (v1 - v0), 0.0, 1.0);
            ua = u0 + ta * (u1 - u0);
            ub = u0 + tb * (u1 - u0);
            if (ua > ub) std::swap(ua, ub);
        }
        span(j, ua, ub, out);
    }
}

void PixelCover::segment(Point a, Point b, std::vector<int>& out) const {
    if (!a.finite() || !b.finite()) return;
    segment_px(u(a.x), v(a.y), u(b.x), v(b.y), out);
}

void PixelCover::disc(Point center, double radius, std::vector<int>& out) const {
    if (!center.finite() || !std::isfinite(radius)) return;
    const double cu = u(center.x), cv = v(center.y);
    const double r = std::max(0.0, radius / grid_.pixel);
    const int j0 = clamp_index(std::ceil(cv - r) - 1, 0, grid_.height);
    const int j1 = clamp_index(std::floor(cv + r), -1, grid_.height - 1);
    for (int j = j0; j <= j1; ++j) {
        // Nearest point of the closed band j <= v <= j + 1 to the centre.
        const double dy = std::max({0.0, j - cv, cv - (j + 1)});
        if (dy > r) continue;
        const double hw = std::sqrt(r * r - dy * dy);
        span(j, cu - hw, cu + hw, out);
    }
}

void PixelCover::centers_inside(const std::vector<std::vector<Point>>& rings, bool evenodd,
                                std::vector<int>& out) const {
    std::vector<Run> runs;
    center_runs_inside(rings, evenodd, runs);
    for (const Run& r : runs)
        for (int i = r.first; i <= r.last; ++i) out.push_back(r.row * grid_.width + i);
}

void PixelCover::center_runs_inside(const std::vector<std::vector<Point>>& rings, bool evenodd,
                                    std::vector<Run>& out) const {
    struct Crossing {
        int row;
        double u;
        int dir;
        bool operator<(const Crossing& o) const {
            return row != o.row ? row < o.row : u != o.u ? u < o.u : dir < o.dir;
        }
    };
    std::vector<Crossing> crossings;
    for (const auto& ring : rings) {
        const std::size_t n = ring.size();
        for (std::size_t k = 0; k < n; ++k) {
            const Point a = ring[k], b = ring[(k + 1) % n];
            if (!a.finite() || !b.finite()) continue;
            const double ua = u(a.x), va = v(a.y), ub = u(b.x), vb = v(b.y);
            if (va == vb) continue;
            const double lo = std::min(va, vb), hi = std::max(va, vb);
            // Rows whose centre j + 0.5 lies in [lo, hi).
            const int j0 = clamp_index(std::ceil(lo - 0.5), 0, grid_.height);
            const int j1 = clamp_index(std::ceil(hi - 0.5) - 1, -1, grid_.height - 1);
            for (int j = j0; j <= j1; ++j) {
                const double vc = j + 0.5;
                crossings.push_back({j, ua + (vc - va) * (ub - ua) / (vb - va), vb > va ? 1 : -1});
            }
        }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k < crossings.size();) {
        const int row = crossings[k].row;
        int winding = 0;
        for (; k < crossings.size() && crossings[k].row == row; ++k) {
            winding += crossings[k].dir;
            const bool inside = evenodd ? (winding % 2) != 0 : winding != 0;
            if (!inside || k + 1 >= crossings.size() || crossings[k + 1].row != row) continue;
            // Centres i + 0.5 in [u_k, u_k+1).
            const int i0 = clamp_index(std::ceil(crossings[k].u - 0.5), 0, grid_.width);
            const int i1 =
                clamp_index(std::ceil(crossings[k + 1].u - 0.5) - 1, -1, grid_.width - 1);
            if (i0 <= i1) out.push_back({row, i0, i1});
        }
    }
}

void PixelCover::polygon(const std::vector<Point>& points, std::vector<int>& out) const {
    if (points.empty()) return;
    for (std::size_t k = 0; k < points.size(); ++k)
        segment(points[k], points[(k + 1) % points.size()], out);
    if (points.size() >= 3) centers_inside({points}, false, out);
}

std::vector<Point> PixelCover::flatten_arc(const ArcProxy& a) const {
    const double sweep = detail::arc_sweep(a.start, a.end);
    const double r = std::abs(a.radius) / grid_.pixel;
    int n = 1;
    if (r > kFlatten) {
        const double step = 2 * std::acos(1 - kFlatten / r);
        n = static_cast<int>(std::clamp(std::ceil(sweep / step), 1.0, 1e5));
    }
    std::vector<Point> out;
    out.reserve(n + 1);
    for (int k = 0; k <= n; ++k)
        out.push_back(a.center.offset(Direction(a.start + sweep * k / n), a.radius));
    return out;
}

std::vector<Point> PixelCover::flatten_bezier(const BezierProxy& b) const {
    std::vector<Point> out{b.c[0]};
    subdivide(b.c[0], b.c[1], b.c[2], b.c[3], kFlatten * grid_.pixel, 0, out);
    return out;
}

void PixelCover::proxy(const Proxy& p, std::vector<int>& out) const {
    if (!p.finite()) return;
    switch (p.kind()) {
        case ProxyKind::point: {
            const auto& q = static_cast<const PointProxy&>(p);
            const double pu = std::floor(u(q.x)), pv = std::floor(v(q.y));
            if (pu >= 0 && pv >= 0 && pu < grid_.width && pv < grid_.height)
                out.push_back(static_cast<int>(pv) * grid_.width + static_cast<int>(pu));
            return;
        }
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(p);
            disc(c.center, c.radius, out);
            return;
        }
        case ProxyKind::arc: {
            const auto pts = flatten_arc(static_cast<const ArcProxy&>(p));
            for (std::size_t k = 0; k + 1 < pts.size(); ++k) segment(pts[k], pts[k + 1], out);
            if (pts.size() == 1) segment(pts[0], pts[0], out);
            return;
        }
        case ProxyKind::linesegment: {
            const auto& s = static_cast<const LineSegmentProxy&>(p);
            segment(s.p0, s.p1, out);
            return;
        }
        case ProxyKind::bezier: {
            const auto pts = flatten_bezier(static_cast<const BezierProxy&>(p));
            for (std::size_t k = 0; k + 1 < pts.size(); ++k) segment(pts[k], pts[k + 1], out);
            return;
        }
        case ProxyKind::polygon:
            polygon(static_cast<const PolygonProxy&>(p).points, out);
            return;
    }
}

}  // namespace acanthus::detail
