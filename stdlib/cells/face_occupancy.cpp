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

// |area| of a rectangle's integer path, summed as ClipperLib::Area sums it.
double rect_area(const IntScale& s, Rect r) {
    ClipperLib::IntPoint p[4] = {s.to_int({r.x0, r.y0}), s.to_int({r.x1, r.y0}),
                                 s.to_int({r.x1, r.y1}), s.to_int({r.x0, r.y1})};
    double a = 0;
    for (int i = 0, j = 3; i < 4; j = i++)
        a += (static_cast<double>(p[j].X) + static_cast<double>(p[i].X)) *
             (static_cast<double>(p[j].Y) - static_cast<double>(p[i].Y));
    return std::abs(a * 0.5);
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
    const auto buckets = static_cast<std::size_t>(nx_ * ny_);
    claim_head_.assign(buckets, -1);
    bucket_inside_.assign(buckets, -1);
    for (const std::vector<Point>& loop : f.loops) {
        int ring = static_cast<int>(ring_boxes_.size());
        ring_boxes_.push_back(bounds_of(loop));
        for_buckets(ring_boxes_.back(), [&](int b) { ring_buckets_.add(b, ring); });
        for (std::size_t k = 0; k < loop.size(); ++k) {
            RingEdge e{loop[k], loop[(k + 1) % loop.size()]};
            int index = static_cast<int>(ring_edges_.size());
            ring_edges_.push_back(e);
            Rect box{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                     std::max(e.a.y, e.b.y)};
            for_buckets(box, [&](int b) { edge_buckets_.add(b, index); });
        }
    }
    for (const ClipperLib::Path& ring : rings_)
        for (std::size_t k = 0; k < ring.size(); ++k) {
            RingEdge e{scale_.to_point(ring[k]), scale_.to_point(ring[(k + 1) % ring.size()])};
            int index = static_cast<int>(int_edges_.size());
            int_edges_.push_back(e);
            Rect box{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                     std::max(e.a.y, e.b.y)};
            for_buckets(box, [&](int b) { int_edge_buckets_.add(b, index); });
        }
    for (int e : f.edges)
        for_buckets(facade.edges[static_cast<std::size_t>(e)].bounds,
                    [&](int b) { feature_edge_buckets_.add(b, e); });
    for (BucketLists* lists :
         {&ring_buckets_, &edge_buckets_, &int_edge_buckets_, &feature_edge_buckets_})
        lists->finish(nx_ * ny_);
}

void BucketLists::finish(int buckets) {
    start_.assign(static_cast<std::size_t>(buckets) + 1, 0);
    for (const auto& [b, item] : pairs_) ++start_[static_cast<std::size_t>(b) + 1];
    for (std::size_t b = 0; b < static_cast<std::size_t>(buckets); ++b) start_[b + 1] += start_[b];
    items_.resize(pairs_.size());
    std::vector<int> next(start_.begin(), start_.end() - 1);
    for (const auto& [b, item] : pairs_)
        items_[static_cast<std::size_t>(next[static_cast<std::size_t>(b)]++)] = item;
    pairs_ = {};
}

void FaceOccupancyData::link_claim(int bucket, int claim) {
    int& head = claim_head_[static_cast<std::size_t>(bucket)];
    claim_links_.push_back({claim, head});
    head = static_cast<int>(claim_links_.size()) - 1;
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

int FaceOccupancyData::bucket_of(Point p) const {
    int i = std::clamp(static_cast<int>(std::floor((p.x - bounds_.x0) / cell_w_)), 0, nx_ - 1);
    int j = std::clamp(static_cast<int>(std::floor((p.y - bounds_.y0) / cell_h_)), 0, ny_ - 1);
    return j * nx_ + i;
}

void FaceOccupancyData::claim(ClipperLib::Path path, Rect box) {
    int index = static_cast<int>(claims_.size());
    claimed_area_ += std::abs(ClipperLib::Area(path)) / (scale_.scale * scale_.scale);
    claims_.push_back({box, static_cast<int>(claim_paths_.size())});
    claim_paths_.push_back(std::move(path));
    for_buckets(box, [&](int b) { link_claim(b, index); });
}

void FaceOccupancyData::claim(Rect rect) {
    int index = static_cast<int>(claims_.size());
    claimed_area_ += rect_area(scale_, rect) / (scale_.scale * scale_.scale);
    claims_.push_back({rect, -1});
    for_buckets(rect, [&](int b) { link_claim(b, index); });
}

// Even-odd over the rings whose box holds p: all of them are listed in p's bucket.
bool FaceOccupancyData::inside_rings(Point p) const {
    ClipperLib::IntPoint q = scale_.to_int(p);
    int parity = 0;
    for (int k : ring_buckets_[static_cast<std::size_t>(bucket_of(p))]) {
        if (!ring_boxes_[static_cast<std::size_t>(k)].contains(p)) continue;
        if (ClipperLib::PointInPolygon(q, rings_[static_cast<std::size_t>(k)]) != 0) parity ^= 1;
    }
    return parity != 0;
}

bool FaceOccupancyData::inside(Point p) const { return inside_rings(p); }

void FaceOccupancyData::edges_near(Rect r, std::vector<int>& out) const {
    out.clear();
    for_buckets(r, [&](int b) {
        std::span<const int> edges = feature_edge_buckets_[static_cast<std::size_t>(b)];
        out.insert(out.end(), edges.begin(), edges.end());
    });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
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
        for (int l = claim_head_[static_cast<std::size_t>(b)]; l >= 0; l = link(l).next)
            if (overlaps(claims_[static_cast<std::size_t>(link(l).claim)].box, r)) {
                free = false;
                return;
            }
    });
    if (!free) return false;
    // No ring edge crosses r, so r is wholly in or out, as is a bucket no ring edge reaches, and
    // r's centre (on no ring edge, r having area) lies in its bucket: the bucket's status is r's.
    // The bucket's own centre, half a bucket from any ring edge, decides it once, safe from the
    // rounding of the integer rings.
    Point c = r.center();
    int bucket = bucket_of(c);
    auto b = static_cast<std::size_t>(bucket);
    // (A centre beyond the face's bounds sits in no bucket: bucket_of() only clamps it.)
    if (!(r.width() > 0 && r.height() > 0) || !bounds_.contains(c) || !edge_buckets_[b].empty())
        return inside_rings(c);
    if (bucket_inside_[b] < 0) {
        Point middle{bounds_.x0 + (bucket % nx_ + 0.5) * cell_w_,
                     bounds_.y0 + (bucket / nx_ + 0.5) * cell_h_};
        bucket_inside_[b] = inside_rings(middle) ? 1 : 0;
    }
    return bucket_inside_[b] == 1;
}

