// An exclusive region (Sakurai & Miyata 2012, section 3.1): a simple closed polygon, possibly
// concave, with its triangulation and the measures placement needs.
#pragma once

#include <acanthus/point.hpp>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus::dartfill {

using Triangle = std::array<Point, 3>;

class Shape {
  public:
    // Validates the outline (finite, at least three distinct points, non-zero area, no
    // self-intersection) and triangulates it. Throws InputError naming `name`.
    static Shape from_points(std::string name, std::vector<Point> outline);
    // Parses SVG path data with lib2geom and flattens curves to `tolerance` (user units).
    // The path must hold exactly one closed subpath.
    static Shape from_path_data(std::string name, std::string_view path_data, double tolerance);

    const std::string& name() const { return name_; }
    // Counter-clockwise (in y-up terms; positive signed area), no repeated closing point.
    const std::vector<Point>& outline() const { return outline_; }
    // Triangles of the constrained Delaunay triangulation inside the outline.
    const std::vector<Triangle>& triangles() const { return triangles_; }
    Rect bounds() const { return bounds_; }
    // Centre of transformation: the bounding-box centre.
    Point center() const { return bounds_.center(); }
    // Bounding circle about center(): distance to the farthest vertex (Figure 9).
    double radius() const { return radius_; }
    double area() const { return area_; }
    // An interior point far from the outline (pole of inaccessibility, to a grid's precision):
    // the anchor the medial method puts at the centre of a gap.
    Point pole() const { return pole_; }

  private:
    Shape() = default;
    std::string name_;
    std::vector<Point> outline_;
    std::vector<Triangle> triangles_;
    Rect bounds_;
    double radius_ = 0;
    double area_ = 0;
    Point pole_;
};

// Signed area of a closed polygon (shoelace); positive when counter-clockwise in y-up terms.
double signed_area(const std::vector<Point>& ring);
// Flattens every closed subpath of SVG path data into rings; throws InputError naming `name`.
std::vector<std::vector<Point>> flatten_path_data(const std::string& name,
                                                  std::string_view path_data, double tolerance);

}  // namespace acanthus::dartfill
