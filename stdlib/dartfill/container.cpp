#include "container.hpp"

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "field/pixel_cover.hpp"

namespace acanthus::dartfill {
namespace {

using acanthus::detail::PixelCover;
using acanthus::detail::SpatialIndex;

double triangle_area(const Triangle& t) { return std::abs((t[1] - t[0]).cross(t[2] - t[0])) / 2; }

// +1 / -1 when a horizontal ray from p to +x crosses edge ab upward / downward, else 0.
int crossing_direction(Point a, Point b, Point p) {
    bool up = a.y <= p.y && p.y < b.y, down = b.y <= p.y && p.y < a.y;
    if (!up && !down) return 0;
    double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
    if (x <= p.x) return 0;
    return up ? 1 : -1;
}

int ring_winding(const std::vector<Point>& ring, Point p) {
    int w = 0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i)
        w += crossing_direction(ring[i], ring[(i + 1) % n], p);
    return w;
}

}  // namespace

GridFrame make_grid(Rect bounds, int resolution) {
    if (resolution < 8) throw InputError("dartfill: resolution must be at least 8 pixels");
    double longer = std::max(bounds.width(), bounds.height());
    if (!(longer > 0) || !std::isfinite(longer))
        throw InputError("dartfill: the space to fill has no extent");
    // One pixel of margin all round, so that the outside of the space is always an obstacle.
    GridFrame g;
    g.pixel = longer / resolution;
    g.x0 = bounds.x0 - g.pixel;
    g.y0 = bounds.y0 - g.pixel;
    g.width = std::max(1, static_cast<int>(std::ceil(bounds.width() / g.pixel - 1e-9))) + 2;
    g.height = std::max(1, static_cast<int>(std::ceil(bounds.height() / g.pixel - 1e-9))) + 2;
    return g;
}

void shape_pixels(const GridFrame& grid, const PlacedShape& shape, std::vector<int>& out) {
    PixelCover(grid).centers_inside({shape.outline()}, /*evenodd=*/true, out);
    const auto& tris = shape.triangles();
    if (!tris.empty()) {
        const Triangle& t = tris.front();
        Point c{(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3};
        int i = static_cast<int>(std::floor((c.x - grid.x0) / grid.pixel));
        int j = static_cast<int>(std::floor((c.y - grid.y0) / grid.pixel));
        if (i >= 0 && j >= 0 && i < grid.width && j < grid.height)
            out.push_back(j * grid.width + i);
    }
}

RingContainer::RingContainer(std::vector<std::vector<Point>> rings, bool evenodd)
    : rings_(std::move(rings)), evenodd_(evenodd) {
    double inf = std::numeric_limits<double>::infinity();
    bounds_ = {inf, inf, -inf, -inf};
    std::vector<std::pair<SpatialIndex::Entry, Rect>> boxes;
    for (const auto& ring : rings_) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
            Point a = ring[i], b = ring[(i + 1) % n];
            if (!a.finite()) throw InputError("dartfill: the panel has a non-finite coordinate");
            bounds_ = {std::min(bounds_.x0, a.x), std::min(bounds_.y0, a.y),
                       std::max(bounds_.x1, a.x), std::max(bounds_.y1, a.y)};
            if (a == b) continue;
            Rect box{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                     std::max(a.y, b.y)};
            boxes.push_back({{static_cast<int>(edges_.size()), 0}, box});
            edges_.push_back({a, b});
        }
    }
    if (edges_.empty()) throw InputError("dartfill: the panel has no boundary");
    index_ = SpatialIndex(boxes);
    // Rings nested at odd depth are holes (either fill rule, for rings that do not cross).
    for (const auto& ring : rings_) {
        if (ring.size() < 3) continue;
        int depth = 0;
        for (const auto& other : rings_)
            if (&other != &ring && other.size() >= 3 && ring_winding(other, ring.front()) != 0)
                ++depth;
        area_ += (depth % 2 == 0 ? 1 : -1) * std::abs(signed_area(ring));
    }
}

std::unique_ptr<RingContainer> RingContainer::from_region(const Region& region) {
    Rect b = region.bounds();
    double size = std::max(b.width(), b.height());
    auto c = std::make_unique<RingContainer>(region.rings(size * 1e-4), region.evenodd());
    c->area_ = region.area();
    return c;
}

bool RingContainer::contains(Point p) const {
    int winding = 0, crossings = 0;
    for (const Edge& e : edges_) {
        int w = crossing_direction(e.a, e.b, p);
        winding += w;
        crossings += w != 0;
    }
    return evenodd_ ? crossings % 2 == 1 : winding != 0;
}

bool RingContainer::admits(const PlacedShape& shape, double tolerance) const {
    Rect sb = shape.bounds();
    if (sb.x0 < bounds_.x0 - tolerance || sb.y0 < bounds_.y0 - tolerance ||
        sb.x1 > bounds_.x1 + tolerance || sb.y1 > bounds_.y1 + tolerance)
        return false;
    // No boundary edge may enter a triangle: then the shape is wholly inside or wholly outside.
    const auto& tris = shape.triangles();
    const bool edge_enters = index_.any_of(sb, [&](SpatialIndex::Entry entry) {
        const Edge& e = edges_[entry.element];
        Rect eb{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                std::max(e.a.y, e.b.y)};
        Triangle segment{e.a, e.b, e.b};
        for (std::size_t k = 0; k < tris.size(); ++k)
            if (boxes_meet(eb, shape.triangle_bounds()[k]) &&
                triangles_overlap(tris[k], segment, tolerance))
                return true;
        return false;
    });
    if (edge_enters) return false;
    // The largest triangle's centroid is farther from the boundary than any tolerance.
    std::size_t best = 0;
    for (std::size_t k = 1; k < tris.size(); ++k)
        if (triangle_area(tris[k]) > triangle_area(tris[best])) best = k;
    const Triangle& t = tris[best];
    return contains({(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3});
}

std::vector<std::uint8_t> RingContainer::rasterize(const GridFrame& grid) const {
    std::vector<std::uint8_t> occupancy(static_cast<std::size_t>(grid.width) * grid.height, 1);
    std::vector<int> inside;
    PixelCover(grid).centers_inside(rings_, evenodd_, inside);
    for (int p : inside) occupancy[p] = 0;
    return occupancy;
}

}  // namespace acanthus::dartfill
