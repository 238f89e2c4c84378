// Range checks of placed proxies (see proxy_range.hpp).
#include "proxy/proxy_range.hpp"

#include <cmath>
#include <sstream>

namespace acanthus::detail {

namespace {

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

std::string point_problem(Point p) {
    if (std::abs(p.x) > kMaxCoordinate)
        return "a coordinate beyond +-" + number(kMaxCoordinate) + " (x = " + number(p.x) + ")";
    if (std::abs(p.y) > kMaxCoordinate)
        return "a coordinate beyond +-" + number(kMaxCoordinate) + " (y = " + number(p.y) + ")";
    return {};
}

std::string radius_problem(double r) {
    if (r < 0) return "a negative radius (" + number(r) + ")";
    if (r > kMaxCoordinate)
        return "a radius beyond " + number(kMaxCoordinate) + " (" + number(r) + ")";
    return {};
}

std::string first_problem(std::initializer_list<std::string> problems) {
    for (const std::string& p : problems)
        if (!p.empty()) return p;
    return {};
}

std::string points_problem(const Point* points, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i)
        if (std::string p = point_problem(points[i]); !p.empty()) return p;
    return {};
}

}  // namespace

std::string proxy_range_problem(const Proxy& proxy) {
    switch (proxy.kind()) {
        case ProxyKind::point:
            return point_problem(static_cast<const PointProxy&>(proxy).point());
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            return first_problem({radius_problem(c.radius), point_problem(c.center)});
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(proxy);
            return first_problem({radius_problem(a.radius), point_problem(a.center)});
        }
        case ProxyKind::linesegment: {
            const auto& s = static_cast<const LineSegmentProxy&>(proxy);
            return first_problem({point_problem(s.p0), point_problem(s.p1)});
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(proxy);
            return points_problem(b.c.data(), b.c.size());
        }
        case ProxyKind::polygon: {
            const auto& g = static_cast<const PolygonProxy&>(proxy);
            return points_problem(g.points.data(), g.points.size());
        }
    }
    return {};
}

}  // namespace acanthus::detail
