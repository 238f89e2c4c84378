// Constrained Delaunay triangulation of a polygon, keeping the inside triangles (CGAL compiles
// slowly: one translation unit per kind of triangulation).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <deque>

#include "triangulation.hpp"

namespace acanthus::common {
namespace {

struct FaceInfo {
    int nesting = -1;  // -1 unvisited; odd levels are inside the polygon
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_2<Kernel>;
using FaceBase0 = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel, FaceBase0>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// Flood fill across unconstrained edges; crossing a constraint goes one level deeper. The
// infinite face and everything reachable from it without crossing the outline is level 0.
void mark_nesting(Cdt& cdt) {
    std::deque<std::pair<Cdt::Face_handle, int>> border{{cdt.infinite_face(), 0}};
    while (!border.empty()) {
        auto [start, level] = border.front();
        border.pop_front();
        if (start->info().nesting != -1) continue;
        std::deque<Cdt::Face_handle> queue{start};
        start->info().nesting = level;
        while (!queue.empty()) {
            Cdt::Face_handle f = queue.front();
            queue.pop_front();
            for (int i = 0; i < 3; ++i) {
                Cdt::Face_handle n = f->neighbor(i);
                if (n->info().nesting != -1) continue;
                if (cdt.is_constrained({f, i})) {
                    border.emplace_back(n, level + 1);
                } else {
                    n->info().nesting = level;
                    queue.push_back(n);
                }
            }
        }
    }
}

}  // namespace

std::vector<std::array<Point, 3>> triangulate_polygon(const std::vector<Point>& outline) {
    Cdt cdt;
    std::vector<Kernel::Point_2> points;
    points.reserve(outline.size());
    for (Point p : outline) points.emplace_back(p.x, p.y);
    cdt.insert_constraint(points.begin(), points.end(), /*close=*/true);
    mark_nesting(cdt);

    std::vector<std::array<Point, 3>> triangles;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (f->info().nesting % 2 != 1) continue;
        std::array<Point, 3> t;
        for (int i = 0; i < 3; ++i) {
            const auto& q = f->vertex(i)->point();
            t[i] = Point{q.x(), q.y()};
        }
        triangles.push_back(t);
    }
    return triangles;
}

}  // namespace acanthus::common
