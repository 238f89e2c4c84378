// Near-regular references (the paper's second class, between a lattice and a scatter): a
// jittered lattice that no exact translation maps onto itself (lattice.hpp finds none), whose
// interior elements' shortest ring offsets still point along a few lattice directions. Synthesis
// fits each motif of such a reference to its own chosen ring (synthesis.hpp); irregular
// references are spared that.
#pragma once

namespace acanthus::growth::detail {

struct ReferenceData;

struct RingRegularity {
    // The bond-orientational order of the interior elements' first shells (their kShell shortest
    // ring offsets): |mean of exp(i n angle)| for the n-fold symmetry (4: square, 6: triangular
    // and honeycomb) that gives the larger value. 1: every such offset on a lattice direction;
    // a scatter with no preferred direction: about 1/sqrt(offsets).
    double order = 0;
    int fold = 0;  // that n (0: too few offsets)
    // The RMS angle (radians) by which the offsets miss the lattice directions, were their
    // scatter normal: sqrt(2 ln(1/order)) / fold.
    double spread = 0;
    bool near_regular = false;
    // The first shell stands apart from the rest of the ring (the median over the elements of
    // the 4th shortest offset over the 3rd is above kShellGap): a honeycomb, whose next
    // neighbours are sqrt(3) edges away, where a triangular or square lattice's are not.
    bool honeycomb = false;
};

// The shortest ring offsets per element measured: a honeycomb's three edges, a square grid's
// sides before its diagonals, half a triangular ring.
inline constexpr int kShell = 3;
// Near-regular from this order up (docs/stdlib/growth.md, "Near-regular references"): a first
// shell scattered by at most 0.23 rad (13 degrees) RMS about six directions, 0.34 about four.
// Dart-thrown sets measure 0.05 to 0.29, the tests' jittered lattices 0.54 to 0.98.
inline constexpr double kNearRegularOrder = 0.4;
// And at least this many times a scatter's noise (1/sqrt(offsets)), so that a small reference's
// chance alignment is not taken for a lattice.
inline constexpr double kNoiseMargin = 4;

inline constexpr double kShellGap = 1.35;

RingRegularity ring_regularity(const ReferenceData& reference);

}  // namespace acanthus::growth::detail
