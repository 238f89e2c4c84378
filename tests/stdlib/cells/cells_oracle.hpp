// Facades built in C++ and independent checks of a texture with Clipper: overlaps, cells over
// openings or outside the wall, and coverage with the mortar added back.
#pragma once

#include <2geom/svg-path-parser.h>

#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/facade_shape.hpp>
#include <cmath>
#include <polyclipping/clipper.hpp>
#include <string>
#include <vector>

namespace cells_test {

using namespace acanthus::cells;
using acanthus::Point;

inline FacadeShape shape(const std::string& d, std::vector<std::string> classes, std::string id) {
    FacadeShape s;
    s.paths = Geom::parse_svg_path(d.c_str());
    s.classes = std::move(classes);
    s.id = id;
    s.label = "<path id=\"" + id + "\">";
    return s;
}

inline std::string rect(double x, double y, double w, double h) {
    return "M " + std::to_string(x) + " " + std::to_string(y) + " h " + std::to_string(w) + " v " +
           std::to_string(h) + " h " + std::to_string(-w) + " Z";
}

// A window with a semicircular head: jambs from the sill up to the springing line.
inline std::string arched(double x, double y_sill, double w, double h_jamb) {
    double r = w / 2;
    return "M " + std::to_string(x) + " " + std::to_string(y_sill) + " h " + std::to_string(w) +
           " v " + std::to_string(-h_jamb) + " A " + std::to_string(r) + " " + std::to_string(r) +
           " 0 0 0 " + std::to_string(x) + " " + std::to_string(y_sill - h_jamb) + " Z";
}

constexpr double kScale = 1024;

inline ClipperLib::Path to_path(const std::vector<Point>& p) {
    ClipperLib::Path out;
    for (Point q : p) out.push_back({std::llround(q.x * kScale), std::llround(q.y * kScale)});
    return out;
}

inline double area(const ClipperLib::Paths& paths) {
    double a = 0;
    for (const auto& p : paths) a += ClipperLib::Area(p);
    return a / (kScale * kScale);
}

struct Report {
    double overlap = 0;        // cell area counted twice
    double over_openings = 0;  // claims over openings
    double outside = 0;        // claims outside the wall
    double coverage = 0;       // claims' union / wall area
};

inline Report check_texture(const Facade& facade, const Texture& t, double mortar) {
    Report r;
    ClipperLib::Paths drawn, claims;
    double sum = 0;
    for (const Cell& c : t.cells) {
        ClipperLib::Path p = to_path(c.polygon);
        if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
        sum += ClipperLib::Area(p) / (kScale * kScale);
        drawn.push_back(p);
        ClipperLib::ClipperOffset o(4.0);
        o.AddPath(p, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
        ClipperLib::Paths grown;
        o.Execute(grown, mortar / 2 * kScale);
        claims.insert(claims.end(), grown.begin(), grown.end());
    }
    ClipperLib::Clipper u;
    u.AddPaths(drawn, ClipperLib::ptSubject, true);
    ClipperLib::Paths drawn_union;
    u.Execute(ClipperLib::ctUnion, drawn_union, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    r.overlap = sum - area(drawn_union);
    ClipperLib::Clipper cu;
    cu.AddPaths(claims, ClipperLib::ptSubject, true);
    ClipperLib::Paths claim_union;
    cu.Execute(ClipperLib::ctUnion, claim_union, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    ClipperLib::Paths wall;
    for (const Face& f : facade.faces())
        for (const auto& loop : f.loops) wall.push_back(to_path(loop));
    ClipperLib::Clipper in;
    in.AddPaths(claim_union, ClipperLib::ptSubject, true);
    in.AddPaths(wall, ClipperLib::ptClip, true);
    ClipperLib::Paths covered, outside;
    in.Execute(ClipperLib::ctIntersection, covered, ClipperLib::pftNonZero, ClipperLib::pftEvenOdd);
    r.coverage = area(covered) / facade.wall_area();
    ClipperLib::Clipper out;
    out.AddPaths(drawn_union, ClipperLib::ptSubject, true);
    out.AddPaths(wall, ClipperLib::ptClip, true);
    out.Execute(ClipperLib::ctDifference, outside, ClipperLib::pftNonZero, ClipperLib::pftEvenOdd);
    r.outside = area(outside);
    ClipperLib::Paths holes;
    for (const auto& o : facade.openings()) holes.push_back(to_path(o));
    ClipperLib::Clipper op;
    op.AddPaths(drawn_union, ClipperLib::ptSubject, true);
    op.AddPaths(holes, ClipperLib::ptClip, true);
    ClipperLib::Paths over;
    op.Execute(ClipperLib::ctIntersection, over, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    r.over_openings = area(over);
    return r;
}

// A row-house front: 6000 x 4000 wall, two sash windows, an arched window, a door to the ground.
inline Facade row_house() {
    std::vector<FacadeShape> s;
    s.push_back(shape(rect(0, 0, 6000, 4000), {"wall"}, "front"));
    s.push_back(shape(rect(600, 1200, 900, 1400), {"window"}, "w1"));
    s.push_back(shape(rect(4500, 1200, 900, 1400), {"window"}, "w2"));
    s.push_back(shape(arched(2600, 2600, 800, 900), {"window", "arch"}, "w3"));
    s.push_back(shape(rect(2700, 3000, 600, 1000), {"door"}, "d1"));
    return Facade::from_shapes(std::move(s), "row_house.svg");
}

}  // namespace cells_test
