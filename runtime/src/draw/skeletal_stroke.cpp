// Skeletal strokes (Hsu and Lee): the stroke's shapes are warped along a skeleton curve by
// mapping frame point (x, y) to skeleton(x * L) + y * width * profile * normal(x * L).
#include <2geom/path.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "draw/skeletal_stroke_data.hpp"
#include "proxy/proxy_path.hpp"

namespace acanthus {

// This file builds public types from private (detail) parts.
using namespace detail;

namespace {

// Flattening tolerance in units of the stroke's width: fine enough that bends look smooth.
constexpr double tolerance_per_width = 0.02;
// A warped piece spanning more skeleton than this (in widths) is split even when it looks flat,
// so that no bend of the skeleton is jumped over.
constexpr double max_step_per_width = 0.25;
constexpr int min_depth = 2;
constexpr int max_depth = 18;
// Guards against a hang on absurd length / width ratios.
constexpr double max_motifs = 20000;

// The skeleton as a dense polyline parametrized by arc length, with smoothly varying normals.
class Skeleton {
  public:
    explicit Skeleton(const std::vector<Point>& points) {
        for (Point p : points) {
            if (!p.finite()) {
                points_.clear();
                return;
            }
            if (points_.empty() || distance(points_.back(), p) > 0) points_.push_back(p);
        }
        if (points_.size() < 2) return;
        arc_.assign(1, 0.0);
        std::vector<Vector> segment_normals;
        for (std::size_t i = 1; i < points_.size(); ++i) {
            Vector d = points_[i] - points_[i - 1];
            arc_.push_back(arc_.back() + d.length());
            segment_normals.push_back(d.normalized().perp());
        }
        if (!std::isfinite(arc_.back()) || arc_.back() <= 0) {
            points_.clear();
            return;
        }
        bool closed = distance(points_.front(), points_.back()) <= 1e-9 * arc_.back();
        normals_.resize(points_.size());
        normals_.front() = segment_normals.front();
        normals_.back() = segment_normals.back();
        for (std::size_t i = 1; i + 1 < points_.size(); ++i)
            normals_[i] = average(segment_normals[i - 1], segment_normals[i]);
        if (closed) {
            normals_.front() = average(segment_normals.back(), segment_normals.front());
            normals_.back() = normals_.front();
        }
        segment_normals_ = std::move(segment_normals);
    }

    bool usable() const { return points_.size() >= 2; }
    double length() const { return arc_.back(); }

    struct Frame {
        Point point;
        Vector normal;
        double tangent;
    };

    Frame at(double s) const {
        s = std::clamp(s, 0.0, length());
        auto it = std::upper_bound(arc_.begin(), arc_.end(), s);
        std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - arc_.begin(), 1) - 1,
                                              points_.size() - 2);
        double t = (s - arc_[i]) / (arc_[i + 1] - arc_[i]);
        Vector n = (normals_[i] * (1 - t) + normals_[i + 1] * t).normalized();
        if (n.length() == 0) n = segment_normals_[i];
        // n is the tangent turned a quarter counter-clockwise, so the tangent is (n.y, -n.x).
        return {lerp(points_[i], points_[i + 1], t), n, std::atan2(-n.x, n.y)};
    }

  private:
    static Vector average(Vector a, Vector b) {
        Vector m = (a + b).normalized();
        return m.length() > 0 ? m : b;
    }

    std::vector<Point> points_;
    std::vector<double> arc_;
    std::vector<Vector> normals_;
    std::vector<Vector> segment_normals_;
};

using detail::from_geom;

// Splits a curve until each piece's midpoint lies within `tolerance` of its chord.
void flatten(const Geom::Curve& curve, double t0, Point p0, double t1, Point p1, int depth,
             double tolerance, std::vector<Point>& out) {
    double tm = (t0 + t1) / 2;
    Point pm = from_geom(curve.pointAt(tm));
    if (depth >= max_depth || !pm.finite() ||
        (depth >= min_depth + 1 && distance(pm, midpoint(p0, p1)) <= tolerance)) {
        out.push_back(p1);
        return;
    }
    flatten(curve, t0, p0, tm, pm, depth + 1, tolerance, out);
    flatten(curve, tm, pm, t1, p1, depth + 1, tolerance, out);
}

void flatten(const Geom::Path& path, double tolerance, std::vector<Point>& out) {
    out.push_back(from_geom(path.initialPoint()));
    for (auto it = path.begin(); it != path.end_default(); ++it)
        flatten(*it, 0, from_geom(it->initialPoint()), 1, from_geom(it->finalPoint()), 0, tolerance,
                out);
}

// Maps frame points of one motif onto the skeleton and flattens the warped curves.
class Warp {
  public:
    Warp(const SkeletalStroke::Data& data, const Skeleton& skeleton, double width, int motif,
         int motifs)
        : data_(data),
          skeleton_(skeleton),
          width_(width),
          motif_(motif),
          motifs_(motifs),
          tolerance_(tolerance_per_width * width),
          max_step_(max_step_per_width * width) {}

    Point map(Geom::Point q) const {
        double x = (motif_ + q[Geom::X]) / motifs_;
        double s = std::clamp(x, 0.0, 1.0) * skeleton_.length();
        Skeleton::Frame f = skeleton_.at(s);
        double w = width_;
        if (data_.profile) w *= data_.profile({x, s, skeleton_.length(), width_, f.tangent});
        return f.point + f.normal * (q[Geom::Y] * w);
    }

