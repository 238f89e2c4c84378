#include "region/band.hpp"

#include <2geom/path.h>
#include <2geom/piecewise.h>
#include <2geom/sbasis-geometric.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <sstream>

#include "svg/shape_reader.hpp"

namespace acanthus::detail {

namespace {

// Samples of C and N along the centre line: enough that the straight pieces between them stay
// well within a hundredth of a unit of the curve on any ordinary path.
constexpr std::size_t min_samples = 2048;
constexpr std::size_t max_samples = 1 << 18;

std::string number_text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

Band Band::from_svg_file(const std::string& path, double width) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::status(path, ec)))
        throw InputError(path + ": cannot open the band's centre line: no such file");
    return from_svg_string(read_input_file_or_throw(path, "band centre line", kMaxSvgFileBytes),
                           path, width);
}

Band Band::from_svg_string(std::string_view svg, const std::string& name, double width) {
    if (!(width > 0) || !std::isfinite(width))
        throw UsageError("--band-width must be a positive number, not " + number_text(width));
    std::vector<SvgShape> shapes = read_svg_shapes(svg, name);
    std::vector<Geom::Path> paths;
    for (const SvgShape& s : shapes)
        for (const Geom::Path& p : s.paths)
            if (!p.empty() || p.closed()) paths.push_back(p);
    if (paths.size() != 1)
        throw InputError(name + ": the band's centre line must be one path with one subpath, not " +
                         std::to_string(paths.size()));
    const Geom::Path& path = paths.front();
    const bool closed = path.closed() || (!path.empty() && Geom::are_near(path.initialPoint(),
                                                                          path.finalPoint(), 1e-9));
    Geom::Piecewise<Geom::D2<Geom::SBasis>> pw = path.toPwSb();
    if (pw.empty()) throw InputError(name + ": the band's centre line has no length");
    const Geom::Piecewise<Geom::D2<Geom::SBasis>> arc =
        Geom::arc_length_parametrization(pw, 3, 1e-4);
    const double length = arc.domain().extent();
    if (!(length > 0) || !std::isfinite(length))
        throw InputError(name + ": the band's centre line has no length");
    const Geom::Piecewise<Geom::D2<Geom::SBasis>> velocity = Geom::derivative(arc);

    const std::size_t n = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::ceil(length / 0.25)) + 1, min_samples, max_samples);
    std::vector<Point> points(n), normals(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double s = arc.domain().min() + length * double(k) / double(n - 1);
        const Geom::Point c = arc.valueAt(s);
        // Sampled just inside a piece, so that a corner's two tangents are both seen.
        const double inside = std::clamp(s, arc.domain().min() + 1e-9, arc.domain().max() - 1e-9);
        Geom::Point v = velocity.valueAt(inside);
        if (Geom::L2(v) == 0) v = arc.valueAt(std::min(inside + 1e-6, arc.domain().max())) - c;
        v = Geom::unit_vector(v);
        points[k] = {c[Geom::X], c[Geom::Y]};
        normals[k] = {-v[Geom::Y], v[Geom::X]};
    }
    Band band(name, width, std::move(points), std::move(normals), length, closed);
    if (width > 2 * band.min_radius_)
        throw UsageError("--band-width " + number_text(width) +
                         " is larger than twice the smallest "
                         "radius of curvature of " +
                         name + "'s centre line (" + number_text(band.min_radius_) +
                         "): the band's inner edge would fold; use a width of at most " +
                         number_text(2 * band.min_radius_) + " or a smoother path");
    return band;
}

