// Reference checks for dartfill tests that share no code with the library: point sampling with a
// crossing-number test on the outline, and Boost.Geometry polygon intersection.
#pragma once

#include <acanthus/point.hpp>

// Boost.Geometry's rescale policy trips a false -Wmaybe-uninitialized in GCC 12.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dartfill_oracle {

using acanthus::Point;
using Ring = std::vector<Point>;

inline bool in_ring(const Ring& ring, Point p) {
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Point& a = ring[i];
        const Point& b = ring[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

inline double distance_to_ring(const Ring& ring, Point p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ring.size(); ++i) {
        Point a = ring[i], b = ring[(i + 1) % ring.size()];
        acanthus::Vector ab = b - a;
        double t = std::clamp((p - a).dot(ab) / ab.dot(ab), 0.0, 1.0);
        best = std::min(best, acanthus::distance(p, a + ab * t));
    }
    return best;
}

inline acanthus::Rect ring_bounds(const Ring& r) {
    acanthus::Rect b{r[0].x, r[0].y, r[0].x, r[0].y};
    for (Point p : r) {
        b.x0 = std::min(b.x0, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.x1 = std::max(b.x1, p.x);
        b.y1 = std::max(b.y1, p.y);
    }
    return b;
}

// A grid of `n` x `n` points over the common box: true if one lies deeper than `margin` inside
// both outlines.
inline bool sampled_overlap(const Ring& a, const Ring& b, int n, double margin) {
    acanthus::Rect ba = ring_bounds(a), bb = ring_bounds(b);
    acanthus::Rect box{std::max(ba.x0, bb.x0), std::max(ba.y0, bb.y0), std::min(ba.x1, bb.x1),
                       std::min(ba.y1, bb.y1)};
    if (box.x0 >= box.x1 || box.y0 >= box.y1) return false;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Point p{box.x0 + (i + 0.5) / n * box.width(), box.y0 + (j + 0.5) / n * box.height()};
            if (in_ring(a, p) && in_ring(b, p) && distance_to_ring(a, p) > margin &&
                distance_to_ring(b, p) > margin)
                return true;
        }
    return false;
}

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint>;

inline BPolygon to_polygon(const Ring& r) {
    BPolygon poly;
    for (Point p : r) bg::append(poly.outer(), BPoint(p.x, p.y));
    bg::append(poly.outer(), BPoint(r[0].x, r[0].y));
    bg::correct(poly);
    return poly;
}

// Area shared by two simple polygons.
inline double intersection_area(const Ring& a, const Ring& b) {
    std::vector<BPolygon> out;
    bg::intersection(to_polygon(a), to_polygon(b), out);
    double area = 0;
    for (const auto& p : out) area += bg::area(p);
    return area;
}

}  // namespace dartfill_oracle
