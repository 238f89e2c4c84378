// Proxies: the simple shapes that stand for an element when finding space and testing overlap.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <initializer_list>
#include <limits>
#include <string_view>
#include <vector>

namespace acanthus {

enum class ProxyKind { point, circle, arc, linesegment, bezier, polygon };

std::string_view to_string(ProxyKind kind);
// True for kinds that cover an area (circle, polygon); curves and points have none.
constexpr bool is_area(ProxyKind kind) {
    return kind == ProxyKind::circle || kind == ProxyKind::polygon;
}

namespace detail {
constexpr double unset = std::numeric_limits<double>::quiet_NaN();
}

// Base of every proxy. Fields start as NaN; set() marks the proxy as set.
class Proxy {
  public:
    ProxyKind kind() const { return kind_; }
    // True once set() was called or every coordinate was assigned a finite value.
    bool is_set() const;
    // True when every coordinate is finite.
    bool finite() const;
    // Tight axis-aligned bounds (curves exact, arcs by extreme angles).
    Rect bounds() const;

  protected:
    explicit Proxy(ProxyKind kind) : kind_(kind) {}
    Proxy(const Proxy&) = default;
    Proxy& operator=(const Proxy&) = default;
    ~Proxy() = default;
    void mark_set() { set_ = true; }

  private:
    ProxyKind kind_;
    bool set_ = false;
};

// A point proxy is a Point: `$0.set( $, 3.0 )` passes it where a Point is expected.
class PointProxy : public Proxy, public Point {
  public:
    PointProxy() : Proxy(ProxyKind::point), Point(detail::unset, detail::unset) {}
    void set(Point p) {
        x = p.x;
        y = p.y;
        mark_set();
    }
    Point point() const { return {x, y}; }
};

class CircleProxy : public Proxy {
  public:
    CircleProxy() : Proxy(ProxyKind::circle) {}
    Point center{detail::unset, detail::unset};
    double radius = detail::unset;
    void set(Point c, double r) {
        center = c;
        radius = r;
        mark_set();
    }
    void set(Circle c) { set(c.center, c.radius); }
};

// Counter-clockwise arc from angle `start` to angle `end` (radians).
class ArcProxy : public Proxy {
  public:
    ArcProxy() : Proxy(ProxyKind::arc) {}
    Point center{detail::unset, detail::unset};
    double radius = detail::unset;
    double start = detail::unset;
    double end = detail::unset;
    void set(Point c, double r, double s, double e) {
        center = c;
        radius = r;
        start = s;
        end = e;
        mark_set();
    }
    Point start_point() const { return center.offset(Direction(start), radius); }
    Point end_point() const { return center.offset(Direction(end), radius); }
};

class LineSegmentProxy : public Proxy {
  public:
    LineSegmentProxy() : Proxy(ProxyKind::linesegment) {}
    Point p0{detail::unset, detail::unset};
    Point p1{detail::unset, detail::unset};
    void set(Point a, Point b) {
        p0 = a;
        p1 = b;
        mark_set();
    }
};

// Cubic Bézier with control points c[0..3].
class BezierProxy : public Proxy {
  public:
    BezierProxy() : Proxy(ProxyKind::bezier) { c.fill(Point{detail::unset, detail::unset}); }
    std::array<Point, 4> c;
    void set(Point c0, Point c1, Point c2, Point c3) {
        c = {c0, c1, c2, c3};
        mark_set();
    }
    // Leaves p0 along dir0 and arrives at p1 along dir1; handle lengths are mag x chord length.
    void set(Point p0, Direction dir0, double mag0, Point p1, Direction dir1, double mag1) {
        double chord = distance(p0, p1);
        set(p0, p0.offset(dir0, mag0 * chord), p1.offset(dir1.opposite(), mag1 * chord), p1);
    }
    Point at(double t) const {
        double u = 1 - t;
        double b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
        return {b0 * c[0].x + b1 * c[1].x + b2 * c[2].x + b3 * c[3].x,
                b0 * c[0].y + b1 * c[1].y + b2 * c[2].y + b3 * c[3].y};
    }
};

// Closed polygon, possibly concave.
class PolygonProxy : public Proxy {
  public:
    PolygonProxy() : Proxy(ProxyKind::polygon) {}
    std::vector<Point> points;
    void set(std::initializer_list<Point> pts) {
        points.assign(pts);
        mark_set();
    }
    void set(std::vector<Point> pts) {
        points = std::move(pts);
        mark_set();
    }
};

}  // namespace acanthus
