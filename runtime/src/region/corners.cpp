#include <2geom/curve.h>
#include <2geom/path.h>

#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>

#include "region/region_data.hpp"

namespace acanthus {
namespace {

Vector to_vector(Geom::Point p) { return {p[Geom::X], p[Geom::Y]}; }

// Unit tangent at the end (t = 1) or start (t = 0) of a curve, from the first non-zero
// derivative (a Bézier whose handle sits on its end point has a zero first derivative there).
Vector end_tangent(const Geom::Curve& c, double t) {
    for (unsigned n = 1; n <= 3; ++n) {
        const std::vector<Geom::Point> d = c.pointAndDerivatives(t, n);
        if (d.size() > n && Geom::L2(d[n]) > 1e-12) return to_vector(d[n]).normalized();
    }
    return to_vector(c.finalPoint() - c.initialPoint()).normalized();
}

}  // namespace

std::vector<Corner> Region::corners(double min_turn) const {
    std::vector<Corner> out;
    const Rect& b = data_->bounds;
    const double probe = 1e-4 * std::max(b.width(), b.height());
    for (const Geom::Path& path : data_->paths) {
        std::vector<const Geom::Curve*> curves;
        for (std::size_t i = 0; i < path.size_closed(); ++i)
            if (!path[i].isDegenerate()) curves.push_back(&path[i]);
        for (std::size_t i = 0; i < curves.size(); ++i) {
            const Geom::Curve& in = *curves[i];
            const Geom::Curve& next = *curves[(i + 1) % curves.size()];
            const Vector a = end_tangent(in, 1.0), c = end_tangent(next, 0.0);
            const double turn = std::atan2(a.cross(c), a.dot(c));
            if (std::abs(turn) < min_turn) continue;
            const Point at{in.finalPoint()[Geom::X], in.finalPoint()[Geom::Y]};
            // The two sides leave the corner along -a and c; the region lies in the sector
            // between them that holds their bisector, or in the other one.
            Vector bisector = (c - a).normalized();
            if (bisector.length() == 0) bisector = a.perp();  // a cusp: the sides coincide
            const double between = M_PI - std::abs(turn);
            if (contains(at + bisector * probe))
                out.push_back({at, Direction(bisector), between});
            else if (contains(at - bisector * probe))
                out.push_back({at, Direction(-bisector), 2 * M_PI - between});
        }
    }
    return out;
}

}  // namespace acanthus
