// From one closed boundary loop of a face to its edges and corners [3.1].
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <vector>

#include "facade_data.hpp"

namespace acanthus::cells::detail {

// A segment of a loop and the shape it lies on (its labels and whether it is an opening's).
struct LoopSegment {
    Segment segment;
    int shape = -1;
};

struct ShapeLabels {
    std::vector<std::string> labels;  // class words, then the id
    bool opening = false;
};

// Tangent turn (radians) above which a vertex is a corner.
inline constexpr double kCornerTurn = 10.0 * M_PI / 180.0;

// Appends the loop's edges and corners to `data` for face `face`. `interior_left`: the face lies
// on the left of the loop's direction.
void add_loop(FacadeData& data, int face, const std::vector<LoopSegment>& loop, bool interior_left,
              const std::vector<ShapeLabels>& shapes);

// Points along the segments, arcs cut into chords within `tolerance`.
void flatten(const Segment& s, double tolerance, std::vector<Point>& out);

}  // namespace acanthus::cells::detail
