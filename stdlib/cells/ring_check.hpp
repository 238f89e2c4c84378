// Rings of arches that would meet (two arched openings close together, or an arch beside a
// flat head's lintel): they are turned as half-brick rings where that clears them; two rings
// that still meet refuse the facade, naming both openings. A voussoir cut by another ring or a
// lintel is no voussoir.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "course_grid.hpp"

namespace acanthus::cells::detail {

// The area a ring covers, as simple polygons (its band cut into short pieces, its skewbacks'
// triangles, or a lintel's rectangle), with their bounding box.
struct RingShape {
    std::vector<std::vector<Point>> parts;
    Rect box;
};

// The ring `depth` deep round the arcs of one arch (`arcs`: arch_arcs()), with the room its
// skewbacks may take.
RingShape ring_shape(const Facade& facade, const Options& options,
                     const std::vector<const Edge*>& arcs, double depth);
// The rectangle the lintel over straight head `head` takes: on the ashlar `grid` of its face,
// the one it will be laid as; in brick (no grid), the most it may take (its bearing past each
// jamb rounded out to a whole unit, the courses over the head).
RingShape lintel_shape(const Edge& head, const Options& options, const CourseGrid* grid);

// Whether two shapes share area: edges that cross, or one inside the other (touching passes).
bool shapes_meet(const RingShape& a, const RingShape& b);
bool polygons_meet(const std::vector<Point>& a, const std::vector<Point>& b);

struct RingPlan {
    // Per arch, by the lowest index of its arc edges: the depth its ring is laid at (0: none
    // fits beside the wall's end).
    std::map<int, double> depth;
    // Two arched openings whose rings meet even as half-brick rings; empty when none. Named by
    // their labels.
    std::string clash_a, clash_b;
};

// Where the lintel over a straight head is laid, once the courses are known (false: none).
using LintelRect = std::function<bool(const Edge& head, Rect& out)>;

// The rings of every arched opening of `facade`, `depth` deep where they fit: an arch whose
// ring would meet another's, or a lintel's, is turned as one half-brick ring. A brick lintel
// takes the rectangle `laid` gives where given (the one laid), else the most it may take.
RingPlan plan_rings(const Facade& facade, const Options& options, double depth,
                    const LintelRect& laid = {});

// An opening's labels as messages name it ("window arch w1").
std::string names_of(const Edge& e);

// The key plan_rings() files the arch of arc edge `e` under.
int arch_key(const Facade& facade, const Edge& e);

}  // namespace acanthus::cells::detail
