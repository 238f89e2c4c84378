#include "symmetry/orbit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/spatial_index.hpp"
#include "proxy/overlap.hpp"
#include "symmetry/image_element.hpp"

namespace acanthus::detail {

namespace {

bool near(Point a, Point b, double tolerance) { return distance(a, b) <= tolerance; }

bool same_angle(double a, double b, double tolerance) {
    const double d = std::remainder(a - b, 2 * M_PI);
    return std::abs(d) <= tolerance;
}

// A proxy of the given kind, for images of a lone proxy.
struct AnyProxy {
    PointProxy point;
    CircleProxy circle;
    ArcProxy arc;
    LineSegmentProxy segment;
    BezierProxy bezier;
    PolygonProxy polygon;
    Proxy& of(ProxyKind kind) {
        switch (kind) {
            case ProxyKind::point:
                return point;
            case ProxyKind::circle:
                return circle;
            case ProxyKind::arc:
                return arc;
            case ProxyKind::linesegment:
                return segment;
            case ProxyKind::bezier:
                return bezier;
            case ProxyKind::polygon:
                return polygon;
        }
        return point;
    }
};

bool overlaps_any(const Element& a, const Element& b, double tolerance) {
    for (std::size_t i = 0; i < a.proxy_count(); ++i)
        for (std::size_t j = 0; j < b.proxy_count(); ++j)
            if (boxes_meet(a.proxy(i).bounds(), b.proxy(j).bounds()) &&
                overlaps(a.proxy(i), b.proxy(j), tolerance))
                return true;
    return false;
}

// Null region: the group maps the region onto itself, an image leaves it only with its element.
bool leaves(const Element& e, const Region* region, double tolerance) {
    if (!region) return false;
    for (std::size_t k = 0; k < e.proxy_count(); ++k)
        if (leaves_region(e.proxy(k), *region, tolerance)) return true;
    return false;
}

// True when g is a reflection with no glide and the proxy's ends (a polygon's corners) lie on
// both sides of its mirror: then the proxy crosses the mirror where its image does. The exact
// curve intersection may miss that meeting, the two curves being one continued.
bool crosses_mirror(const Proxy& p, const Isometry& g, double tolerance) {
    // (Points and circles have no ends: told before composing g with itself.)
    if (!g.reverses() || p.kind() == ProxyKind::point || p.kind() == ProxyKind::circle)
        return false;
    const Isometry twice = g.then(g);
    if (std::abs(twice.e) > tolerance || std::abs(twice.f) > tolerance) return false;
    std::vector<Point> ends;
    switch (p.kind()) {
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(p);
            ends = {l.p0, l.p1};
            break;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(p);
            ends = {b.c[0], b.c[3]};
            break;
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(p);
            for (double t : {a.start, a.end})
                ends.push_back(a.center + Vector(std::cos(t), std::sin(t)) * a.radius);
            break;
        }
        case ProxyKind::polygon:
            ends = static_cast<const PolygonProxy&>(p).points;
            break;
        default:
            return false;
    }
    // p to its image is twice p's offset from the mirror, along its normal.
    Vector normal(0, 0);
    for (Point q : ends) {
        const Vector v = g.apply(q) - q;
        if (v.length() <= 2 * tolerance) continue;
        if (normal.length() == 0)
            normal = v;
        else if (normal.dot(v) < 0)
            return true;
    }
    return false;
}

}  // namespace

Rect bounds_of(const Element& e) {
    Rect bounds = e.proxy_count() > 0 ? e.proxy(0).bounds() : Rect{};
    for (std::size_t p = 1; p < e.proxy_count(); ++p) {
        const Rect b = e.proxy(p).bounds();
        bounds = {std::min(bounds.x0, b.x0), std::min(bounds.y0, b.y0), std::max(bounds.x1, b.x1),
                  std::max(bounds.y1, b.y1)};
    }
    return bounds;
}

