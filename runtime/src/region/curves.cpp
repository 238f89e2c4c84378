#include "region/curves.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>
#include <2geom/path.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace acanthus::detail {
namespace {

void append_arc_as_cubics(const Geom::EllipticalArc& arc, Geom::Path& out) {
    const double rx = arc.ray(Geom::X), ry = arc.ray(Geom::Y);
    const double phi = arc.rotationAngle().radians();
    const double a0 = arc.initialAngle().radians(), sweep = arc.sweepAngle();
    const Geom::Point c = arc.center();
    auto map = [&](double x, double y) {
        double ex = rx * x, ey = ry * y;
        return c + Geom::Point(ex * std::cos(phi) - ey * std::sin(phi),
                               ex * std::sin(phi) + ey * std::cos(phi));
    };
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (M_PI / 12))));
    const double d = sweep / n;
    const double k = 4.0 / 3.0 * std::tan(d / 4);
    for (int i = 0; i < n; ++i) {
        double a = a0 + i * d, b = a + d;
        Geom::Point p0 = i == 0 ? arc.initialPoint() : out.finalPoint();
        Geom::Point p3 = i == n - 1 ? arc.finalPoint() : map(std::cos(b), std::sin(b));
        Geom::Point p1 = map(std::cos(a) - k * std::sin(a), std::sin(a) + k * std::cos(a));
        Geom::Point p2 = map(std::cos(b) + k * std::sin(b), std::sin(b) - k * std::cos(b));
        out.append(Geom::CubicBezier(p0, p1, p2, p3));
    }
}

double y_at(const Geom::Curve& c, double t) {
    if (t <= 0) return c.initialPoint()[Geom::Y];
    if (t >= 1) return c.finalPoint()[Geom::Y];
    return c.pointAt(t)[Geom::Y];
}

Geom::Point point_at(const Geom::Curve& c, double t) {
    if (t <= 0) return c.initialPoint();
    if (t >= 1) return c.finalPoint();
    return c.pointAt(t);
}

// Times in (0, 1) where y(t) turns.
std::vector<double> y_turns(const Geom::Curve& c) {
    std::vector<double> turns;
    if (auto bez = dynamic_cast<const Geom::BezierCurve*>(&c)) {
        if (bez->order() >= 2) turns = Geom::derivative(bez->fragment()[Geom::Y]).roots();
    } else {
        for (int i = 1; i < 64; ++i) turns.push_back(i / 64.0);  // not produced by regions
    }
    std::erase_if(turns, [](double t) { return !(t > 0 && t < 1); });
    std::sort(turns.begin(), turns.end());
    return turns;
}

}  // namespace

Geom::PathVector arcs_to_cubics(const Geom::PathVector& paths) {
    Geom::PathVector out;
    for (const Geom::Path& path : paths) {
        Geom::Path converted(path.initialPoint());
        for (std::size_t i = 0; i < path.size_open(); ++i) {
            const Geom::Curve& c = path[i];
            auto arc = dynamic_cast<const Geom::EllipticalArc*>(&c);
            if (arc && !arc->isChord() && !arc->isDegenerate()) {
                append_arc_as_cubics(*arc, converted);
            } else if (arc) {
                converted.append(Geom::LineSegment(c.initialPoint(), c.finalPoint()));
            } else {
                converted.append(c);
            }
        }
        converted.close(path.closed());
        out.push_back(std::move(converted));
    }
    return out;
}

int winding_number(const Geom::Curve& c, Geom::Point p) {
    const double py = p[Geom::Y];
    const Geom::Rect box = c.boundsFast();
    if (py < box.top() || py > box.bottom() || p[Geom::X] > box.right()) return 0;
    int winding = 0;
    std::vector<double> cuts = y_turns(c);
    cuts.insert(cuts.begin(), 0.0);
    cuts.push_back(1.0);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        double t0 = cuts[k], t1 = cuts[k + 1];
        double y0 = y_at(c, t0), y1 = y_at(c, t1);
        // Half-open in y, so a ray through a shared vertex counts once.
        int dir = (y0 <= py && py < y1) ? 1 : (y1 <= py && py < y0) ? -1 : 0;
        if (dir == 0) continue;
        double lo = t0, hi = t1;  // y(lo) on the y0 side of py, y(hi) on the other
        for (int it = 0; it < 80 && hi - lo > 1e-15; ++it) {
            double mid = (lo + hi) / 2;
            bool below = dir > 0 ? y_at(c, mid) <= py : y_at(c, mid) > py;
            (below ? lo : hi) = mid;
        }
        if (point_at(c, (lo + hi) / 2)[Geom::X] > p[Geom::X]) winding += dir;
    }
    return winding;
}

int winding_number(const Geom::PathVector& paths, Geom::Point p) {
    int winding = 0;
    for (const Geom::Path& path : paths)
        for (std::size_t i = 0; i < path.size_closed(); ++i) winding += winding_number(path[i], p);
    return winding;
}

}  // namespace acanthus::detail
