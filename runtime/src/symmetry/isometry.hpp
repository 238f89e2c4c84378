// A distance-preserving map of the plane, x' = a x + c y + e, y' = b x + d y + f (Cairo's
// matrix order): a rotation or a reflection followed by a translation.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <cmath>

namespace acanthus::detail {

struct Isometry {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

    // Rotation by `radians` about `center`.
    static Isometry rotation(Point center, double radians);
    // Reflection in the line through `center` at angle `radians`.
    static Isometry reflection(Point center, double radians);

    Point apply(Point p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
    // True for a reflection (orientation reversed).
    bool reverses() const { return a * d - b * c < 0; }
    // The image of the direction `radians`.
    double apply_angle(double radians) const {
        return std::atan2(b * std::cos(radians) + d * std::sin(radians),
                          a * std::cos(radians) + c * std::sin(radians));
    }
    // First this, then `next`.
    Isometry then(const Isometry& next) const;
    Isometry inverse() const;
    std::array<double, 6> matrix() const { return {a, b, c, d, e, f}; }
};

}  // namespace acanthus::detail