Band::Band(const std::string&, double width, std::vector<Point> points, std::vector<Point> normals,
           double length, bool closed)
    : width_(width),
      length_(length),
      closed_(closed),
      points_(std::move(points)),
      normals_(std::move(normals)) {
    // Radius of curvature from the turn of the normal between neighbouring samples (a corner
    // turns within one step: radius about step / angle, near 0).
    const double h = length_ / double(points_.size() - 1);
    min_radius_ = std::numeric_limits<double>::infinity();
    auto turn = [&](std::size_t i, std::size_t j) {
        const Point a = normals_[i], b = normals_[j];
        const double angle = std::abs(std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y));
        if (angle > 1e-12) min_radius_ = std::min(min_radius_, h / angle);
    };
    for (std::size_t k = 0; k + 1 < normals_.size(); ++k) turn(k, k + 1);
    if (closed_) turn(normals_.size() - 1, 0);
}

Region Band::straight_region() const {
    std::ostringstream svg;
    svg.precision(17);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"M0 " << -width_ / 2 << " H"
        << length_ << " V" << width_ / 2 << " H0 Z\"/></svg>";
    return Region::from_svg_string(svg.str(), "band");
}

Point Band::map(Point st) const {
    double s = st.x;
    const std::size_t last = points_.size() - 1;
    const double h = length_ / double(last);
    if (closed_) s -= length_ * std::floor(s / length_);
    Point c, nrm;
    if (!closed_ && (s < 0 || s > length_)) {
        // Straight on along the end's tangent (the normal turned back a quarter).
        const std::size_t end = s < 0 ? 0 : last;
        const double beyond = s < 0 ? s : s - length_;
        nrm = normals_[end];
        c = {points_[end].x + beyond * nrm.y, points_[end].y - beyond * nrm.x};
    } else {
        const double u = std::min(s / h, double(last));
        const std::size_t k = std::min(static_cast<std::size_t>(u), last - 1);
        const double f = u - double(k);
        const Point& p0 = points_[k];
        const Point& p1 = points_[k + 1];
        c = {p0.x + f * (p1.x - p0.x), p0.y + f * (p1.y - p0.y)};
        const Point& n0 = normals_[k];
        const Point& n1 = normals_[k + 1];
        nrm = {n0.x + f * (n1.x - n0.x), n0.y + f * (n1.y - n0.y)};
        const double len = std::hypot(nrm.x, nrm.y);
        if (len > 0) nrm = {nrm.x / len, nrm.y / len};
    }
    return {c.x + st.y * nrm.x, c.y + st.y * nrm.y};
}

Rect Band::bounds() const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Rect r{inf, inf, -inf, -inf};
    for (std::size_t k = 0; k < points_.size(); ++k)
        for (double t : {-width_ / 2, width_ / 2}) {
            const Point p{points_[k].x + t * normals_[k].x, points_[k].y + t * normals_[k].y};
            r.x0 = std::min(r.x0, p.x);
            r.y0 = std::min(r.y0, p.y);
            r.x1 = std::max(r.x1, p.x);
            r.y1 = std::max(r.y1, p.y);
        }
    return r;
}

std::vector<std::vector<Point>> Band::outline(double tolerance) const {
    const double h = step(tolerance);
    const int pieces = std::max(8, static_cast<int>(std::ceil(length_ / h)));
    auto edge = [&](double t, bool forward, std::vector<Point>& ring) {
        for (int k = 0; k <= pieces; ++k) {
            const double s = length_ * (forward ? k : pieces - k) / pieces;
            ring.push_back(map({s, t}));
        }
    };
    if (closed_) {
        std::vector<Point> outer, inner;
        edge(-width_ / 2, true, outer);
        edge(width_ / 2, true, inner);
        outer.pop_back();  // the ring closes itself
        inner.pop_back();
        return {outer, inner};
    }
    std::vector<Point> ring;
    edge(-width_ / 2, true, ring);
    edge(width_ / 2, false, ring);
    return {ring};
}

double Band::step(double tolerance) const {
    // A chord of length h on a circle of radius R strays h^2 / (8 R) from it.
    const double r = std::max(min_radius_ - width_ / 2, 1e-9);
    const double sampled = length_ / double(points_.size() - 1);
    return std::max(sampled / 4, std::min(std::sqrt(8 * r * tolerance), width_ / 4));
}

}  // namespace acanthus::detail
