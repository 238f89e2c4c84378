// Section 5.4 (Figure 6): the chosen ring's unmatched neighbours become seeds, unless one lies
// within l_short of an existing node (merged), makes too sharp an angle with an existing edge
// (dropped) or its edge crosses another (dropped); ring edges longer than l_long get an extra
// id-less seed on the bisector.
#include <algorithm>
#include <cmath>

#include "synthesis.hpp"

namespace acanthus::growth::detail {
namespace {

// Counter-clockwise angle from u to v in [0, 2pi).
double ccw_angle(Vector u, Vector v) {
    double a = std::atan2(u.cross(v), u.dot(v));
    return a < 0 ? a + 2 * M_PI : a;
}

double unsigned_angle(Vector u, Vector v) { return std::abs(std::atan2(u.cross(v), u.dot(v))); }

}  // namespace

void Synthesis::spawn(int centre, const Choice& choice, const std::vector<int>& target_nodes) {
    const auto& ring = reference_.rings[choice.element];
    const std::size_t m = ring.size();
    const double rotation = pattern_[centre].rotation;
    std::vector<int> slot_node(m, -1);
    for (std::size_t i = 0; i < target_nodes.size(); ++i) {
        int slot = choice.slot(i, m);
        if (slot >= 0) slot_node[static_cast<std::size_t>(slot)] = target_nodes[i];
    }
    std::vector<std::size_t> open;
    for (std::size_t j = 0; j < m; ++j)
        if (slot_node[j] < 0) open.push_back(j);

    for (std::size_t j : open) {
        const Point p = pattern_[centre].position;
        const Vector offset = ring[j].offset.rotated(rotation);
        Point q = p + offset;
        if (on_lattice()) {
            // The new seed goes on its lattice point, so that fronts meeting agree exactly.
            Lattice::Spot spot = lattice_->nearest(origin_, q);
            if (spot.residual > kOffLattice * spacing_) {
                ++stats_.dropped;
                continue;
            }
            q = spot.at;
        }
        if (!panel_.contains(q) || !panel_.reaches(p, q)) {
            ++stats_.dropped;
            continue;
        }
        // (b): an element or seed within l_short takes the new seed's place.
        int near = pattern_.nearest(q, l_short_, centre);
        // Off a lattice, also a node closer than the reference ever has the two symbols.
        if (near < 0) near = too_close(centre, q, reference_.symbol[ring[j].element], false);
        if (near >= 0 && !panel_.reaches(p, pattern_[near].position)) {
            ++stats_.dropped;  // it lies beyond a boundary stroke
            continue;
        }
        if (near >= 0) {
            ++stats_.merged;
            slot_node[j] = near;
            Point pn = pattern_[near].position;
            if (!pattern_.linked(centre, near) && !pattern_.crosses(p, pn, centre, near))
                pattern_.link(centre, near, offset);
            continue;
        }
        // (c): too sharp an angle with an edge already at the centre.
        double original = std::min(ccw_angle(ring[(j + m - 1) % m].offset, ring[j].offset),
                                   ccw_angle(ring[j].offset, ring[(j + 1) % m].offset));
        if (m == 1) original = 2 * M_PI;
        bool sharp = false;
        for (const Link& l : pattern_[centre].links)
            if (unsigned_angle(pattern_[l.node].position - p, offset) <
                options_.angle_factor * original) {
                sharp = true;
                break;
            }
        // (d): the new edge crosses an existing one.
        if (sharp || pattern_.crosses(p, q, centre, -1)) {
            ++stats_.dropped;
            continue;
        }
        int seed = new_seed(q, reference_.symbol[ring[j].element]);
        pattern_.link(centre, seed, offset);
        slot_node[j] = seed;
    }

    // Edges between consecutive ring neighbours that bound a reference triangle.
    for (std::size_t j = 0; j < m; ++j) {
        if (!ring[j].closed || m < 2) continue;
        int a = slot_node[j], b = slot_node[(j + 1) % m];
        if (a < 0 || b < 0 || a == b || pattern_.linked(a, b)) continue;
        Vector desired = (ring[(j + 1) % m].offset - ring[j].offset).rotated(rotation);
        link_ring_pair(centre, a, b, (ring[(j + 1) % m].offset - ring[j].offset).length(), desired);
    }
}

void Synthesis::link_ring_pair(int centre, int a, int b, double original, Vector desired) {
    const Point p = pattern_[centre].position;
    const Point pa = pattern_[a].position, pb = pattern_[b].position;
    if (distance(pa, pb) <= options_.long_factor * original) {
        if (!pattern_.crosses(pa, pb, a, b) && panel_.reaches(pa, pb)) pattern_.link(a, b, desired);
        return;
    }
    // (e): too long; an id-less seed at the end of the bisector of angle a-centre-b, as long as
    // the mean of the two edges, linked to all three.
    Vector va = pa - p, vb = pb - p;
    if (!(va.cross(vb) > 0)) return;
    Vector dir = (va.normalized() + vb.normalized()).normalized();
    Point x = p + dir * ((va.length() + vb.length()) / 2);
    if (on_lattice()) {
        Lattice::Spot spot = lattice_->nearest(origin_, x);
        if (spot.residual > kOffLattice * spacing_) return;
        x = spot.at;
    }
    if (!panel_.contains(x) || !panel_.reaches(p, x) || pattern_.nearest(x, l_short_, -1) >= 0 ||
        pattern_.crosses(p, x, centre, -1))
        return;
    int seed = new_seed(x, -1);
    pattern_.link(centre, seed, x - p);
    // (f): link the extra seed to a and b where no edge is in the way.
    for (int end : {a, b}) {
        Point pe = pattern_[end].position;
        if (!pattern_.crosses(pe, x, end, seed) && panel_.reaches(pe, x))
            pattern_.link(end, seed, x - pe);
    }
}

}  // namespace acanthus::growth::detail
