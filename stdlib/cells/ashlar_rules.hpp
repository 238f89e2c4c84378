// The joint-rules ashlar of a face: stones laid in reading order on the ashlar grid, each of a
// random size no taller than wide, chosen so that no four stones meet at a point, no unit
// squares touch and no straight joint runs along more than `max_seam` stones where some size
// allows it. Stones laid before (jambs, sills, lintels, arch rings) are known by the units they
// hold, so the rules hold against them too.
#pragma once

#include <acanthus/random.hpp>
#include <cstdint>
#include <tuple>
#include <unordered_set>
#include <vector>

#include "ashlar_merge.hpp"  // Stone
#include "course_grid.hpp"

namespace acanthus::cells::detail {

class AshlarRules {
  public:
    static constexpr int kBlocked = -2, kEmpty = -1;
    // Every unit starts blocked; free() opens one for the layout, hold() gives it to a stone
    // laid before (ids from 0, distinct from the layout's own, which count on from `first_id`).
    // `square`: a stone narrower and lower than this (a unit and a half, measured) is a unit
    // square to a mason, whatever units of the grid it spans.
    AshlarRules(const CourseGrid& g, int max_w, int max_h, int max_seam, int first_id,
                double square);

    void free(int r, int u) { at(r, u) = kEmpty; }
    // A unit against a jamb or the wall's end: a stone starting there may stand on end, one
    // unit wide and up to max_h high, as the paper's edge stones take random heights.
    void jamb(int r, int u) { jamb_[static_cast<std::size_t>(r * units_ + u)] = 1; }
    // A unit the face holds only `share` of across (a strip cut to a jamb or a skewback off
    // the grid's lines): a stone there is as narrow as what is left of it.
    void cut(int r, int u, double share) {
        share_[static_cast<std::size_t>(r * units_ + u)] = share;
    }
    // `shaped`: a stone not rectangular (a voussoir), whose joints are no grid lines.
    // `small`: that stone is a unit square (see `square`).
    void hold(int r, int u, int id, bool shaped = false, bool small = false) {
        at(r, u) = id;
        shaped_[static_cast<std::size_t>(r * units_ + u)] = shaped;
        small_held_[static_cast<std::size_t>(r * units_ + u)] = small;
    }
    int get(int r, int u) const {
        if (r < 0 || u < 0 || r >= rows_ || u >= units_) return kBlocked;
        return owner_[static_cast<std::size_t>(r * units_ + u)];
    }
    // Lays every free unit; whole rows before any becomes a cell, each reported as progress.
    void lay(Random& random);
    const std::vector<Stone>& stones() const { return stones_; }
    static constexpr int kMaxRounds = 16;
    // Rounds of repairs lay() ran, the last (which changed nothing) included; kMaxRounds + 1
    // where the bound stopped them.
    int rounds() const { return rounds_; }

  private:
    int& at(int r, int u) { return owner_[static_cast<std::size_t>(r * units_ + u)]; }
    bool fits(int r, int u, int h, int w) const;
    int faults(int r, int u, int h, int w) const;
    int cross(int r, int u, int h, int w, int i, int j) const;
    const Stone* own(int id) const;  // a stone of this layout, or null
    void lay_at(int r, int u, Random& random);
    // Grid points (rows r0..r1, units u0..u1) where four laid rectangular stones meet.
    int four_ways(int r0, int r1, int u0, int u1) const;
    // Unit square `k` on end joined to the row it shares of a taller stone beside it; false
    // (nothing changed) where none can take it without more four-way joints than allowed.
    bool split_beside(int k, const std::vector<char>& gone);
    // True while one four-way joint more keeps the face within 1% of its stones: the layout's
    // own (`gone` aside) and those laid before, as a mason counts them.
    bool four_way_allowed(const std::vector<char>& gone) const;
    // Unit squares on end joined to a stone beside them; true when any was.
    bool join_on_end(std::vector<char>& gone);
    // Four-way joints broken by moving the side joint between two stones of one row (and one
    // height) by a unit, or by joining them, where none ends on end or beside a unit square
    // and the joints round them lose one; true when any was.
    bool break_four_ways(std::vector<char>& gone);
    bool lone_square(const Stone& s, int other) const;
    // Measured as the face holds it, under `square` both ways.
    bool small(const Stone& s) const;
    // Unit (r, u) held by a unit square: one of the layout, or one laid before.
    bool small_at(int r, int u) const;
    // Calls f(r, u) on the units round stone `s` (above, below, left and right of it), each once.
    template <class F>
    void each_beside(const Stone& s, F f) const {
        for (int u = s.unit; u < s.unit + s.w; ++u) f(s.row - 1, u), f(s.row + s.h, u);
        for (int r = s.row; r < s.row + s.h; ++r) f(r, s.unit - 1), f(r, s.unit + s.w);
    }
    bool on_end(const Stone& s) const;
    // Measured as the face holds it (a unit cut by a jamb counts as what is left of it): no
    // taller than wide, or one unit wide against a jamb.
    bool upright(const Stone& s) const;
    // The order every repair lowers, compared in turn: the face over 1% of four-way joints
    // (counted over its stones, those laid before too), stones on end, four-way joints, unit
    // squares side by side. A repair taken only where it lowers it cannot undo another's.
    using Key = std::tuple<int, long, long, long>;
    // The layout's stones still laid and the rectangular ones laid before.
    long live(const std::vector<char>& gone) const;
    // The stones `ks` of the layout laid again over the same units, every way the rules allow
    // (largest stones first, up to `max_nodes` steps), the tiling with the lowest key kept where
    // it is lower than now; true when it was.
    bool relay(std::vector<int> ks, std::vector<char>& gone, long max_nodes = 20000);
    // Each four-way joint, stone on end and unit square beside another of the layout laid again
    // with the stones round it; true when any was.
    bool relay_faults(std::vector<char>& gone);

    const CourseGrid& g_;
    int rows_, units_, max_w_, max_h_, max_seam_, first_id_;
    std::vector<int> owner_;
    double square_;
    std::vector<char> jamb_, shaped_, small_held_;
    std::vector<double> share_;
    std::vector<Stone> stones_;
    int four_way_ = 0;  // four-way joints of the face, counted once laid
    int held_ = 0;      // rectangular stones laid before, counted once laid
    int rounds_ = 0;
    std::unordered_set<std::uint64_t> failed_;  // relays that found nothing (see relay())
};

}  // namespace acanthus::cells::detail
