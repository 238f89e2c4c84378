#include "clip.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::cells::detail {

ClipperLib::IntPoint IntScale::to_int(Point p) const {
    return {static_cast<ClipperLib::cInt>(std::llround(p.x * scale)),
            static_cast<ClipperLib::cInt>(std::llround(p.y * scale))};
}

Point IntScale::to_point(const ClipperLib::IntPoint& p) const {
    return {static_cast<double>(p.X) / scale, static_cast<double>(p.Y) / scale};
}

ClipperLib::Path IntScale::to_path(const std::vector<Point>& polygon) const {
    ClipperLib::Path path;
    path.reserve(polygon.size());
    for (Point p : polygon) path.push_back(to_int(p));
    return path;
}

std::vector<Point> IntScale::to_polygon(const ClipperLib::Path& path) const {
    std::vector<Point> polygon;
    polygon.reserve(path.size());
    for (const ClipperLib::IntPoint& p : path) polygon.push_back(to_point(p));
    return polygon;
}

ClipperLib::Path IntScale::to_path(Rect r) const {
    return to_path(std::vector<Point>{{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}});
}

double IntScale::area(const ClipperLib::Paths& paths) const {
    double a = 0;
    for (const ClipperLib::Path& p : paths) a += ClipperLib::Area(p);
    return a / (scale * scale);
}

IntScale scale_for(Rect frame) {
    double extent = std::max(
        {std::abs(frame.x0), std::abs(frame.x1), std::abs(frame.y0), std::abs(frame.y1), 1e-9});
    // A power of two, so that grid coordinates that are exact in binary stay exact.
    int e = 0;
    std::frexp(extent, &e);
    return {std::ldexp(1.0, 40 - e)};
}

double signed_area(const std::vector<Point>& polygon) {
    double a = 0;
    for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
        const Point& p = polygon[i];
        const Point& q = polygon[(i + 1) % n];
        a += p.x * q.y - q.x * p.y;
    }
    return a / 2;
}

Rect bounds_of(const std::vector<Point>& polygon) {
    Rect r{1e300, 1e300, -1e300, -1e300};
    for (Point p : polygon) {
        r.x0 = std::min(r.x0, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x);
        r.y1 = std::max(r.y1, p.y);
    }
    return r;
}

bool axis_rect(const std::vector<Point>& p, Rect& r) {
    if (p.size() != 4) return false;
    r = bounds_of(p);
    // Each of the box's four corners once: a triangle with a repeated vertex (a skewback with
    // no bed below its springing) has a box too, but is not one.
    int corners = 0;
    for (Point q : p) {
        if ((q.x != r.x0 && q.x != r.x1) || (q.y != r.y0 && q.y != r.y1)) return false;
        corners |= 1 << ((q.x == r.x1 ? 1 : 0) + (q.y == r.y1 ? 2 : 0));
    }
    return corners == 15 && r.x0 < r.x1 && r.y0 < r.y1;
}

std::vector<std::vector<Point>> shrink(const std::vector<Point>& polygon, double distance,
                                       const IntScale& s) {
    std::vector<std::vector<Point>> out;
    if (distance <= 0) {
        out.push_back(polygon);
        return out;
    }
    ClipperLib::ClipperOffset offset(4.0);
    offset.AddPath(s.to_path(polygon), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::Paths result;
    offset.Execute(result, -distance * s.scale);
    // A vertex on a straight side (where the booleans met a neighbour's joint) is no corner of
    // the unit, and a voussoir with one reads as cut off its arcs: dropped, and vertices a
    // few micrometres apart merged.
    ClipperLib::CleanPolygons(result, 4e-3 * distance * s.scale);
    for (const ClipperLib::Path& p : result)
        if (p.size() >= 3 && ClipperLib::Orientation(p)) out.push_back(s.to_polygon(p));
    return out;
}

}  // namespace acanthus::cells::detail
