// Section 5.2: the error between a target neighbourhood and a reference 1-ring. Neighbours are
// paired in counter-clockwise order without skipping or flipping; the error is the minimum over
// the cyclic alignments (in rotation mode, after the best-fit rotation of each alignment).
#pragma once

#include <acanthus/point.hpp>
#include <limits>
#include <vector>

namespace acanthus::growth::detail {

struct RingEntry {
    Vector offset;    // neighbour minus centre
    int symbol = -1;  // -1: an id-less seed, which matches any symbol
    int sub = -1;     // sub-id: the reference element it is (a copy of); -1 for a seed
};

// A neighbour's neighbour (the 2-ring without the 1-ring), matched by nearest position.
struct OuterEntry {
    Vector offset;    // from the centre
    int symbol = -1;  // -1: unknown (an id-less seed), matches any symbol
};

struct Weights {
    double w1 = 1, w2 = 1, w3 = 100;
};

struct RingMatch {
    double error = std::numeric_limits<double>::infinity();
    int shift = -1;       // target[i] pairs with reference[(shift + i) % m]
    double rotation = 0;  // applied to the reference offsets
    bool found() const { return shift >= 0; }
};

// Indices of `offsets` counter-clockwise, starting after the widest angular gap (so that a
// partial neighbourhood is one consecutive run).
std::vector<int> ccw_from_widest_gap(const std::vector<Vector>& offsets);

// Error of one alignment at a given rotation.
double alignment_error(const std::vector<RingEntry>& target,
                       const std::vector<RingEntry>& reference, int shift, double rotation,
                       const Weights& w);

// alignment_error at the rotation whose cosine and sine are given (the same bits as
// Vector::rotated), summed in the same order, or infinity as soon as the sum exceeds `bound`.
double alignment_error_within(const std::vector<RingEntry>& target, const RingEntry* reference,
                              std::size_t size, int shift, double cos_r, double sin_r,
                              const Weights& w, double bound);

// The rotation that best maps the paired reference offsets onto the target ones (least squares,
// closed form; the centre stays fixed).
double best_fit_rotation(const std::vector<RingEntry>& target,
                         const std::vector<RingEntry>& reference, int shift);

// Min over the cyclic alignments; not found when the target has more neighbours than the ring.
// `rotate`: each alignment at its best-fit rotation; otherwise all at `rotation` (flow mode).
RingMatch match_ring(const std::vector<RingEntry>& target, const std::vector<RingEntry>& reference,
                     const Weights& w, bool rotate, double rotation = 0.0);

// The 2-ring term of an alignment: w2 for each target entry whose nearest reference entry (turned
// by `rotation`) has another symbol or lies farther than `reach`.
double outer_ring_error(const std::vector<OuterEntry>& target,
                        const std::vector<OuterEntry>& reference, double rotation, double reach,
                        const Weights& w);

// match_ring with the 2-ring term added to every alignment's error (the option beside the
// paper's 1-ring matching). Alignments whose 1-ring error alone reaches `bound` are skipped.
RingMatch match_two_ring(const std::vector<RingEntry>& target,
                         const std::vector<RingEntry>& reference,
                         const std::vector<OuterEntry>& target_outer,
                         const std::vector<OuterEntry>& reference_outer, const Weights& w,
                         bool rotate, double rotation, double reach, double bound);

// On a lattice, where a target neighbourhood need not be one consecutive run of the ring: each
// target neighbour pairs with the nearest ring slot (no rotation), `slots[i]` (-1 when none lies
// within `reach`, or a nearer target took it: w2 plus w1 times the distance to the nearest). The
// error has the terms of alignment_error. Not found when the target has more neighbours.
RingMatch match_by_position(const std::vector<RingEntry>& target,
                            const std::vector<RingEntry>& reference, const Weights& w, double reach,
                            std::vector<int>& slots);

}  // namespace acanthus::growth::detail
