// Delaunay triangulation of a point set (CGAL), returned as index triples with neighbours.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "triangulation.hpp"

namespace acanthus::common {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

// The first index of each distinct point, in Hilbert order: CGAL's hilbert_sort is
// deterministic (spatial_sort shuffles at random) and keeps point location short.
std::vector<std::size_t> insertion_order(const std::vector<Kernel::Point_2>& points) {
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a] < points[b] || (points[a] == points[b] && a < b);
    });
    order.erase(std::unique(order.begin(), order.end(),
                            [&](std::size_t a, std::size_t b) { return points[a] == points[b]; }),
                order.end());
    using Traits = CGAL::Spatial_sort_traits_adapter_2<
        Kernel, CGAL::Pointer_property_map<Kernel::Point_2>::const_type>;
    CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(points)));
    return order;
}

}  // namespace

std::vector<DelaunayTriangle> delaunay_triangulation(const std::vector<Point>& points) {
    std::vector<Kernel::Point_2> input;
    input.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].finite())
            throw std::invalid_argument("delaunay_triangulation: point " + std::to_string(i) +
                                        " is not finite");
        input.emplace_back(points[i].x, points[i].y);
    }
    if (input.size() < 3) return {};  // CGAL's property map would index an empty vector
    Delaunay dt;
    Delaunay::Face_handle hint;
    for (std::size_t i : insertion_order(input)) {
        Delaunay::Vertex_handle v = dt.insert(input[i], hint);
        v->info() = static_cast<int>(i);
        hint = v->face();
    }
    if (dt.dimension() < 2) return {};

    // Each triangle starts at its smallest vertex (a rotation keeps the orientation and which
    // edge lies opposite which vertex); then triangles are sorted and neighbours renumbered.
    std::vector<DelaunayTriangle> triangles;
    int id = 0;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) f->info() = id++;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
        DelaunayTriangle t;
        for (int k = 0; k < 3; ++k) {
            t.vertices[k] = f->vertex(k)->info();
            t.neighbors[k] = dt.is_infinite(f->neighbor(k)) ? -1 : f->neighbor(k)->info();
        }
        auto first = std::min_element(t.vertices.begin(), t.vertices.end()) - t.vertices.begin();
        std::rotate(t.vertices.begin(), t.vertices.begin() + first, t.vertices.end());
        std::rotate(t.neighbors.begin(), t.neighbors.begin() + first, t.neighbors.end());
        triangles.push_back(t);
    }
    std::vector<int> order(triangles.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return triangles[a].vertices < triangles[b].vertices; });
    std::vector<int> renumbered(triangles.size());
    for (std::size_t k = 0; k < order.size(); ++k) renumbered[order[k]] = static_cast<int>(k);
    std::vector<DelaunayTriangle> sorted;
    sorted.reserve(triangles.size());
    for (int k : order) {
        DelaunayTriangle t = triangles[k];
        for (int& n : t.neighbors)
            if (n >= 0) n = renumbered[n];
        sorted.push_back(t);
    }
    return sorted;
}

}  // namespace acanthus::common
