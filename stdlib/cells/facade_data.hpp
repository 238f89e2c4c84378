// What a Facade holds: its features and the faces as integer polygons for the occupancy maps.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <polyclipping/clipper.hpp>
#include <string>
#include <vector>

namespace acanthus::cells::detail {

struct FacadeData {
    std::string name;
    std::vector<Corner> corners;
    std::vector<Edge> edges;
    std::vector<Face> faces;
    Rect bounds;
    double wall_area = 0;
    std::vector<std::vector<Point>> openings;
    double scale = 1;                                  // Clipper integer units per user unit
    std::vector<ClipperLib::Paths> face_rings;         // per face: outer rings and holes (even-odd)
    std::vector<std::vector<std::string>> face_walls;  // per face: the wall shapes, for messages
};

}  // namespace acanthus::cells::detail
