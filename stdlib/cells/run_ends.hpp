// The ends of a course's runs at jambs laid as a mason lays them: no brick shaved to fit.
#pragma once

#include <memory>

#include "brick_layout.hpp"
#include "face_jambs.hpp"

namespace acanthus::cells::detail {

// Where a jamb (or the wall's end) falls between a course's head joints, the piece there would
// be cut to what is left: within 12% of a brick's or a header's length it is a shaved brick, a
// cut no mason makes. Per run end at a jamb, the last pieces of the run (up to three, four
// near a shaved brick, or the whole run between two jambs, its far quoin whole or the piece cut)
// are laid again from the joint before them: whole bricks and standard bats and closers (one to
// four quarter bricks), the difference taken up first in their head joints (each within the
// tolerance; the joint before them too where those are too few), and beyond that in one piece
// cut to what is left, never within 12% of a brick or a header. A quoin at the jamb is whole
// (its own length where it can, else a closer or bat), flush. A way adds no odd piece, none the
// geometry does not force and no piece narrower than a queen closer. The courses whose runs end at
// one jamb one above the other are decided together: the cheapest ways over the column (a shaved
// brick left costs most) that bring no head joint within a quarter brick of one in the course below
// or above, as each is laid in that choice.
// The ways found for a run's end, kept by all they were found from: a face laid twice (its
// window-bottom rows centred, then two units past each jamb) finds the same ways again in the
// columns the rows do not reach. One per face and its options; `fit_run_ends` without one finds
// them all afresh, with the same result.
class RunEndsMemo {
  public:
    RunEndsMemo();
    ~RunEndsMemo();
    RunEndsMemo(const RunEndsMemo&) = delete;
    RunEndsMemo& operator=(const RunEndsMemo&) = delete;
    std::size_t kept() const;  // run ends whose ways are kept
    std::size_t hits() const;  // run ends whose ways were taken from it
    struct Data;
    std::unique_ptr<Data> data;
};

void fit_run_ends(const Facade& facade, int face, const Options& options, BrickLayout& layout,
                  RunEndsMemo* memo = nullptr);

// The same ways laid again where a piece narrower than a header stands at an arris (the run's
// end at a jamb, or at its other end where that is a jamb too): a mason keeps queen closers
// beside the header there and cuts back from the arris, where a small piece is weak and shows
// on the return. Taken alone, after fit_run_ends: a way that sets a closer back from one jamb
// took the place of a better way at the next one.
void fit_arrises(const Facade& facade, int face, const Options& options, BrickLayout& layout);

// The same ways laid at a skewback's plumb side (`back`, over the courses it bounds whole; the
// skewback reaches from it to the reveal at x = `reveal`) once the skewback is set: the run it
// crosses ends there as at a jamb, its pieces beyond lying under the skewback, so the walling is
// cut at a joint there and not shaved; the run ends at jambs in the courses near it are laid
// again too, the joints under the skewback no longer in their way. Pieces laid already are not
// laid again.
void fit_run_ends_at(const Facade& facade, int face, const Options& options, BrickLayout& layout,
                     const Jamb& back, double reveal);

// A brick cut off at a jamb a few millimetres off whole quarters, laid whole (context.cpp): the
// piece `r` (its claim `claim` cut at the jamb) as drawn, or an empty rect when it is not.
Rect nominal_at_jamb(Rect r, Rect claim, Rect drawn, const Options& o);

}  // namespace acanthus::cells::detail
