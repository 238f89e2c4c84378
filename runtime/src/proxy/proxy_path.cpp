#include "proxy/proxy_path.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>

#include <algorithm>
#include <cmath>

namespace acanthus::detail {

double arc_sweep(double start, double end) {
    double d = end - start;
    if (d >= 2 * M_PI) return 2 * M_PI;
    if (d < 0) {
        d = std::fmod(d, 2 * M_PI);
        if (d < 0) d += 2 * M_PI;
        // end == start - 2k*pi: a whole number of turns backwards is a full circle.
        if (d == 0) return 2 * M_PI;
    }
    return d;
}

Geom::Path arc_path(Point center, double radius, double start, double sweep) {
    Geom::Point first = to_geom(center.offset(Direction(start), radius));
    Geom::Path path(first);
    if (!(radius > 0) || !(sweep > 0)) {
        path.append(Geom::LineSegment(first, first));
        return path;
    }
    int pieces = std::max(1, static_cast<int>(std::ceil(sweep / (M_PI / 2) - 1e-12)));
    Geom::Point from = first;
    for (int i = 1; i <= pieces; ++i) {
        double angle = start + sweep * i / pieces;
        // The last point of a full circle is exactly the first, so the path closes cleanly.
        Geom::Point to = (i == pieces && sweep >= 2 * M_PI)
                             ? first
                             : to_geom(center.offset(Direction(angle), radius));
        // sweep = true turns towards increasing angle (from +x towards +y).
        path.append(Geom::EllipticalArc(from, radius, radius, 0, false, true, to));
        from = to;
    }
    return path;
}

namespace {

Geom::Path polygon_path(const std::vector<Point>& points) {
    std::vector<Geom::Point> pts;
    for (Point p : points) {
        Geom::Point g = to_geom(p);
        if (pts.empty() || pts.back() != g) pts.push_back(g);
    }
    while (pts.size() > 1 && pts.back() == pts.front()) pts.pop_back();
    if (pts.empty()) return Geom::Path(Geom::Point(NAN, NAN));
    Geom::Path path(pts.front());
    if (pts.size() == 1) {
        path.append(Geom::LineSegment(pts.front(), pts.front()));
    } else {
        for (std::size_t i = 0; i < pts.size(); ++i) {
            path.append(Geom::LineSegment(pts[i], pts[(i + 1) % pts.size()]));
        }
    }
    path.close(true);
    return path;
}

}  // namespace

Geom::Path proxy_path(const Proxy& proxy) {
    switch (proxy.kind()) {
        case ProxyKind::point:
            return Geom::Path(to_geom(static_cast<const PointProxy&>(proxy).point()));
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            Geom::Path path = arc_path(c.center, c.radius, 0, 2 * M_PI);
            path.close(true);
            return path;
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(proxy);
            return arc_path(a.center, a.radius, a.start, arc_sweep(a.start, a.end));
        }
        case ProxyKind::linesegment: {
            const auto& s = static_cast<const LineSegmentProxy&>(proxy);
            Geom::Path path(to_geom(s.p0));
            path.append(Geom::LineSegment(to_geom(s.p0), to_geom(s.p1)));
            return path;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(proxy);
            Geom::Path path(to_geom(b.c[0]));
            path.append(Geom::CubicBezier(to_geom(b.c[0]), to_geom(b.c[1]), to_geom(b.c[2]),
                                          to_geom(b.c[3])));
            return path;
        }
        case ProxyKind::polygon:
            return polygon_path(static_cast<const PolygonProxy&>(proxy).points);
    }
    return Geom::Path();
}

Geom::PathVector proxy_paths(const Proxy& proxy) { return Geom::PathVector(proxy_path(proxy)); }

}  // namespace acanthus::detail
