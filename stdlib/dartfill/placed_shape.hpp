// An exclusive region under the transformation of Eq. 1 (x = (RS + T) x0 about the bounding-box
// centre), and exact overlap tests between two of them.
#pragma once

#include <vector>

#include "shape.hpp"

namespace acanthus::dartfill {

struct Pose {
    Point position;       // where the shape's bounding-box centre goes
    double rotation = 0;  // radians, counter-clockwise in y-up terms
    double scale = 1;
};

class PlacedShape {
  public:
    PlacedShape(const Shape& shape, int shape_index, Pose pose);

    int shape_index() const { return shape_index_; }
    const Pose& pose() const { return pose_; }
    const std::vector<Triangle>& triangles() const { return triangles_; }
    const std::vector<Rect>& triangle_bounds() const { return triangle_bounds_; }
    const std::vector<Point>& outline() const { return outline_; }
    Rect bounds() const { return bounds_; }
    Circle bounding_circle() const { return circle_; }
    double area() const { return area_; }
    // True when p lies inside (or on) one of the triangles.
    bool contains(Point p) const;

  private:
    int shape_index_;
    Pose pose_;
    std::vector<Point> outline_;
    std::vector<Triangle> triangles_;
    std::vector<Rect> triangle_bounds_;
    Rect bounds_;
    Circle circle_;
    double area_;
};

// Separating-axis test: true when the triangles share area deeper than `tolerance`.
bool triangles_overlap(const Triangle& a, const Triangle& b, double tolerance);
// Bounding circles, then boxes, then triangle pairs whose boxes meet.
bool shapes_overlap(const PlacedShape& a, const PlacedShape& b, double tolerance);
bool point_in_triangle(const Triangle& t, Point p);
bool boxes_meet(const Rect& a, const Rect& b);

}  // namespace acanthus::dartfill
