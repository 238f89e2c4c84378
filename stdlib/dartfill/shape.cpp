#include "shape.hpp"

#include <2geom/exception.h>
#include <2geom/pathvector.h>
#include <2geom/svg-path-parser.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/triangulation.hpp"

namespace acanthus::dartfill {
namespace {

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
    throw InputError("dartfill: shape '" + name + "': " + why);
}

double orient(Point a, Point b, Point c) { return (b - a).cross(c - a); }

// c lies on segment ab, given that a, b, c are collinear.
bool on_segment(Point a, Point b, Point c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
}

// Closed segments ab and cd share a point.
bool segments_touch(Point a, Point b, Point c, Point d) {
    double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return true;
    return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
           (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// Returns the first pair of edges (i, j) that intersect improperly for a simple polygon.
bool find_self_intersection(const std::vector<Point>& ring, std::size_t& ei, std::size_t& ej) {
    std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        Point a = ring[i], b = ring[(i + 1) % n];
        // Adjacent edge folding back onto this one (a spike).
        Point c = ring[(i + 2) % n];
        if (orient(a, b, c) == 0 && (b - a).dot(c - b) < 0) {
            ei = i;
            ej = (i + 1) % n;
            return true;
        }
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through the closing vertex
            if (segments_touch(a, b, ring[j], ring[(j + 1) % n])) {
                ei = i;
                ej = j;
                return true;
            }
        }
    }
    return false;
}

void flatten_curve(const Geom::Curve& curve, double a, double b, Geom::Point pa, Geom::Point pb,
                   double tolerance, int depth, std::vector<Point>& out) {
    double mid = (a + b) / 2;
    Geom::Point pm = curve.pointAt(mid);
    Geom::Point chord = pb - pa;
    double len = Geom::L2(chord);
    double error = len > 0 ? std::abs(Geom::cross(chord, pm - pa)) / len : Geom::L2(pm - pa);
    // At least four pieces per curve so that an S-bend is not mistaken for a line.
    if (depth < 2 || (error > tolerance && depth < 16)) {
        flatten_curve(curve, a, mid, pa, pm, tolerance, depth + 1, out);
        flatten_curve(curve, mid, b, pm, pb, tolerance, depth + 1, out);
    } else {
        out.push_back({pa.x(), pa.y()});
    }
}

double distance_to_segment(Point p, Point a, Point b) {
    Vector ab = b - a;
    double len2 = ab.dot(ab);
    double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * t);
}

bool inside_triangles(const std::vector<Triangle>& triangles, Point p) {
    for (const Triangle& t : triangles) {
        double d0 = (t[1] - t[0]).cross(p - t[0]), d1 = (t[2] - t[1]).cross(p - t[1]),
               d2 = (t[0] - t[2]).cross(p - t[2]);
        if ((d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0)) return true;
    }
    return false;
}

// Grid search over the bounding box, then one finer grid around the best sample.
Point find_pole(const std::vector<Point>& ring, const std::vector<Triangle>& triangles, Rect box) {
    auto clearance = [&](Point p) {
        double d = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0, n = ring.size(); i < n; ++i)
            d = std::min(d, distance_to_segment(p, ring[i], ring[(i + 1) % n]));
        return d;
    };
    const Triangle& t0 = triangles.front();
    Point best{(t0[0].x + t0[1].x + t0[2].x) / 3, (t0[0].y + t0[1].y + t0[2].y) / 3};
    double best_d = clearance(best);
    Point center = box.center();
    double w = box.width(), h = box.height();
    for (int pass = 0; pass < 2; ++pass) {
        const int n = 24;
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                Point p{center.x + w * ((i + 0.5) / n - 0.5), center.y + h * ((j + 0.5) / n - 0.5)};
                if (!inside_triangles(triangles, p)) continue;
                double d = clearance(p);
                if (d > best_d) {
                    best_d = d;
                    best = p;
                }
            }
        }
        center = best;
        w /= 8;
        h /= 8;
    }
    return best;
}

}  // namespace

double signed_area(const std::vector<Point>& ring) {
    double twice = 0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        Point a = ring[i], b = ring[(i + 1) % n];
        twice += a.x * b.y - b.x * a.y;
    }
    return twice / 2;
}

