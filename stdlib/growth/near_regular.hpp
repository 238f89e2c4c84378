// Near-regular references (the paper's second class, between a lattice and a scatter): a
// jittered lattice that no exact translation maps onto itself (lattice.hpp finds none), whose
// interior elements' shortest ring offsets still point along a few lattice directions. Synthesis
// puts each motif of such a reference on its lattice site plus its element's own jitter
// (synthesis.hpp); irregular references are spared that.
#pragma once

#include <acanthus/point.hpp>
#include <optional>
#include <utility>
#include <vector>

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
    double direction = 0;  // one lattice direction (radians): the mean first-shell phase
    double shell = 0;      // the median first-shell offset length
};

// A near-regular reference fitted to the lattice it jitters: each element's ideal site (on one
// lattice of translations: a honeycomb's sites are a triangular lattice of its edge, a third of
// it empty) and its own offset from it. Synthesis grows sites at the lattice's exact spacing and
// gives each motif its copied element's offset, so the grown arrangement keeps the reference's
// jitter without adding up the errors of the offsets it copies.
struct JitteredLattice {
    std::vector<Point> site;     // per element
    std::vector<Vector> jitter;  // per element: position - site
    Vector basis[2];             // the lattice's translations
    Point origin;                // a lattice point: every site is origin + i basis[0] + j basis[1]
    double rms = 0;              // RMS jitter in units of the basis length
    // A honeycomb: the sublattice (of the three at sqrt(3) spacing, by lattice coordinates'
    // difference modulo 3) no element holds, its hexagons' centres; -1: none.
    int vacant = -1;

    // The lattice coordinates (i, j) of the site nearest `p`.
    std::pair<long, long> index(Point p) const;
    Point site_at(std::pair<long, long> index) const;
    // A honeycomb's sublattice of (i, j): (i - j) modulo 3, as `vacant` counts it.
    static int sublattice(std::pair<long, long> index);
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
// Worked out once per reference: ring_regularity(), and fit_jittered_lattice() on it when it is
// near-regular (null: not, or no lattice fits).
const RingRegularity& regularity_of(const ReferenceData& reference);
const JitteredLattice* jittered_lattice_of(const ReferenceData& reference);

// Fits a near-regular reference to the triangular (fold 6) or square (fold 4) lattice its rings
// show; none when no lattice explains it (two elements on one site, or a jitter above
// kMostJitter of the spacing RMS).
std::optional<JitteredLattice> fit_jittered_lattice(const ReferenceData& reference,
                                                    const RingRegularity& regularity);
// A lattice jittered by 0.2 of its spacing each way measures 0.16 RMS; above this the sites
// explain little.
inline constexpr double kMostJitter = 0.3;

}  // namespace acanthus::growth::detail
