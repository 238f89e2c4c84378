#include "region/build.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/elliptical-arc.h>
#include <2geom/path.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "geometry/path_checks.hpp"
#include "region/curves.hpp"
#include "region/fill.hpp"

namespace acanthus::detail {
namespace {

double wedge(Geom::Point a, Geom::Point b) {
    return a[Geom::X] * b[Geom::Y] - a[Geom::Y] * b[Geom::X];
}

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

std::string where(const std::string& name, const std::string& label) {
    return label.empty() || label == name ? name : name + ": " + label;
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

std::unique_ptr<RegionData> build_region_data(const std::string& name,
                                              std::vector<FilledShape> shapes) {
    std::erase_if(shapes, [](const FilledShape& s) { return s.paths.empty(); });
    auto data = std::make_unique<RegionData>();
    data->name = name;
    std::size_t curves = 0;
    for (FilledShape& s : shapes) {
        require_in_range(s.paths, where(name, s.label));
        try {
            for (Geom::Path& p : s.paths) p.close(true);  // fill closes open subpaths
            s.paths = arcs_to_cubics(s.paths);
        } catch (const std::exception& e) {
            throw InputError(where(name, s.label) + ": cannot use this shape: " + e.what());
        }
        // Counted as cubics: an arc becomes up to 24 of them.
        for (const Geom::Path& p : s.paths) curves += p.size_closed();
        if (curves > kMaxRegionCurves)
            throw InputError(where(name, s.label) + ": the region has more than " +
                             std::to_string(kMaxRegionCurves) +
                             " curves once arcs become cubic Béziers");
    }
    data->paths = filled_area(shapes);
    // One shape keeps its rule for Region::evenodd(); the loops read the same under both.
    data->evenodd = shapes.size() == 1 && shapes.front().evenodd;

    Geom::OptRect b = data->paths.boundsExact();
    double area = signed_area(data->paths);
    if (!b || !(b->width() > 0) || !(b->height() > 0) || !(area > 1e-12 * b->width() * b->height()))
        throw InputError(name + ": region has no area");
    data->bounds = Rect{b->left(), b->top(), b->right(), b->bottom()};
    data->area = area;
    set_boundary(*data);
    return data;
}

}  // namespace acanthus::detail
