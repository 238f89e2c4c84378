// Facade::from_shapes: the wall is the union of `wall` shapes, every other shape an opening cut
// from it [3.1]. Clipper decides the areas; BoundaryTrace hands back the exact curves.
#include <2geom/elliptical-arc.h>

#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/facade_shape.hpp>
#include <algorithm>
#include <cmath>

#include "clip.hpp"
#include "facade_data.hpp"
#include "feature_loop.hpp"
#include "opening_overlaps.hpp"
#include "region/fill.hpp"
#include "region/trace.hpp"

namespace acanthus::cells {

using detail::FacadeData;
using detail::LoopSegment;
using detail::ShapeLabels;

namespace {

Segment line(Point a, Point b) {
    Segment s;
    s.a = a;
    s.b = b;
    return s;
}

std::string describe(const FacadeShape& s) {
    if (!s.label.empty()) return s.label;
    if (!s.id.empty()) return "id \"" + s.id + "\"";
    return "a shape without id";
}

bool is_wall(const FacadeShape& s) {
    return std::find(s.classes.begin(), s.classes.end(), "wall") != s.classes.end();
}

// Lines and circular arcs stay exact; other curves become chords (a tenth of a percent of the
// facade's size at most).
void add_curve(const Geom::Curve& c, int shape, double chord, std::vector<LoopSegment>& out) {
    Geom::Point a = c.initialPoint(), b = c.finalPoint();
    if (c.isDegenerate()) return;
    if (c.isLineSegment()) {
        out.push_back({line({a[0], a[1]}, {b[0], b[1]}), shape});
        return;
    }
    if (const auto* arc = dynamic_cast<const Geom::EllipticalArc*>(&c)) {
        double rx = arc->ray(Geom::X), ry = arc->ray(Geom::Y);
        if (std::abs(rx - ry) <= 1e-9 * std::max(rx, ry) && rx > 0) {
            Segment s;
            s.a = {a[0], a[1]};
            s.b = {b[0], b[1]};
            s.arc = true;
            s.center = {arc->center()[0], arc->center()[1]};
            s.radius = rx;
            s.start = std::atan2(s.a.y - s.center.y, s.a.x - s.center.x);
            double sweep = arc->sweepAngle();
            s.sweep = arc->sweep() ? sweep : -sweep;
            Geom::Point mid = arc->pointAt(0.5);
            if (distance(s.at(s.length() / 2), {mid[0], mid[1]}) > 1e-6 * rx) s.sweep = -s.sweep;
            out.push_back({s, shape});
            return;
        }
    }
    double length = 0;
    for (int i = 0; i < 64; ++i)
        length += Geom::distance(c.pointAt(i / 64.0), c.pointAt((i + 1) / 64.0));
    int n = std::clamp(static_cast<int>(std::ceil(length / chord)), 4, 512);
    Geom::Point p = a;
    for (int i = 1; i <= n; ++i) {
        Geom::Point q = i == n ? b : c.pointAt(static_cast<double>(i) / n);
        out.push_back({line({p[0], p[1]}, {q[0], q[1]}), shape});
        p = q;
    }
}

double distance_to(const Geom::PathVector& paths, Geom::Point p) {
    double best = 1e300;
    for (const Geom::Path& path : paths) {
        Geom::OptRect box = path.boundsFast();
        if (!box || Geom::distance(p, *box) > best) continue;
        double t = path.nearestTime(p).asFlatTime();
        best = std::min(best, Geom::distance(path.pointAt(t), p));
    }
    return best;
}

}  // namespace

Facade::Facade(std::shared_ptr<const FacadeData> data) : data_(std::move(data)) {}
const std::vector<Corner>& Facade::corners() const { return data_->corners; }
const std::vector<Edge>& Facade::edges() const { return data_->edges; }
const std::vector<Face>& Facade::faces() const { return data_->faces; }
const std::string& Facade::name() const { return data_->name; }
Rect Facade::bounds() const { return data_->bounds; }
double Facade::wall_area() const { return data_->wall_area; }
const std::vector<std::vector<Point>>& Facade::openings() const { return data_->openings; }

Facade Facade::from_shapes(std::vector<FacadeShape> shapes, const std::string& source_name) {
    auto fail = [&](const FacadeShape& s, const std::string& why) {
        throw InputError(source_name + ": " + describe(s) + ": " + why);
    };
    Geom::OptRect frame;
    for (const FacadeShape& s : shapes) {
        for (const Geom::Path& p : s.paths)
            for (const Geom::Curve& c : p) {
                Geom::Rect box = c.boundsFast();
                if (!std::isfinite(box.left()) || !std::isfinite(box.right()) ||
                    !std::isfinite(box.top()) || !std::isfinite(box.bottom()))
                    fail(s, "non-finite coordinates");
                frame.unionWith(box);
            }
    }
    if (std::none_of(shapes.begin(), shapes.end(), is_wall))
        throw InputError(source_name +
                         ": no shape with class \"wall\" (the wall is the union of those shapes)");
    const double size = std::max(frame->width(), frame->height());
    if (!(size > 0)) fail(shapes.front(), "has no area");

    acanthus::detail::BoundaryTrace trace(*frame, acanthus::detail::kFillTolerance * size);
    std::vector<ClipperLib::Paths> filled(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        ClipperLib::Paths rings = trace.add(shapes[i].paths);
        ClipperLib::Clipper c;
        c.AddPaths(rings, ClipperLib::ptSubject, true);
        c.Execute(ClipperLib::ctUnion, filled[i], ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        double area = 0;
        for (const ClipperLib::Path& r : filled[i]) area += ClipperLib::Area(r);
        if (!(area > 0)) fail(shapes[i], "has no area");
        // A sliver thinner than the trace's tolerance is no area either.
        double perimeter = 0;
        for (const ClipperLib::Path& r : filled[i])
            for (std::size_t k = 0; k < r.size(); ++k) {
                const auto& p = r[k];
                const auto& q = r[(k + 1) % r.size()];
                perimeter +=
                    std::hypot(static_cast<double>(q.X - p.X), static_cast<double>(q.Y - p.Y));
            }
        if (area < 1e-6 * perimeter * perimeter) fail(shapes[i], "has no area");
    }

    ClipperLib::Clipper walls;
    for (std::size_t i = 0; i < shapes.size(); ++i)
        if (is_wall(shapes[i])) walls.AddPaths(filled[i], ClipperLib::ptSubject, true);
    ClipperLib::Paths wall;
    walls.Execute(ClipperLib::ctUnion, wall, ClipperLib::pftNonZero, ClipperLib::pftNonZero);

    ClipperLib::Clipper holes;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (is_wall(shapes[i])) continue;
        ClipperLib::Clipper outside;
        outside.AddPaths(filled[i], ClipperLib::ptSubject, true);
        outside.AddPaths(wall, ClipperLib::ptClip, true);
        ClipperLib::Paths out;
        outside.Execute(ClipperLib::ctDifference, out, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        double own = 0, beyond = 0;
        for (const ClipperLib::Path& r : filled[i]) own += ClipperLib::Area(r);
        for (const ClipperLib::Path& r : out) beyond += ClipperLib::Area(r);
        if (beyond > 1e-6 * own)
            fail(shapes[i],
                 "crosses the wall's outline (an opening must lie inside the union of the "
                 "shapes with class \"wall\")");
        holes.AddPaths(filled[i], ClipperLib::ptSubject, true);
    }
    std::vector<bool> opening(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) opening[i] = !is_wall(shapes[i]);
    if (auto [a, b] = detail::overlapping_openings(filled, opening); a >= 0)
        throw InputError(source_name + ": " + describe(shapes[a]) + " and " + describe(shapes[b]) +
                         ": openings overlap (they are not merged: draw one opening as one "
                         "shape, or move them apart)");
    ClipperLib::Paths opening_union;
    holes.Execute(ClipperLib::ctUnion, opening_union, ClipperLib::pftNonZero,
                  ClipperLib::pftNonZero);
    ClipperLib::Clipper cut;
    cut.AddPaths(wall, ClipperLib::ptSubject, true);
    cut.AddPaths(opening_union, ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    cut.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);

    auto data = std::make_shared<FacadeData>();
    data->name = source_name;
    data->bounds = {frame->left(), frame->top(), frame->right(), frame->bottom()};
    const detail::IntScale scale = detail::scale_for(data->bounds);
    data->scale = scale.scale;

    std::vector<ShapeLabels> labels(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        labels[i].labels = shapes[i].classes;
        if (!shapes[i].id.empty()) labels[i].labels.push_back(shapes[i].id);
        labels[i].opening = !is_wall(shapes[i]);
    }
    // The shape a boundary curve lies on: openings before walls, where both share a stretch.
    const double near = 1e-5 * size;
    // Each shape's bounds grown by `near`: a cheap refusal before the distance, which would
    // otherwise make this quadratic in the number of openings.
    std::vector<Rect> reach(shapes.size(), Rect{0, 0, -1, -1});
    for (std::size_t i = 0; i < shapes.size(); ++i)
        if (Geom::OptRect b = shapes[i].paths.boundsFast())
            reach[i] = {b->left() - near, b->top() - near, b->right() + near, b->bottom() + near};
    auto shape_of = [&](const Geom::Curve& c) {
        Geom::Point mid = c.pointAt(0.5);
        for (int pass = 0; pass < 2; ++pass)
            for (std::size_t i = 0; i < shapes.size(); ++i) {
                if (is_wall(shapes[i]) != (pass == 1)) continue;
                if (!reach[i].contains({mid.x(), mid.y()})) continue;
                if (distance_to(shapes[i].paths, mid) <= near) return static_cast<int>(i);
            }
        return -1;
    };

    const double chord = 1e-3 * size;
    const double flat_tolerance = 1e-5 * size;
    auto add_face = [&](const ClipperLib::PolyNode& outer) {
        const int face = static_cast<int>(data->faces.size());
        data->faces.emplace_back();
        std::vector<const ClipperLib::PolyNode*> rings{&outer};
        for (const ClipperLib::PolyNode* h : outer.Childs) rings.push_back(h);
        ClipperLib::Paths ints;
        for (const ClipperLib::PolyNode* node : rings) {
            Geom::Path path = trace.rebuild(node->Contour);
            std::vector<LoopSegment> loop;
            for (const Geom::Curve& c : path) add_curve(c, shape_of(c), chord, loop);
            if (loop.empty()) continue;
            std::vector<Point> flat;
            for (const LoopSegment& s : loop) detail::flatten(s.segment, flat_tolerance, flat);
            bool outer_ring = !node->IsHole();
            bool interior_left = (detail::signed_area(flat) > 0) == outer_ring;
            detail::add_loop(*data, face, loop, interior_left, labels);
            ints.push_back(scale.to_path(flat));
            data->faces.back().loops.push_back(std::move(flat));
        }
        Face& f = data->faces.back();
        f.area = std::abs(scale.area({ints.front()}));
        for (std::size_t k = 1; k < ints.size(); ++k) f.area -= std::abs(scale.area({ints[k]}));
        f.bounds = detail::bounds_of(f.loops.front());
        data->face_walls.emplace_back();
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            if (!is_wall(shapes[i])) continue;
            Geom::OptRect b = shapes[i].paths.boundsFast();
            if (!b || !detail::overlaps(f.bounds, {b->left(), b->top(), b->right(), b->bottom()}))
                continue;
            data->face_walls.back().push_back(describe(shapes[i]));
            for (const std::string& l : labels[i].labels)
                if (std::find(f.labels.begin(), f.labels.end(), l) == f.labels.end())
                    f.labels.push_back(l);
        }
        data->wall_area += f.area;
        data->face_rings.push_back(std::move(ints));
    };
    std::vector<const ClipperLib::PolyNode*> stack{&tree};
    while (!stack.empty()) {
        const ClipperLib::PolyNode* node = stack.back();
        stack.pop_back();
        for (auto it = node->Childs.rbegin(); it != node->Childs.rend(); ++it) {
            if (!(*it)->IsHole()) add_face(**it);
            stack.push_back(*it);
        }
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        if (is_wall(shapes[i])) continue;
        for (const Geom::Path& p : shapes[i].paths) {
            std::vector<LoopSegment> loop;
            Geom::Path closed = p;
            closed.close(true);
            for (std::size_t k = 0; k < closed.size_closed(); ++k)
                add_curve(closed[k], static_cast<int>(i), chord, loop);
            std::vector<Point> flat;
            for (const LoopSegment& s : loop) detail::flatten(s.segment, flat_tolerance, flat);
            if (flat.size() >= 3) data->openings.push_back(std::move(flat));
        }
    }
    if (data->faces.empty())
        throw InputError(source_name + ": the openings leave nothing of the wall");
    return Facade(std::move(data));
}

}  // namespace acanthus::cells