bool boxes_meet(const Rect& a, const Rect& b) {
    return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

bool same_place(const Proxy& a, const Proxy& b, double t) {
    if (a.kind() != b.kind()) return false;
    switch (a.kind()) {
        case ProxyKind::point:
            return near(static_cast<const PointProxy&>(a).point(),
                        static_cast<const PointProxy&>(b).point(), t);
        case ProxyKind::circle: {
            const auto& p = static_cast<const CircleProxy&>(a);
            const auto& q = static_cast<const CircleProxy&>(b);
            return near(p.center, q.center, t) && std::abs(p.radius - q.radius) <= t;
        }
        case ProxyKind::arc: {
            const auto& p = static_cast<const ArcProxy&>(a);
            const auto& q = static_cast<const ArcProxy&>(b);
            const double angle = t / std::max(p.radius, t);
            return near(p.center, q.center, t) && std::abs(p.radius - q.radius) <= t &&
                   same_angle(p.start, q.start, angle) &&
                   std::abs((p.end - p.start) - (q.end - q.start)) <= angle;
        }
        case ProxyKind::linesegment: {
            const auto& p = static_cast<const LineSegmentProxy&>(a);
            const auto& q = static_cast<const LineSegmentProxy&>(b);
            return (near(p.p0, q.p0, t) && near(p.p1, q.p1, t)) ||
                   (near(p.p0, q.p1, t) && near(p.p1, q.p0, t));
        }
        case ProxyKind::bezier: {
            const auto& p = static_cast<const BezierProxy&>(a);
            const auto& q = static_cast<const BezierProxy&>(b);
            bool forward = true, backward = true;
            for (int k = 0; k < 4; ++k) {
                forward = forward && near(p.c[k], q.c[k], t);
                backward = backward && near(p.c[k], q.c[3 - k], t);
            }
            return forward || backward;
        }
        case ProxyKind::polygon: {
            const auto& p = static_cast<const PolygonProxy&>(a).points;
            const auto& q = static_cast<const PolygonProxy&>(b).points;
            if (p.size() != q.size()) return false;
            for (Point x : p) {
                bool found = false;
                for (Point y : q) found = found || near(x, y, t);
                if (!found) return false;
            }
            return true;
        }
    }
    return false;
}

bool same_place(const Element& a, const Element& b, double tolerance) {
    if (a.proxy_count() != b.proxy_count()) return false;
    for (std::size_t k = 0; k < a.proxy_count(); ++k)
        if (!same_place(a.proxy(k), b.proxy(k), tolerance)) return false;
    return true;
}

Orbit orbit_of(const Element& e, const SymmetryGroup& group, double tolerance) {
    std::vector<std::unique_ptr<ImageElement>> images;
    std::vector<Isometry> transforms;
    std::vector<bool> apart;  // the image's box is clear of the element's bounds
    bool fixed = false;       // some image coincides with e
    const auto& g = group.transforms();
    Orbit out;
    if (g.size() < 2) return out;
    images.reserve(g.size());
    transforms.reserve(g.size());
    apart.reserve(g.size());
    // The element lies within `reach` of the middle of its bounds, so an image under g within
    // `reach` of g(middle). An image whose box is clear of the element's is neither in its
    // place nor overlapping it, and the box alone often tells whether the image is kept: then
    // no scratch image is needed (the margin covers the rounding of the transformed proxies).
    const bool boxed = e.proxy_count() > 0;
    const Rect bounds = bounds_of(e);
    const Point middle = bounds.center();
    const double reach = 0.5 * std::hypot(bounds.width(), bounds.height());
    const double margin =
        10 * tolerance + 1e-9 * (1 + std::abs(middle.x) + std::abs(middle.y) + reach);
    // Only a proxy with ends can cross a mirror (crosses_mirror()): most elements' tests
    // below are skipped at once.
    bool has_ends = false;
    for (std::size_t p = 0; p < e.proxy_count(); ++p) {
        const ProxyKind kind = e.proxy(p).kind();
        has_ends = has_ends || (kind != ProxyKind::point && kind != ProxyKind::circle);
    }
    // Each image is tried in one scratch element; only those kept are built.
    ImageElement scratch(e, g[1]);
    for (std::size_t k = 1; k < g.size(); ++k) {
        const Point q = g[k].apply(middle);
        if (boxed && (std::abs(q.x - middle.x) > reach + bounds.width() / 2 + margin ||
                      std::abs(q.y - middle.y) > reach + bounds.height() / 2 + margin)) {
            const int kept = group.keeps_within(
                Rect{q.x - reach, q.y - reach, q.x + reach, q.y + reach}, margin);
            if (kept == 1) {
                images.push_back(std::make_unique<ImageElement>(e, g[k]));
                transforms.push_back(g[k]);
                apart.push_back(true);
                continue;
            }
            if (kept == 0) {
                for (std::size_t p = 0; has_ends && out.clear && p < e.proxy_count(); ++p)
                    if (crosses_mirror(e.proxy(p), g[k], tolerance)) out.clear = false;
                continue;
            }
        }
        if (k > 1) scratch.set_transform(g[k]);
        if (same_place(scratch, e, tolerance)) {
            fixed = true;
            continue;
        }
        if (!group.keeps(scratch, tolerance)) {
            // Beyond a frieze's ends or the window, not placed; but an element that overlaps it
            // has translates of both (inside the window) that overlap.
            if (out.clear && overlaps_any(scratch, e, tolerance)) out.clear = false;
            for (std::size_t p = 0; has_ends && out.clear && p < e.proxy_count(); ++p)
                if (crosses_mirror(e.proxy(p), g[k], tolerance)) out.clear = false;
            continue;
        }
        images.push_back(std::make_unique<ImageElement>(e, g[k]));
        transforms.push_back(g[k]);
        apart.push_back(false);
    }
    // g(e) = h(e) only when an image other than the identity's coincides with e: only then do
    // the images repeat (once per coset of the stabilizer).
    // Whether the image is clear of e.
    auto check = [&](std::size_t k) {
        // An image whose box is clear of the element's bounds meets none of its proxies' boxes.
        if (out.clear && !apart[k] && overlaps_any(*images[k], e, tolerance)) out.clear = false;
        // (Rosettes keep their tested behaviour: their trees stay as they were.)
        for (std::size_t p = 0; has_ends && out.clear && !group.rosette() && p < e.proxy_count();
             ++p)
            if (crosses_mirror(e.proxy(p), transforms[k], tolerance)) out.clear = false;
    };
    if (!fixed) {  // every image distinct: all kept, in order
        for (std::size_t k = 0; k < images.size(); ++k) check(k);
        out.images = std::move(transforms);
        out.elements = std::move(images);
        return out;
    }
    std::vector<const ImageElement*> kept;
    kept.reserve(images.size());
    out.images.reserve(images.size());
    out.elements.reserve(images.size());
    for (std::size_t k = 0; k < images.size(); ++k) {
        bool repeated = false;
        for (const ImageElement* other : kept)
            repeated = repeated || same_place(*images[k], *other, tolerance);
        if (repeated) continue;
        kept.push_back(images[k].get());
        out.images.push_back(transforms[k]);
        check(k);
        out.elements.push_back(std::move(images[k]));  // `kept` still points to it
    }
    return out;
}

bool orbit_intersects(const Element& e, const SymmetryGroup& group, const Region* region,
                      double tolerance) {
    const Orbit orbit = orbit_of(e, group, tolerance);
    if (!orbit.clear) return true;
    for (const Isometry& g : orbit.images)
        if (leaves(ImageElement(e, g), region, tolerance)) return true;
    return false;
}

bool orbit_intersects(const Proxy& p, const SymmetryGroup& group, const Region* region,
                      double tolerance) {
    AnyProxy image;
    Proxy& q = image.of(p.kind());
    const auto& g = group.transforms();
    for (std::size_t k = 1; k < g.size(); ++k) {
        transform_proxy(p, g[k], q);
        if (same_place(q, p, tolerance)) continue;
        if (!group.rosette() && crosses_mirror(p, g[k], tolerance)) return true;
        if (boxes_meet(q.bounds(), p.bounds()) && overlaps(q, p, tolerance)) return true;
        if (region && leaves_region(q, *region, tolerance)) return true;
    }
    return false;
}

bool same_isometry(const Isometry& a, const Isometry& b, double tolerance) {
    return std::abs(a.a - b.a) <= 1e-9 && std::abs(a.b - b.b) <= 1e-9 &&
           std::abs(a.c - b.c) <= 1e-9 && std::abs(a.d - b.d) <= 1e-9 &&
           std::abs(a.e - b.e) <= tolerance && std::abs(a.f - b.f) <= tolerance;
}

std::vector<std::optional<Orbit>> placeable_orbits(
    const std::vector<const Element*>& batch, const SymmetryGroup& group, const Region* region,
    double tolerance, const std::function<bool(const Proxy&)>& hits_placed_image,
    const std::function<bool(const Element&, const Proxy&, const Isometry&)>& hits_placed) {
    std::vector<std::optional<Orbit>> out;
    out.reserve(batch.size());
    const bool every_image = static_cast<bool>(hits_placed);
    // The images of the elements kept so far (and the elements: every_image); made only for a
    // batch of several (most are one element).
    std::optional<SpatialIndex> index;
    if (batch.size() > 1) index.emplace();
    std::vector<const Element*> images;
    std::vector<Isometry> transforms;  // of each entry of `images`
    // True when the proxy, of the image under `g`, overlaps an indexed element or image under
    // another transformation (all of them when `any`).
    auto hits_batch = [&](const Proxy& p, const Isometry& g, bool any) {
        if (!index) return false;
        return index->any_of(p.bounds(), [&](SpatialIndex::Entry en) {
            const auto k = static_cast<std::size_t>(en.element);
            if (!any && same_isometry(transforms[k], g, tolerance)) return false;
            return overlaps(p, images[k]->proxy(static_cast<std::size_t>(en.proxy)), tolerance);
        });
    };
    auto add = [&](const Element& e, const Isometry& g) {
        const int id = static_cast<int>(images.size());
        for (std::size_t k = 0; k < e.proxy_count(); ++k)
            index->insert(id, static_cast<int>(k), e.proxy(k).bounds());
        images.push_back(&e);
        transforms.push_back(g);
    };
    const Isometry identity{};
    for (std::size_t n = 0; n < batch.size(); ++n) {
        const Element* e = batch[n];
        Orbit orbit = orbit_of(*e, group, tolerance);
        bool ok = orbit.clear;
        for (std::size_t k = 0; ok && k < orbit.elements.size(); ++k)
            ok = !leaves(*orbit.elements[k], region, tolerance);
        for (std::size_t k = 0; ok && k < e->proxy_count(); ++k) {
            const Proxy& p = e->proxy(k);
            if (hits_placed_image(p)) {
                ok = false;
                break;
            }
            ok = !hits_batch(p, identity, !every_image);
        }
        for (std::size_t i = 0; ok && every_image && i < orbit.elements.size(); ++i) {
            ImageElement& image = *orbit.elements[i];
            for (std::size_t k = 0; ok && k < image.proxy_count(); ++k) {
                const Proxy& p = image.proxy(k);
                ok = !hits_placed(*e, p, orbit.images[i]) && !hits_batch(p, orbit.images[i], false);
            }
        }
        if (!ok) {
            out.emplace_back(std::nullopt);
            continue;
        }
        // The last element's images are checked by no later one.
        if (n + 1 < batch.size()) {
            if (every_image) add(*e, identity);
            for (std::size_t i = 0; i < orbit.elements.size(); ++i)
                add(*orbit.elements[i], orbit.images[i]);
        }
        out.emplace_back(std::move(orbit));
    }
    return out;
}

}  // namespace acanthus::detail
