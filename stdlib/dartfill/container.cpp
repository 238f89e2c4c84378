#include "container.hpp"

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <limits>

namespace acanthus::dartfill {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using Box = bg::model::box<BoxPoint>;
using Entry = std::pair<Box, std::size_t>;

Box to_box(const Rect& r) { return Box(BoxPoint(r.x0, r.y0), BoxPoint(r.x1, r.y1)); }

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
    // Scanline over the outline: each edge adds its crossings with the rows of pixel centres
    // (half-open in y, so a vertex on a row is counted once), then each row fills between pairs.
    thread_local std::vector<std::pair<int, double>> crossings;
    crossings.clear();
    const std::vector<Point>& ring = shape.outline();
    for (std::size_t k = 0, n = ring.size(); k < n; ++k) {
        Point a = ring[k], b = ring[(k + 1) % n];
        if (a.y == b.y) continue;
        double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
        // Rows j with lo <= y0 + (j + 0.5) pixel < hi.
        int j0 = std::max(0, static_cast<int>(std::ceil((lo - grid.y0) / grid.pixel - 0.5)));
        int j1 = std::min(grid.height - 1,
                          static_cast<int>(std::ceil((hi - grid.y0) / grid.pixel - 0.5)) - 1);
        double slope = (b.x - a.x) / (b.y - a.y);
        for (int j = j0; j <= j1; ++j) {
            double y = grid.y0 + (j + 0.5) * grid.pixel;
            crossings.emplace_back(j, a.x + (y - a.y) * slope);
        }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        int j = crossings[k].first;
        if (crossings[k + 1].first != j) {  // a lone crossing (rounding at a vertex): resync
            --k;
            continue;
        }
        // Pixels whose centres lie in [x_k, x_k+1).
        int i0 = static_cast<int>(std::ceil((crossings[k].second - grid.x0) / grid.pixel - 0.5));
        int i1 =
            static_cast<int>(std::ceil((crossings[k + 1].second - grid.x0) / grid.pixel - 0.5));
        for (int i = std::max(i0, 0); i < std::min(i1, grid.width); ++i)
            out.push_back(j * grid.width + i);
    }
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

struct RingContainer::Index {
    bgi::rtree<Entry, bgi::rstar<16>> tree;
};

RingContainer::RingContainer(std::vector<std::vector<Point>> rings, bool evenodd)
    : evenodd_(evenodd), index_(std::make_unique<Index>()) {
    double inf = std::numeric_limits<double>::infinity();
    bounds_ = {inf, inf, -inf, -inf};
    for (const auto& ring : rings) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
            Point a = ring[i], b = ring[(i + 1) % n];
            if (!a.finite()) throw InputError("dartfill: the panel has a non-finite coordinate");
            bounds_ = {std::min(bounds_.x0, a.x), std::min(bounds_.y0, a.y),
                       std::max(bounds_.x1, a.x), std::max(bounds_.y1, a.y)};
            if (a == b) continue;
            Rect box{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                     std::max(a.y, b.y)};
            index_->tree.insert({to_box(box), edges_.size()});
            edges_.push_back({a, b});
        }
    }
    if (edges_.empty()) throw InputError("dartfill: the panel has no boundary");
    // Rings nested at odd depth are holes (either fill rule, for rings that do not cross).
    for (const auto& ring : rings) {
        if (ring.size() < 3) continue;
        int depth = 0;
        for (const auto& other : rings)
            if (&other != &ring && other.size() >= 3 && ring_winding(other, ring.front()) != 0)
                ++depth;
        area_ += (depth % 2 == 0 ? 1 : -1) * std::abs(signed_area(ring));
    }
}

RingContainer::~RingContainer() = default;

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
    for (auto it = index_->tree.qbegin(bgi::intersects(to_box(sb))); it != index_->tree.qend();
         ++it) {
        const Edge& e = edges_[it->second];
        Rect eb{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                std::max(e.a.y, e.b.y)};
        Triangle segment{e.a, e.b, e.b};
        for (std::size_t k = 0; k < tris.size(); ++k)
            if (boxes_meet(eb, shape.triangle_bounds()[k]) &&
                triangles_overlap(tris[k], segment, tolerance))
                return false;
    }
    // The largest triangle's centroid is farther from the boundary than any tolerance.
    std::size_t best = 0;
    for (std::size_t k = 1; k < tris.size(); ++k)
        if (triangle_area(tris[k]) > triangle_area(tris[best])) best = k;
    const Triangle& t = tris[best];
    return contains({(t[0].x + t[1].x + t[2].x) / 3, (t[0].y + t[1].y + t[2].y) / 3});
}

std::vector<std::uint8_t> RingContainer::rasterize(const GridFrame& grid) const {
    std::vector<std::uint8_t> occupancy(static_cast<std::size_t>(grid.width) * grid.height, 1);
    std::vector<std::pair<double, int>> crossings;
    for (int j = 0; j < grid.height; ++j) {
        double y = grid.y0 + (j + 0.5) * grid.pixel;
        crossings.clear();
        for (const Edge& e : edges_) {
            bool up = e.a.y <= y && y < e.b.y, down = e.b.y <= y && y < e.a.y;
            if (!up && !down) continue;
            double x = e.a.x + (y - e.a.y) / (e.b.y - e.a.y) * (e.b.x - e.a.x);
            crossings.emplace_back(x, up ? 1 : -1);
        }
        std::sort(crossings.begin(), crossings.end());
        int winding = 0, count = 0;
        for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
            winding += crossings[k].second;
            ++count;
            bool in = evenodd_ ? count % 2 == 1 : winding != 0;
            if (!in) continue;
            // Pixels whose centres lie in [x_k, x_k+1).
            int i0 = static_cast<int>(std::ceil((crossings[k].first - grid.x0) / grid.pixel - 0.5));
            int i1 =
                static_cast<int>(std::ceil((crossings[k + 1].first - grid.x0) / grid.pixel - 0.5));
            for (int i = std::max(i0, 0); i < std::min(i1, grid.width); ++i)
                occupancy[static_cast<std::size_t>(j) * grid.width + i] = 0;
        }
    }
    return occupancy;
}

}  // namespace acanthus::dartfill
