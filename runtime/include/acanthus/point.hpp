// Small value types for rule bodies: Point, Vector, Direction, Circle, Rect.
#pragma once

#include <cmath>

namespace acanthus {

struct Vector {
    double x = 0.0;
    double y = 0.0;

    constexpr Vector() = default;
    constexpr Vector(double vx, double vy) : x(vx), y(vy) {}

    double length() const { return std::hypot(x, y); }
    constexpr double dot(Vector o) const { return x * o.x + y * o.y; }
    constexpr double cross(Vector o) const { return x * o.y - y * o.x; }
    // Counter-clockwise perpendicular.
    constexpr Vector perp() const { return {-y, x}; }
    Vector normalized() const {
        double l = length();
        return l > 0 ? Vector{x / l, y / l} : Vector{};
    }
    Vector rotated(double radians) const {
        double c = std::cos(radians), s = std::sin(radians);
        return {c * x - s * y, s * x + c * y};
    }

    constexpr Vector operator+(Vector o) const { return {x + o.x, y + o.y}; }
    constexpr Vector operator-(Vector o) const { return {x - o.x, y - o.y}; }
    constexpr Vector operator-() const { return {-x, -y}; }
    constexpr Vector operator*(double s) const { return {x * s, y * s}; }
    constexpr Vector operator/(double s) const { return {x / s, y / s}; }
    Vector& operator+=(Vector o) { return *this = *this + o; }
    Vector& operator-=(Vector o) { return *this = *this - o; }
    Vector& operator*=(double s) { return *this = *this * s; }
    Vector& operator/=(double s) { return *this = *this / s; }
    constexpr bool operator==(const Vector&) const = default;
};

constexpr Vector operator*(double s, Vector v) { return v * s; }
// The paper's length operator: ~(b - a) is the distance from a to b.
inline double operator~(Vector v) { return v.length(); }

// An angle in radians, counter-clockwise from +x. Converts from a Vector and from radians.
struct Direction {
    double angle = 0.0;

    constexpr Direction() = default;
    constexpr Direction(double radians) : angle(radians) {}  // NOLINT: implicit by design
    Direction(Vector v) : angle(std::atan2(v.y, v.x)) {}     // NOLINT: implicit by design

    Vector unit() const { return {std::cos(angle), std::sin(angle)}; }
    constexpr operator double() const { return angle; }  // NOLINT: usable where radians are
    constexpr Direction operator+(double radians) const { return {angle + radians}; }
    constexpr Direction operator-(double radians) const { return {angle - radians}; }
    Direction& operator+=(double radians) {
        angle += radians;
        return *this;
    }
    Direction& operator-=(double radians) {
        angle -= radians;
        return *this;
    }
    constexpr Direction opposite() const { return {angle + M_PI}; }
};

struct Point {
    double x = 0.0;
    double y = 0.0;

    constexpr Point() = default;
    constexpr Point(double px, double py) : x(px), y(py) {}

    // The point `distance` away along `direction`.
    Point offset(Direction direction, double distance) const {
        Vector u = direction.unit();
        return {x + u.x * distance, y + u.y * distance};
    }
    bool finite() const { return std::isfinite(x) && std::isfinite(y); }

    constexpr Point operator+(Vector v) const { return {x + v.x, y + v.y}; }
    constexpr Point operator-(Vector v) const { return {x - v.x, y - v.y}; }
    constexpr Vector operator-(Point o) const { return {x - o.x, y - o.y}; }
    Point& operator+=(Vector v) { return *this = *this + v; }
    Point& operator-=(Vector v) { return *this = *this - v; }
    constexpr bool operator==(const Point&) const = default;
};

inline double distance(Point a, Point b) { return (b - a).length(); }
constexpr Point midpoint(Point a, Point b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }
constexpr Point lerp(Point a, Point b, double t) {
    return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

// A circle as a value (the empty circle C is one): center and radius.
struct Circle {
    Point center;
    double radius = 0.0;
};

// Axis-aligned box, x0 <= x1, y0 <= y1.
struct Rect {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    constexpr double width() const { return x1 - x0; }
    constexpr double height() const { return y1 - y0; }
    constexpr Point center() const { return {(x0 + x1) / 2, (y0 + y1) / 2}; }
    constexpr bool contains(Point p) const {
        return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
    }
};

}  // namespace acanthus