    // Appends the warped subpath to the current Cairo path; skipped if anything is not finite.
    void add(const Geom::Path& path, cairo_t* cr) const {
        std::vector<Point> out{map(path.initialPoint())};
        for (auto it = path.begin(); it != path.end_closed(); ++it)
            split(*it, 0, it->initialPoint(), out.back(), 1, it->finalPoint(),
                  map(it->finalPoint()), 0, out);
        if (!std::all_of(out.begin(), out.end(), [](Point p) { return p.finite(); })) return;
        cairo_move_to(cr, out[0].x, out[0].y);
        for (std::size_t i = 1; i < out.size(); ++i) cairo_line_to(cr, out[i].x, out[i].y);
        cairo_close_path(cr);
    }

  private:
    double skeleton_span(double x0, double x1) const {
        return std::abs(x1 - x0) / motifs_ * skeleton_.length();
    }

    void split(const Geom::Curve& c, double t0, Geom::Point q0, Point p0, double t1, Geom::Point q1,
               Point p1, int depth, std::vector<Point>& out) const {
        double tm = (t0 + t1) / 2;
        Geom::Point qm = c.pointAt(tm);
        Point pm = map(qm);
        double span = std::max({skeleton_span(q0[Geom::X], q1[Geom::X]),
                                2 * skeleton_span(q0[Geom::X], qm[Geom::X]),
                                2 * skeleton_span(qm[Geom::X], q1[Geom::X])});
        bool flat = distance(pm, midpoint(p0, p1)) <= tolerance_ && span <= max_step_;
        if (depth >= max_depth || (depth >= min_depth && flat) || !pm.finite()) {
            out.push_back(p1);
            return;
        }
        split(c, t0, q0, p0, tm, qm, pm, depth + 1, out);
        split(c, tm, qm, pm, t1, q1, p1, depth + 1, out);
    }

    const SkeletalStroke::Data& data_;
    const Skeleton& skeleton_;
    double width_;
    int motif_;
    int motifs_;
    double tolerance_;
    double max_step_;
};

}  // namespace

SkeletalStroke::SkeletalStroke() : data_(std::make_unique<Data>()) {}
SkeletalStroke::SkeletalStroke(Data data) : data_(std::make_unique<Data>(std::move(data))) {}
SkeletalStroke::SkeletalStroke(const SkeletalStroke& o)
    : data_(o.data_ ? std::make_unique<Data>(*o.data_) : nullptr) {}
SkeletalStroke::SkeletalStroke(SkeletalStroke&&) noexcept = default;
SkeletalStroke& SkeletalStroke::operator=(const SkeletalStroke& o) {
    if (this != &o) data_ = o.data_ ? std::make_unique<Data>(*o.data_) : nullptr;
    return *this;
}
SkeletalStroke& SkeletalStroke::operator=(SkeletalStroke&&) noexcept = default;
SkeletalStroke::~SkeletalStroke() = default;

const std::string& SkeletalStroke::name() const {
    static const std::string none;
    return data_ ? data_->name : none;
}

void SkeletalStroke::draw(Canvas& canvas, const Proxy& curve, double width) const {
    if (!(width > 0) || !std::isfinite(width)) return;
    std::vector<Point> points;
    // Non-finite proxies give non-finite points, which the skeleton refuses.
    flatten(detail::proxy_path(curve), tolerance_per_width * width, points);
    draw(canvas, points, width);
}

void SkeletalStroke::draw(Canvas& canvas, const std::vector<const Proxy*>& chain,
                          double width) const {
    if (!(width > 0) || !std::isfinite(width)) return;
    std::vector<Point> points, piece;
    for (const Proxy* curve : chain) {
        piece.clear();
        if (curve) flatten(detail::proxy_path(*curve), tolerance_per_width * width, piece);
        if (std::all_of(piece.begin(), piece.end(), [](Point p) { return p.finite(); }))
            points.insert(points.end(), piece.begin(), piece.end());
    }
    draw(canvas, points, width);
}

void SkeletalStroke::draw(Canvas& canvas, const std::vector<Point>& skeleton, double width) const {
    // A moved-from stroke has no data and draws nothing.
    if (!data_ || !(width > 0) || !std::isfinite(width)) return;
    Skeleton sk(skeleton);
    if (!sk.usable()) return;
    double motifs = 1;
    if (data_->motif_length > 0)
        motifs =
            std::clamp(std::round(sk.length() / (data_->motif_length * width)), 1.0, max_motifs);
    cairo_t* cr = canvas.cairo();
    for (const StrokeShape& shape : data_->shapes) {
        cairo_new_path(cr);
        for (int k = 0; k < static_cast<int>(motifs); ++k) {
            Warp warp(*data_, sk, width, k, static_cast<int>(motifs));
            for (const Geom::Path& path : shape.paths) warp.add(path, cr);
        }
        cairo_fill_rule_t previous = cairo_get_fill_rule(cr);
        cairo_set_fill_rule(cr, shape.evenodd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
        cairo_fill(cr);
        cairo_set_fill_rule(cr, previous);
    }
}

}  // namespace acanthus
