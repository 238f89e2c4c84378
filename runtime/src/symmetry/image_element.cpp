#include "symmetry/image_element.hpp"

namespace acanthus::detail {

void transform_proxy(const Proxy& in, const Isometry& g, Proxy& out) {
    switch (in.kind()) {
        case ProxyKind::point:
            static_cast<PointProxy&>(out).set(g.apply(static_cast<const PointProxy&>(in).point()));
            break;
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(in);
            static_cast<CircleProxy&>(out).set(g.apply(c.center), c.radius);
            break;
        }
        case ProxyKind::arc: {
            // A reflection turns the counter-clockwise arc s..e into one from e's image to s's.
            const auto& a = static_cast<const ArcProxy&>(in);
            const double sweep = a.end - a.start;
            const double start = g.apply_angle(g.reverses() ? a.end : a.start);
            static_cast<ArcProxy&>(out).set(g.apply(a.center), a.radius, start, start + sweep);
            break;
        }
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(in);
            static_cast<LineSegmentProxy&>(out).set(g.apply(l.p0), g.apply(l.p1));
            break;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(in);
            static_cast<BezierProxy&>(out).set(g.apply(b.c[0]), g.apply(b.c[1]), g.apply(b.c[2]),
                                               g.apply(b.c[3]));
            break;
        }
        case ProxyKind::polygon: {
            const auto& p = static_cast<const PolygonProxy&>(in);
            std::vector<Point> points;
            points.reserve(p.points.size());
            for (Point q : p.points) points.push_back(g.apply(q));
            static_cast<PolygonProxy&>(out).set(std::move(points));
            break;
        }
    }
}

ImageElement::ImageElement(const Element& original, const Isometry& transform)
    : original_(&original), transform_(transform) {
    sterile = true;
    depth = original.depth;
    count_ = original.proxy_count();
    if (count_ > 1) more_.resize(count_ - 1);
    for (std::size_t k = 0; k < count_; ++k) {
        const Proxy& p = original.proxy(k);
        AnyProxy& out = slot(k);
        switch (p.kind()) {
            case ProxyKind::point:
                out.emplace<PointProxy>();
                break;
            case ProxyKind::circle:
                out.emplace<CircleProxy>();
                break;
            case ProxyKind::arc:
                out.emplace<ArcProxy>();
                break;
            case ProxyKind::linesegment:
                out.emplace<LineSegmentProxy>();
                break;
            case ProxyKind::bezier:
                out.emplace<BezierProxy>();
                break;
            case ProxyKind::polygon:
                out.emplace<PolygonProxy>();
                break;
        }
        transform_proxy(p, transform, proxy(k));
    }
}

void ImageElement::set_transform(const Isometry& transform) {
    transform_ = transform;
    for (std::size_t k = 0; k < count_; ++k)
        transform_proxy(original_->proxy(k), transform, proxy(k));
}

Proxy& ImageElement::proxy(std::size_t k) {
    return std::visit([](auto& p) -> Proxy& { return p; }, slot(k));
}

}  // namespace acanthus::detail
