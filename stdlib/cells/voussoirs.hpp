// Stones in rows along an arc edge [5.2]: in each free stretch of the edge, as many as the
// length asks for, cut by radial joints.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <vector>

namespace acanthus::cells::detail {

// `width` along the arc (the count is the stretch's length over it, rounded), `depth` per row.
void place_voussoirs(const Edge& edge, Context& c, double width, double depth, int rows);
// The keystone between two arcs of an arch meeting at corner `k` at an angle (a pointed apex), if
// any: `width` along the arcs (half each side of the apex), `depth` into the wall.
void place_keystone(const Corner& k, Context& c, double depth, double width);
// The skewback under a ring springing from a plumb jamb at corner `k` (a segmental arch), its
// bed at y = `bed` (SVG numbers, at or below the springing).
void place_skewback(const Corner& k, Context& c, double depth, double bed);
// The straight plumb jamb a segmental arc springs from at its end `corner`, if any.
const Edge* plumb_jamb(const Facade& facade, const Edge& arc, int corner);
// The arcs of one arch: `e` and the arcs it meets at an angle (a pointed arch's two halves), or
// the arcs of one circle.
std::vector<const Edge*> arch_arcs(const Facade& facade, const Edge& e);
// Whether a ring `depth` deep round arc `edge`, with its skewbacks, lies in the wall.
bool ring_fits(const Facade& facade, const Edge& edge, double depth);
// Even-odd: inside the face's flattened boundary (its outline and the openings in it).
bool in_face(const Face& face, Point p);
// The edge of face `face`'s outline (the wall's or an opening's) nearest to `p`.
const Edge* nearest_edge(const Facade& facade, int face, Point p);
// Another opening a ring `depth` deep round arc `edge` reaches into, if any (else the ring fits
// or reaches past the wall's outline).
const Edge* opening_in_ring(const Facade& facade, const Edge& edge, double depth);
// The depth the ring of the arch `edge` belongs to (with a pointed arch's other half) is turned
// in, by the wall alone: `depth` where it fits, else a half brick (one half-brick ring) where
// that fits, else 0. Other rings and lintels near it: plan_rings() (ring_check.hpp).
double ring_depth(const Facade& facade, const Edge& edge, const Options& options, double depth);

}  // namespace acanthus::cells::detail
