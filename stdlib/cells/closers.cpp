// Inside a run the bond's own sequence already staggers the joints, so what moves is what an
// opening, a wall's end or a window-bottom row put over a joint of the course below.
#include "closers.hpp"

#include <algorithm>
#include <array>
#include <set>

namespace acanthus::cells::detail {

namespace {

// Unit lines where a piece ends and the next begins, in the same run (not at a jamb).
std::set<int> joints_of(const std::vector<Piece>& pieces) {
    std::set<int> out;
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
        if (pieces[k].start + pieces[k].length == pieces[k + 1].start)
            out.insert(pieces[k + 1].start);
    return out;
}

bool run_end(const std::vector<Piece>& pieces, std::size_t k, bool left) {
    if (left) return k == 0 || pieces[k - 1].start + pieces[k - 1].length != pieces[k].start;
    return k + 1 == pieces.size() || pieces[k].start + pieces[k].length != pieces[k + 1].start;
}

// The joint between pieces k and k + 1 moved by d units, if both stay from one to four units
// and a piece at a run's end keeps two (it may end in a part unit at the jamb).
bool movable(const std::vector<Piece>& pieces, std::size_t k, int d) {
    if (pieces[k].quoin || pieces[k + 1].quoin) return false;
    const int a = pieces[k].length + d, b = pieces[k + 1].length - d;
    if (a < 1 || b < 1 || a > 4 || b > 4) return false;
    if (run_end(pieces, k, true) && a < 2) return false;
    if (run_end(pieces, k + 1, false) && b < 2) return false;
    return true;
}

// The joint at unit line j of row r + 1 moved off `here` (the joints of row r) and the joints of
// row r + 2, when its pieces allow.
void move_below(std::vector<std::vector<Piece>>& rows, int r, int j, const std::set<int>& here) {
    if (r + 1 >= static_cast<int>(rows.size())) return;
    auto& pieces = rows[static_cast<std::size_t>(r + 1)];
    const std::set<int> under = r + 2 < static_cast<int>(rows.size())
                                    ? joints_of(rows[static_cast<std::size_t>(r + 2)])
                                    : std::set<int>{};
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
        if (pieces[k + 1].start != j || pieces[k].start + pieces[k].length != j) continue;
        for (int d : std::array<int, 4>{1, -1, 2, -2}) {
            if (!movable(pieces, k, d) || here.count(j + d) || under.count(j + d)) continue;
            pieces[k].length += d;
            pieces[k + 1].start += d;
            pieces[k + 1].length -= d;
            pieces[k].cut = pieces[k + 1].cut = true;
            return;
        }
        return;
    }
}

}  // namespace

void set_closers(BrickLayout& layout) {
    if (layout.bond.bond == Bond::stack) return;  // joints over joints is the stack bond
    auto& rows = layout.rows;
    const int n = static_cast<int>(rows.size());
    // Rows are listed from the top; courses are laid from the bottom.
    for (int r = n - 2; r >= 0; --r) {
        const std::set<int> below = joints_of(rows[static_cast<std::size_t>(r + 1)]);
        const std::set<int> above =
            r > 0 ? joints_of(rows[static_cast<std::size_t>(r - 1)]) : std::set<int>{};
        auto& pieces = rows[static_cast<std::size_t>(r)];
        for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
            if (pieces[k].start + pieces[k].length != pieces[k + 1].start) continue;
            const int j = pieces[k + 1].start;
            if (!below.count(j)) continue;
            // Neighbouring joints of this course stay where they are: no new straight joint
            // between them and the new place.
            int best = 0, best_cost = 1 << 20;
            for (int d : std::array<int, 4>{1, -1, 2, -2}) {
                if (!movable(pieces, k, d) || below.count(j + d)) continue;
                const int cost = (above.count(j + d) ? 10 : 0) + std::abs(d);
                if (cost < best_cost) best = d, best_cost = cost;
            }
            if (best == 0) {
                // Fixed here (a quoin's or a head's end): move the joint of the course below
                // instead, off this course's joints and those of the course under it.
                move_below(rows, r, j, joints_of(pieces));
                continue;
            }
            pieces[k].length += best;
            pieces[k + 1].start += best;
            pieces[k + 1].length -= best;
            pieces[k].cut = pieces[k + 1].cut = true;
        }
    }
}

}  // namespace acanthus::cells::detail
