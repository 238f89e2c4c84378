#include "symmetry/isometry.hpp"

namespace acanthus::detail {

Isometry Isometry::rotation(Point o, double t) {
    const double cs = std::cos(t), sn = std::sin(t);
    return {cs, sn, -sn, cs, o.x - cs * o.x + sn * o.y, o.y - sn * o.x - cs * o.y};
}

Isometry Isometry::reflection(Point o, double t) {
    const double cs = std::cos(2 * t), sn = std::sin(2 * t);
    return {cs, sn, sn, -cs, o.x - cs * o.x - sn * o.y, o.y - sn * o.x + cs * o.y};
}

Isometry Isometry::then(const Isometry& n) const {
    return {n.a * a + n.c * b, n.b * a + n.d * b,       n.a * c + n.c * d,
            n.b * c + n.d * d, n.a * e + n.c * f + n.e, n.b * e + n.d * f + n.f};
}

Isometry Isometry::inverse() const {
    const double det = a * d - b * c;  // +-1
    const double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
    return {ia, ib, ic, id, -(ia * e + ic * f), -(ib * e + id * f)};
}

}  // namespace acanthus::detail
