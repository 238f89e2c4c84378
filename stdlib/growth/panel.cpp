#include "panel.hpp"

#include <acanthus/environment.hpp>
#include <acanthus/proxy.hpp>

#include "proxy/overlap.hpp"

namespace acanthus::growth::detail {

bool RegionPanel::admits(Circle motif, double tolerance) const {
    return region_.contains(motif.center) &&
           region_.distance_to_boundary(motif.center) >= motif.radius - tolerance;
}

bool EnvironmentPanel::contains(Point p) const { return env_.inside(p); }

bool EnvironmentPanel::symmetric() const { return env_.symmetric(); }

Rect EnvironmentPanel::bounds() const { return env_.region() ? env_.region()->bounds() : Rect{}; }

double EnvironmentPanel::clearance(Point p) const { return env_.distance_to_boundary(p); }

double EnvironmentPanel::area() const {
    return env_.region() ? env_.region()->area() : Panel::area();
}

bool EnvironmentPanel::admits(Circle motif, double tolerance) const {
    if (!env_.inside(motif.center) ||
        env_.distance_to_boundary(motif.center) < motif.radius - tolerance)
        return false;
    // The outline, a curve, meets every element it crosses or lies in, but not the seed point
    // synthesis starts on (points never overlap curves): the motif replaces its seed.
    ArcProxy outline;
    outline.set(motif.center, motif.radius, 0, 2 * M_PI);
    if (env_.intersects(outline)) return false;
    // An element wholly inside the circle is nearer to its centre than the radius.
    if (const Element* e = env_.nearest_element(motif.center))
        for (std::size_t k = 0; k < e->proxy_count(); ++k) {
            const Proxy& p = e->proxy(k);
            if (p.kind() != ProxyKind::point && p.is_set() &&
                acanthus::detail::distance_to(p, motif.center) < motif.radius - tolerance)
                return false;
        }
    return true;
}

}  // namespace acanthus::growth::detail
