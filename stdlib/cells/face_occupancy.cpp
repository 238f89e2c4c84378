// 2-D occupancy maps of faces [3.3], exact: the face's polygon less the claims, by Clipper
// booleans on the claims and rings near the query.
#include "face_occupancy.hpp"

#include <algorithm>
#include <cmath>

#include "facade_data.hpp"

namespace acanthus::cells::detail {

namespace {

// True when segment ab passes through the open interior of r.
bool crosses_interior(Point a, Point b, Rect r) {
    double t0 = 0, t1 = 1;
    double dx = b.x - a.x, dy = b.y - a.y;
    auto clip = [&](double p, double q) {  // p t < q
        if (p == 0) return q > 0;
        double t = q / p;
        if (p < 0) {
            if (t > t1) return false;
            t0 = std::max(t0, t);
        } else {
            if (t < t0) return false;
            t1 = std::min(t1, t);
        }
        return true;
    };
    if (!clip(-dx, a.x - r.x0) || !clip(dx, r.x1 - a.x) || !clip(-dy, a.y - r.y0) ||
        !clip(dy, r.y1 - a.y))
        return false;
    if (t1 <= t0) return false;
    // The part inside the closed rectangle must not run along its border only.
    double tm = (t0 + t1) / 2;
    Point m{a.x + dx * tm, a.y + dy * tm};
    double eps = 1e-9 * std::max({1.0, std::abs(r.x1), std::abs(r.y1)});
    return m.x > r.x0 + eps && m.x < r.x1 - eps && m.y > r.y0 + eps && m.y < r.y1 - eps;
}

}  // namespace

FaceOccupancyData::FaceOccupancyData(const FacadeData& facade, int face)
    : scale_{facade.scale}, rings_(facade.face_rings[static_cast<std::size_t>(face)]) {
    const Face& f = facade.faces[static_cast<std::size_t>(face)];
    bounds_ = f.bounds;
    double w = std::max(bounds_.width(), 1e-9), h = std::max(bounds_.height(), 1e-9);
    double cell = std::max(w, h) / 256;
    nx_ = std::clamp(static_cast<int>(std::ceil(w / cell)), 1, 256);
    ny_ = std::clamp(static_cast<int>(std::ceil(h / cell)), 1, 256);
    cell_w_ = w / nx_;
    cell_h_ = h / ny_;
    edge_buckets_.resize(static_cast<std::size_t>(nx_ * ny_));
    claim_buckets_.resize(static_cast<std::size_t>(nx_ * ny_));
    for (const std::vector<Point>& loop : f.loops) {
        ring_boxes_.push_back(bounds_of(loop));
        for (std::size_t k = 0; k < loop.size(); ++k) {
            RingEdge e{loop[k], loop[(k + 1) % loop.size()]};
            int index = static_cast<int>(ring_edges_.size());
            ring_edges_.push_back(e);
            Rect box{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                     std::max(e.a.y, e.b.y)};
            for_buckets(
                box, [&](int b) { edge_buckets_[static_cast<std::size_t>(b)].push_back(index); });
        }
    }
}

template <class F>
void FaceOccupancyData::for_buckets(Rect r, F&& f) const {
    int i0 = std::clamp(static_cast<int>(std::floor((r.x0 - bounds_.x0) / cell_w_)), 0, nx_ - 1);
    int i1 = std::clamp(static_cast<int>(std::floor((r.x1 - bounds_.x0) / cell_w_)), 0, nx_ - 1);
    int j0 = std::clamp(static_cast<int>(std::floor((r.y0 - bounds_.y0) / cell_h_)), 0, ny_ - 1);
    int j1 = std::clamp(static_cast<int>(std::floor((r.y1 - bounds_.y0) / cell_h_)), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) f(j * nx_ + i);
}

void FaceOccupancyData::claim(ClipperLib::Path path, Rect box) {
    int index = static_cast<int>(claims_.size());
    claimed_area_ += std::abs(ClipperLib::Area(path)) / (scale_.scale * scale_.scale);
    claims_.push_back(std::move(path));
    claim_boxes_.push_back(box);
    for_buckets(box, [&](int b) { claim_buckets_[static_cast<std::size_t>(b)].push_back(index); });
}

bool FaceOccupancyData::inside(Point p) const {
    ClipperLib::IntPoint q = scale_.to_int(p);
    int parity = 0;
    for (std::size_t k = 0; k < rings_.size(); ++k) {
        if (!ring_boxes_[k].contains(p)) continue;
        if (ClipperLib::PointInPolygon(q, rings_[k]) != 0) parity ^= 1;
    }
    return parity != 0;
}

bool FaceOccupancyData::rect_is_free(Rect r) const {
    bool free = true;
    for_buckets(r, [&](int b) {
        if (!free) return;
        for (int e : edge_buckets_[static_cast<std::size_t>(b)]) {
            const RingEdge& edge = ring_edges_[static_cast<std::size_t>(e)];
            if (crosses_interior(edge.a, edge.b, r)) {
                free = false;
                return;
            }
        }
        for (int c : claim_buckets_[static_cast<std::size_t>(b)])
            if (overlaps(claim_boxes_[static_cast<std::size_t>(c)], r)) {
                free = false;
                return;
            }
    });
    return free && inside(r.center());
}

std::vector<std::vector<Point>> FaceOccupancyData::free_part(
    const std::vector<Point>& polygon) const {
    Rect box = bounds_of(polygon);
    ClipperLib::Clipper in_face;
    in_face.AddPath(scale_.to_path(polygon), ClipperLib::ptSubject, true);
    for (std::size_t k = 0; k < rings_.size(); ++k)
        if (overlaps(ring_boxes_[k], box)) in_face.AddPath(rings_[k], ClipperLib::ptClip, true);
    ClipperLib::Paths inside_face;
    in_face.Execute(ClipperLib::ctIntersection, inside_face, ClipperLib::pftNonZero,
                    ClipperLib::pftEvenOdd);
    std::vector<int> near;
    for_buckets(box, [&](int b) {
        for (int c : claim_buckets_[static_cast<std::size_t>(b)])
            if (overlaps(claim_boxes_[static_cast<std::size_t>(c)], box)) near.push_back(c);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    ClipperLib::Paths result = std::move(inside_face);
    if (!near.empty() && !result.empty()) {
        ClipperLib::Clipper minus;
        minus.AddPaths(result, ClipperLib::ptSubject, true);
        for (int c : near)
            minus.AddPath(claims_[static_cast<std::size_t>(c)], ClipperLib::ptClip, true);
        ClipperLib::Paths rest;
        minus.Execute(ClipperLib::ctDifference, rest, ClipperLib::pftNonZero,
                      ClipperLib::pftNonZero);
        result = std::move(rest);
    }
    std::vector<std::vector<Point>> out;
    // Pieces thinner than a millionth of the query are rounding, not room.
    double tiny = 1e-6 * std::max(box.width() * box.height(), 1e-300);
    for (const ClipperLib::Path& p : result)
        if (ClipperLib::Orientation(p) && scale_.area({p}) > tiny)
            out.push_back(scale_.to_polygon(p));
    return out;
}

}  // namespace acanthus::cells::detail

namespace acanthus::cells {

FaceOccupancy::FaceOccupancy(const Facade& facade, int face)
    : data_(std::make_unique<detail::FaceOccupancyData>(facade.data(), face)) {}
FaceOccupancy::~FaceOccupancy() = default;
FaceOccupancy::FaceOccupancy(FaceOccupancy&&) noexcept = default;
FaceOccupancy& FaceOccupancy::operator=(FaceOccupancy&&) noexcept = default;

void FaceOccupancy::claim(const std::vector<Point>& polygon) {
    data_->claim(data_->scale().to_path(polygon), detail::bounds_of(polygon));
}
void FaceOccupancy::claim(Rect rect) { data_->claim(data_->scale().to_path(rect), rect); }
std::vector<std::vector<Point>> FaceOccupancy::free_part(const std::vector<Point>& polygon) const {
    return data_->free_part(polygon);
}
bool FaceOccupancy::rect_is_free(Rect rect) const { return data_->rect_is_free(rect); }
double FaceOccupancy::claimed_area() const { return data_->claimed_area(); }

}  // namespace acanthus::cells
