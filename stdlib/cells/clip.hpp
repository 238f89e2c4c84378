// Clipper at a facade's integer scale: conversions, areas and the mortar shrink.
#pragma once

#include <acanthus/point.hpp>
#include <polyclipping/clipper.hpp>
#include <vector>

namespace acanthus::cells::detail {

struct IntScale {
    double scale = 1;  // integer units per user unit
    ClipperLib::IntPoint to_int(Point p) const;
    Point to_point(const ClipperLib::IntPoint& p) const;
    ClipperLib::Path to_path(const std::vector<Point>& polygon) const;
    std::vector<Point> to_polygon(const ClipperLib::Path& path) const;
    ClipperLib::Path to_path(Rect r) const;
    double area(const ClipperLib::Paths& paths) const;  // signed sum, user units squared
};

// A scale that keeps every coordinate of `frame` within about 2^40 integer units.
IntScale scale_for(Rect frame);

double signed_area(const std::vector<Point>& polygon);
Rect bounds_of(const std::vector<Point>& polygon);
// Open interiors intersect. Inline: the occupancy maps ask it for every claim near a query.
inline bool overlaps(Rect a, Rect b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}
// True when `polygon` is an axis-aligned rectangle (four corners, any order); `r` its box.
bool axis_rect(const std::vector<Point>& polygon, Rect& r);

// The polygon inset by `distance` (mitred corners); may split or vanish.
std::vector<std::vector<Point>> shrink(const std::vector<Point>& polygon, double distance,
                                       const IntScale& s);

}  // namespace acanthus::cells::detail