std::vector<std::vector<Point>> flatten_path_data(const std::string& name,
                                                  std::string_view path_data, double tolerance) {
    Geom::PathVector paths;
    try {
        paths = Geom::parse_svg_path(std::string(path_data).c_str());
    } catch (const Geom::SVGPathParseError&) {
        refuse(name, "cannot parse SVG path data \"" + std::string(path_data.substr(0, 60)) +
                         (path_data.size() > 60 ? "...\"" : "\""));
    } catch (const std::exception& e) {
        refuse(name, std::string("cannot parse SVG path data: ") + e.what());
    }
    if (!(tolerance > 0)) {
        // Relative to the outline's size, so a shape drawn in any unit flattens alike.
        Geom::OptRect box = paths.boundsFast();
        tolerance = box ? std::max(box->width(), box->height()) / 500 : 1.0;
        if (!(tolerance > 0)) tolerance = 1.0;
    }
    std::vector<std::vector<Point>> rings;
    for (const Geom::Path& path : paths) {
        std::vector<Point> ring;
        // Fill closes every subpath, so an open one is closed by its implicit segment.
        for (auto it = path.begin(); it != path.end_closed(); ++it) {
            const Geom::Curve& curve = *it;
            if (curve.isLineSegment() || curve.isDegenerate()) {
                Geom::Point p = curve.initialPoint();
                ring.push_back({p.x(), p.y()});
            } else {
                flatten_curve(curve, 0, 1, curve.initialPoint(), curve.finalPoint(), tolerance, 0,
                              ring);
            }
        }
        if (!path.closed() && path.size_open() > 0) {
            Geom::Point p = path.finalPoint();
            ring.push_back({p.x(), p.y()});
        }
        if (!ring.empty()) rings.push_back(std::move(ring));
    }
    return rings;
}

Shape Shape::from_points(std::string name, std::vector<Point> outline) {
    for (std::size_t i = 0; i < outline.size(); ++i)
        if (!outline[i].finite()) refuse(name, "point " + std::to_string(i) + " is not finite");
    // Drop repeated points, including a closing point equal to the first.
    std::vector<Point> ring;
    for (Point p : outline)
        if (ring.empty() || !(p == ring.back())) ring.push_back(p);
    while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    if (ring.size() < 3)
        refuse(name, "needs at least 3 distinct points, has " + std::to_string(ring.size()));

    Rect box{ring[0].x, ring[0].y, ring[0].x, ring[0].y};
    for (Point p : ring) {
        box.x0 = std::min(box.x0, p.x);
        box.y0 = std::min(box.y0, p.y);
        box.x1 = std::max(box.x1, p.x);
        box.y1 = std::max(box.y1, p.y);
    }
    double area = signed_area(ring);
    double extent = std::max(box.width(), box.height());
    std::size_t ei = 0, ej = 0;
    bool collinear = true;
    for (std::size_t i = 2; i < ring.size() && collinear; ++i)
        collinear = orient(ring[0], ring[1], ring[i]) == 0;
    if (!(extent > 0) || collinear) refuse(name, "has zero area");
    if (find_self_intersection(ring, ei, ej))
        refuse(name, "outline intersects itself (edges " + std::to_string(ei) + " and " +
                         std::to_string(ej) + ")");
    if (!(std::abs(area) > 1e-12 * extent * extent)) refuse(name, "has zero area");
    if (area < 0) {
        std::reverse(ring.begin(), ring.end());
        area = -area;
    }

    Shape s;
    s.name_ = std::move(name);
    s.triangles_ = common::triangulate_polygon(ring);
    s.outline_ = std::move(ring);
    s.bounds_ = box;
    s.area_ = area;
    Point c = box.center();
    for (Point p : s.outline_) s.radius_ = std::max(s.radius_, distance(c, p));
    s.pole_ = find_pole(s.outline_, s.triangles_, box);
    return s;
}

Shape Shape::from_path_data(std::string name, std::string_view path_data, double tolerance) {
    auto rings = flatten_path_data(name, path_data, tolerance);
    if (rings.size() != 1)
        refuse(name, "SVG path data must hold exactly one closed outline, it holds " +
                         std::to_string(rings.size()));
    return from_points(std::move(name), std::move(rings.front()));
}

}  // namespace acanthus::dartfill
