#include "geometry/path_checks.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>

#include <acanthus/error.hpp>
#include <cmath>

#include "geometry/coordinate_range.hpp"

namespace acanthus::detail {
namespace {

bool finite(Geom::Point p) { return std::isfinite(p[Geom::X]) && std::isfinite(p[Geom::Y]); }

bool in_range(Geom::Point p) {
    return in_coordinate_range(p[Geom::X]) && in_coordinate_range(p[Geom::Y]);
}

}  // namespace

void require_finite(const Geom::PathVector& paths, const std::string& where) {
    for (const Geom::Path& p : paths) {
        for (std::size_t i = 0; i < p.size_closed(); ++i) {
            const Geom::Curve& c = p[i];
            Geom::Rect b = c.boundsFast();
            if (!finite(c.initialPoint()) || !finite(c.finalPoint()) || !finite(b.min()) ||
                !finite(b.max()))
                throw InputError(where + ": coordinates are not finite numbers");
        }
    }
}

void require_in_range(const Geom::PathVector& paths, const std::string& where) {
    for (const Geom::Path& p : paths) {
        for (std::size_t i = 0; i < p.size_closed(); ++i) {
            const Geom::Curve& c = p[i];
            bool ok = in_range(c.initialPoint()) && in_range(c.finalPoint());
            if (auto arc = dynamic_cast<const Geom::EllipticalArc*>(&c))
                ok = ok && in_coordinate_range(arc->ray(Geom::X)) &&
                     in_coordinate_range(arc->ray(Geom::Y));
            else if (auto bez = dynamic_cast<const Geom::BezierCurve*>(&c))
                for (unsigned k = 0; k <= bez->order(); ++k) ok = ok && in_range((*bez)[k]);
            if (!ok)
                throw InputError(where +
                                 ": coordinates out of range (the limit is ±1e9 user units)");
        }
    }
}

}  // namespace acanthus::detail
