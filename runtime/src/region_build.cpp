#include "region_build.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>
#include <2geom/intersection-graph.h>
#include <2geom/path.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "region_curves.hpp"
#include "region_uncross.hpp"

namespace acanthus::detail {
namespace {

double wedge(Geom::Point a, Geom::Point b) {
    return a[Geom::X] * b[Geom::Y] - a[Geom::Y] * b[Geom::X];
}

bool finite(Geom::Point p) { return std::isfinite(p[Geom::X]) && std::isfinite(p[Geom::Y]); }

// Five-point Gauss-Legendre on [0, 1]: exact for polynomials up to degree 9, so exact for
// x(t) y'(t) of any Bézier up to order 5.
constexpr std::array<double, 5> kNodes = {0.046910077030668, 0.230765344947158, 0.5,
                                          0.769234655052842, 0.953089922969332};
constexpr std::array<double, 5> kWeights = {0.118463442528095, 0.239314335249683, 0.284444444444444,
                                            0.239314335249683, 0.118463442528095};

// Exact for Béziers up to order 5; pointAndDerivatives() is right for Béziers (lib2geom
// 1.2's EllipticalArc version is not, so arcs never come here).
double gauss_cross_integral(const Geom::BezierCurve& c) {
    double sum = 0;
    for (std::size_t i = 0; i < kNodes.size(); ++i) {
        std::vector<Geom::Point> pd = c.pointAndDerivatives(kNodes[i], 1);
        sum += kWeights[i] * wedge(pd[0], pd[1]);
    }
    return sum;
}

// Any other curve type: the closed polyline through many points of the curve.
double polyline_cross_integral(const Geom::Curve& c) {
    constexpr int kSteps = 1024;
    double sum = 0;
    Geom::Point prev = c.initialPoint();
    for (int i = 1; i <= kSteps; ++i) {
        Geom::Point next = i == kSteps ? c.finalPoint() : c.pointAt(double(i) / kSteps);
        sum += wedge(prev, next);
        prev = next;
    }
    return sum;
}

// ∫ (x dy - y dx) along one curve.
double cross_integral(const Geom::Curve& c) {
    if (c.isLineSegment()) return wedge(c.initialPoint(), c.finalPoint());
    if (auto arc = dynamic_cast<const Geom::EllipticalArc*>(&c)) {
        // p(θ) = c + A u(θ): ∫ p × p' dθ = c × (p1 - p0) + det(A) Δθ, det(A) = rx ry.
        return wedge(arc->center(), arc->finalPoint() - arc->initialPoint()) +
               arc->ray(Geom::X) * arc->ray(Geom::Y) * arc->sweepAngle();
    }
    if (auto bez = dynamic_cast<const Geom::BezierCurve*>(&c); bez && bez->order() <= 5)
        return gauss_cross_integral(*bez);
    return polyline_cross_integral(c);
}

using FillTest = std::function<bool(Geom::Point)>;

FillTest fill_test(const Geom::PathVector& paths, bool evenodd) {
    return [&paths, evenodd](Geom::Point p) {
        int w = winding_number(paths, p);
        return evenodd ? (w % 2) != 0 : w != 0;
    };
}

// Which side of the subpath is filled: +1 left, -1 right, 0 neither (a redundant subpath,
// e.g. nested inside another with the same orientation under nonzero, or a degenerate one).
int filled_side(const Geom::Path& path, const FillTest& filled, double step) {
    std::vector<std::pair<double, std::size_t>> by_size;
    for (std::size_t i = 0; i < path.size_closed(); ++i) {
        const Geom::Curve& c = path[i];
        if (c.isDegenerate()) continue;
        Geom::Rect b = c.boundsFast();
        double size = std::max(b.diameter(), Geom::distance(c.initialPoint(), c.finalPoint()));
        by_size.emplace_back(-size, i);
    }
    std::stable_sort(by_size.begin(), by_size.end());
    if (by_size.size() > 6) by_size.resize(6);
    for (auto [neg_size, i] : by_size) {
        for (double t : {0.5, 0.3, 0.7, 0.1, 0.9}) {
            Geom::Point p = path[i].pointAt(t);
            Geom::Point tangent = path[i].unitTangentAt(t);
            if (!(Geom::L2(tangent) > 0.5)) continue;
            Geom::Point left(-tangent[Geom::Y], tangent[Geom::X]);
            bool l = filled(p + left * step);
            bool r = filled(p - left * step);
            if (l != r) return l ? 1 : -1;
        }
    }
    return 0;
}

double scale_of(const Geom::PathVector& paths) {
    Geom::OptRect b = paths.boundsFast();
    return b ? std::max({b->width(), b->height(), 1e-300}) : 1.0;
}

// Keeps the subpaths that separate filled from empty, each with the filled side on its left.
// Slivers below 1e-6 of the bounding square are dropped: they are numerical debris of
// boolean operations (a curve piece run out and back), not a panel's shape.
Geom::PathVector orient(const Geom::PathVector& paths, const FillTest& filled) {
    Geom::PathVector out;
    const double scale = scale_of(paths);
    const double step = scale * 1e-7;
    for (const Geom::Path& p : paths) {
        if (p.empty() || std::abs(signed_area(p)) < 1e-6 * scale * scale) continue;
        int side = filled_side(p, filled, step);
        if (side > 0) out.push_back(p);
        if (side < 0) out.push_back(p.reversed());
    }
    return out;
}

bool bounds_meet(const Geom::PathVector& a, const Geom::PathVector& b) {
    Geom::OptRect ra = a.boundsFast(), rb = b.boundsFast();
    return ra && rb && ra->intersects(*rb);
}

}  // namespace

double signed_area(const Geom::Path& path) {
    double sum = 0;
    for (std::size_t i = 0; i < path.size_closed(); ++i) sum += cross_integral(path[i]);
    return sum / 2;
}

double signed_area(const Geom::PathVector& paths) {
    double sum = 0;
    for (const Geom::Path& p : paths) sum += signed_area(p);
    return sum;
}

void require_finite(const Geom::PathVector& paths, const std::string& name,
                    const std::string& label) {
    for (const Geom::Path& p : paths) {
        for (std::size_t i = 0; i < p.size_closed(); ++i) {
            const Geom::Curve& c = p[i];
            Geom::Rect b = c.boundsFast();
            if (!finite(c.initialPoint()) || !finite(c.finalPoint()) || !finite(b.min()) ||
                !finite(b.max()))
                throw InputError(name + ": " + label + ": coordinates are not finite numbers");
        }
    }
}

std::unique_ptr<RegionData> build_region_data(const std::string& name,
                                              std::vector<FilledShape> shapes) {
    std::erase_if(shapes, [](const FilledShape& s) { return s.paths.empty(); });
    auto data = std::make_unique<RegionData>();
    data->name = name;

    std::vector<Geom::PathVector> oriented;
    for (FilledShape& s : shapes) {
        for (Geom::Path& p : s.paths) p.close(true);
        s.paths = uncross(arcs_to_cubics(s.paths));
        oriented.push_back(orient(s.paths, fill_test(s.paths, s.evenodd)));
    }
    if (oriented.size() == 1) {
        data->paths = std::move(oriented.front());
        data->evenodd = shapes.front().evenodd;
    } else {
        // Oriented shapes read the same under both fill rules, which is what the
        // intersection graph (parity based) needs; their union is then a nonzero region.
        Geom::PathVector acc;
        bool merged = false;
        for (const Geom::PathVector& s : oriented) {
            if (s.empty()) continue;
            if (acc.empty() || !bounds_meet(acc, s)) {
                acc.insert(acc.end(), s.begin(), s.end());
                continue;
            }
            try {
                Geom::PathIntersectionGraph graph(acc, s);
                if (graph.valid()) {
                    acc = graph.getUnion();
                    merged = true;
                    continue;
                }
            } catch (const std::exception&) {
            }
            // Degenerate contact lib2geom cannot resolve: keep both; nonzero winding still
            // gives the right inside test, the overlap just stays inside the boundary.
            acc.insert(acc.end(), s.begin(), s.end());
        }
        if (merged) {
            auto inside_any = [&oriented](Geom::Point p) {
                return std::any_of(
                    oriented.begin(), oriented.end(),
                    [p](const Geom::PathVector& s) { return winding_number(s, p) != 0; });
            };
            acc = orient(acc, inside_any);
        }
        data->paths = std::move(acc);
        data->evenodd = false;
    }

    Geom::OptRect b = data->paths.boundsExact();
    double area = signed_area(data->paths);
    if (!b || !(b->width() > 0) || !(b->height() > 0) || !(area > 1e-12 * b->width() * b->height()))
        throw InputError(name + ": region has no area");
    data->bounds = Rect{b->left(), b->top(), b->right(), b->bottom()};
    data->area = area;
    return data;
}

}  // namespace acanthus::detail