bool FaceOccupancyData::snapped_rect_is_free(Rect r) const {
    auto snap = [&](double v) {  // as IntScale::to_point(to_int(p)) does
        return static_cast<double>(std::llround(v * scale_.scale)) / scale_.scale;
    };
    bool free = true;
    for_buckets(r, [&](int b) {
        if (!free) return;
        for (int k : int_edge_buckets_[static_cast<std::size_t>(b)]) {
            const RingEdge& e = int_edges_[static_cast<std::size_t>(k)];
            Rect box{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y), std::max(e.a.x, e.b.x),
                     std::max(e.a.y, e.b.y)};
            bool across;
            if (e.a.y == e.b.y)  // horizontal: inside r's rows, overlapping its columns
                across = e.a.y > r.y0 && e.a.y < r.y1 && box.x0 < r.x1 && box.x1 > r.x0;
            else if (e.a.x == e.b.x)
                across = e.a.x > r.x0 && e.a.x < r.x1 && box.y0 < r.y1 && box.y1 > r.y0;
            else  // slanted: exact only when its box stays clear of r
                across = overlaps(box, r);
            if (across) {
                free = false;
                return;
            }
        }
        for (int l = claim_head_[static_cast<std::size_t>(b)]; l >= 0; l = link(l).next) {
            const Rect& box = claims_[static_cast<std::size_t>(link(l).claim)].box;
            // On the grid, as the booleans see it (rounding is monotone, so the float test
            // finds every candidate).
            if (overlaps(box, r) &&
                overlaps({snap(box.x0), snap(box.y0), snap(box.x1), snap(box.y1)}, r)) {
                free = false;
                return;
            }
        }
    });
    return free && inside_rings(r.center());
}

std::vector<std::vector<Point>> FaceOccupancyData::free_part(
    const std::vector<Point>& polygon) const {
    Rect box = bounds_of(polygon);
    ClipperLib::Clipper in_face;
    in_face.AddPath(scale_.to_path(polygon), ClipperLib::ptSubject, true);
    std::vector<int> near;
    for_buckets(box, [&](int b) {
        for (int k : ring_buckets_[static_cast<std::size_t>(b)])
            if (overlaps(ring_boxes_[static_cast<std::size_t>(k)], box)) near.push_back(k);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (int k : near)
        in_face.AddPath(rings_[static_cast<std::size_t>(k)], ClipperLib::ptClip, true);
    ClipperLib::Paths inside_face;
    in_face.Execute(ClipperLib::ctIntersection, inside_face, ClipperLib::pftNonZero,
                    ClipperLib::pftEvenOdd);
    near.clear();
    for_buckets(box, [&](int b) {
        for (int l = claim_head_[static_cast<std::size_t>(b)]; l >= 0; l = link(l).next) {
            int c = link(l).claim;
            if (overlaps(claims_[static_cast<std::size_t>(c)].box, box)) near.push_back(c);
        }
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    ClipperLib::Paths result = std::move(inside_face);
    if (!near.empty() && !result.empty()) {
        ClipperLib::Clipper minus;
        minus.AddPaths(result, ClipperLib::ptSubject, true);
        for (int c : near) {
            const Claim& claim = claims_[static_cast<std::size_t>(c)];
            if (claim.path >= 0)
                minus.AddPath(claim_paths_[static_cast<std::size_t>(claim.path)],
                              ClipperLib::ptClip, true);
            else
                minus.AddPath(scale_.to_path(claim.box), ClipperLib::ptClip, true);
        }
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
    Rect r;
    if (detail::axis_rect(polygon, r))
        data_->claim(r);
    else
        data_->claim(data_->scale().to_path(polygon), detail::bounds_of(polygon));
}
void FaceOccupancy::claim(Rect rect) { data_->claim(rect); }
std::vector<std::vector<Point>> FaceOccupancy::free_part(const std::vector<Point>& polygon) const {
    return data_->free_part(polygon);
}
bool FaceOccupancy::rect_is_free(Rect rect) const { return data_->rect_is_free(rect); }
double FaceOccupancy::claimed_area() const { return data_->claimed_area(); }

}  // namespace acanthus::cells
