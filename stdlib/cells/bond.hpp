// Brick bonds as sequences of pieces along a course, in quarter-brick units of the grid:
// stretcher 4, header 2. Each course's sequence is shifted so that the bond's joints stagger.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <span>
#include <vector>

namespace acanthus::cells::detail {

struct Piece {
    int start = 0;  // first unit
    int length = 0;
    bool cut = false;    // shorter or longer than the bond's piece there (a bat or a closer)
    bool full = false;   // every unit fully inside the face
    bool sill = false;   // a header of a window-bottom row (sill_rows.hpp)
    bool quoin = false;  // a jamb quoin, bonded in (quoin_rows.hpp); its joints stay
    bool head = false;   // a lintel's stretch of the course (lintel.hpp); its joints stay
    bool king = false;   // a king closer: a header and its queen closer in one brick (Flemish)
    bool fixed() const { return quoin || head; }
};

struct BondPattern {
    Bond bond = Bond::running;
    // Added to the course number: 1 swaps English bond's stretcher and header courses, for a face
    // whose building corner is at its right end (quoin_rows.hpp).
    int course_shift = 0;
    // Piece lengths of `course` (counted from the bottom) and where the sequence starts.
    std::span<const int> lengths(int course) const;  // static storage: asked per run of units
    int offset(int course) const;
    int period() const;  // phases tried for the fewest cut pieces
};

// The pieces of a run of units [a, b) in `course`, the sequence shifted by `phase`. A one-unit
// remnant at either end joins its neighbour (as a three-quarter bat, or a half bat and a
// three-quarter bat), so no quarter bats are laid.
void pieces_of_run(const BondPattern& bond, int course, int phase, int a, int b,
                   std::vector<Piece>& out);

// A course's pieces (in order) with units [a, b) taken out for a quoin or a window-bottom row:
// pieces clear of it kept, those across a or b cut there (each remnant a cut piece that keeps
// its `sill`), in order. The caller puts in what fills [a, b).
std::vector<Piece> cut_out(const std::vector<Piece>& pieces, int a, int b);

}  // namespace acanthus::cells::detail
