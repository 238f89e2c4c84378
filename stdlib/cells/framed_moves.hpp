// The framed tree's fixed ends (lintel bearings, window-bottom rows' ends, quoins) moved by a
// quarter brick where two of them would stand over each other and no free piece beside either can
// take the joint: a longer or shorter bearing, a row's end a header further or nearer, the other
// quoin length in one course, as a mason breaks such a joint. Chosen by the brick layout
// (brick_layout.hpp), which tries them one by one and keeps those that leave fewer straight joints.
#pragma once

#include <map>
#include <tuple>
#include <utility>

namespace acanthus::cells::detail {

struct FramedMoves {
    // (edge, 0 at its left end, 1 at its right end): quarters added to a lintel's bearing there
    // (negative: taken off; never under kMinBearing of a brick's length).
    std::map<std::pair<int, int>, int> bearing;
    // (sill edge, 0 left, 1 right): quarters added to its window-bottom row past that jamb.
    std::map<std::pair<int, int>, int> sill_end;
    // (jamb edge, grid row): the quoin's length there in quarters, in place of its course's (the
    // other one, or a three-quarter bat).
    std::map<std::pair<int, int>, int> quoin_length;

    // Window-bottom row `edge`'s end (0 left, 1 right) moved d quarters further past its jamb;
    // false where that takes it more than a quarter either way.
    bool move_sill_end(int edge, int end, int d) {
        int& v = sill_end[{edge, end}];
        v += d;
        const bool within = v >= -1 && v <= 1;
        if (v == 0) sill_end.erase({edge, end});
        return within;
    }

    bool empty() const { return bearing.empty() && sill_end.empty() && quoin_length.empty(); }
    bool operator<(const FramedMoves& o) const {
        return std::tie(bearing, sill_end, quoin_length) <
               std::tie(o.bearing, o.sill_end, o.quoin_length);
    }
    int count(const std::map<std::pair<int, int>, int>& m, int edge, int side) const {
        auto it = m.find({edge, side});
        return it == m.end() ? 0 : it->second;
    }
};

// A lintel bears at least 100 mm on a 215 mm brick's wall, in brick lengths.
constexpr double kMinBearing = 100.0 / 215.0;

}  // namespace acanthus::cells::detail
