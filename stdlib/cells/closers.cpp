// Inside a run the bond's own sequence already staggers the joints, so what moves is what an
// opening, a wall's end or a window-bottom row put over a joint of the course below.
#include "closers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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
bool movable(const std::vector<Piece>& pieces, std::size_t k, int d, bool keep_sill_ends) {
    if (pieces[k].fixed() || pieces[k + 1].fixed()) return false;
    // A window-bottom row's ends set out about the opening's middle stay: the course below moves.
    if (keep_sill_ends && pieces[k].sill != pieces[k + 1].sill) return false;
    const int a = pieces[k].length + d, b = pieces[k + 1].length - d;
    if (a < 1 || b < 1 || a > 4 || b > 4) return false;
    if (run_end(pieces, k, true) && a < 2) return false;
    if (run_end(pieces, k + 1, false) && b < 2) return false;
    return true;
}

// The joint between pieces k and k + 1 taken out: one piece of both, at most a whole brick, when
// neither is fixed or a window-bottom header (two headers there would make a stretcher).
bool removable(const std::vector<Piece>& pieces, std::size_t k) {
    const Piece &a = pieces[k], &b = pieces[k + 1];
    return !a.fixed() && !b.fixed() && !a.sill && !b.sill && a.length + b.length <= 4;
}

constexpr int kRemove = 100;  // a move that takes the joint out

void apply(std::vector<Piece>& pieces, std::size_t k, int d) {
    if (d == kRemove) {
        pieces[k].length += pieces[k + 1].length;
        pieces[k].cut = true;
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(k) + 1);
        return;
    }
    pieces[k].length += d;
    pieces[k + 1].start += d;
    pieces[k + 1].length -= d;
    pieces[k].cut = pieces[k + 1].cut = true;
}

// The ways the joint at k may go, in order of preference: a quarter or half brick either way,
// then out (the two pieces one, a three-quarter bat or a stretcher).
constexpr std::array<int, 5> kMoves{1, -1, 2, -2, kRemove};

// The joint at unit line j of row r + 1 moved off `here` (the joints of row r) and the joints of
// row r + 2, when its pieces allow. Where every place clear of `here` falls on a joint of row r + 2
// (a header bond leaves every other line to the course below), the joint goes there and that one
// of row r + 2 moves in turn, down to `depth` courses.
void move_below(std::vector<std::vector<Piece>>& rows, int r, int j, const std::set<int>& here,
                bool keep_sill_ends, int depth = 8) {
    if (r + 1 >= static_cast<int>(rows.size()) || depth <= 0) return;
    auto& pieces = rows[static_cast<std::size_t>(r + 1)];
    const std::set<int> under = r + 2 < static_cast<int>(rows.size())
                                    ? joints_of(rows[static_cast<std::size_t>(r + 2)])
                                    : std::set<int>{};
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
        if (pieces[k + 1].start != j || pieces[k].start + pieces[k].length != j) continue;
        int fallback = 0;
        for (int d : kMoves) {
            if (d == kRemove ? !removable(pieces, k) : !movable(pieces, k, d, keep_sill_ends))
                continue;
            if (d != kRemove && here.count(j + d)) continue;
            if (d != kRemove && under.count(j + d)) {
                if (fallback == 0) fallback = d;
                continue;
            }
            apply(pieces, k, d);
            return;
        }
        if (fallback == 0) return;
        apply(pieces, k, fallback);
        move_below(rows, r + 1, j + fallback, joints_of(pieces), keep_sill_ends, depth - 1);
        return;
    }
}

// A pier between two quoins (nothing else fixed, at most three bricks wide) with joint line j in
// it set out again: each quoin two to four quarters, the pieces between one to four, every joint
// off `avoid` and j; the fewest pieces, then the quoins' lengths nearest what they were.
bool recut_pier(std::vector<Piece>& pieces, int j, const std::set<int>& avoid) {
    std::size_t a = pieces.size(), b = pieces.size();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (pieces[i].start >= j) break;
        if (pieces[i].quoin) a = i;
    }
    for (std::size_t i = pieces.size(); i-- > 0;) {
        if (pieces[i].start < j) break;
        if (pieces[i].quoin) b = i;
    }
    if (a >= pieces.size() || b >= pieces.size() || a >= b) return false;
    for (std::size_t i = a; i < b; ++i)
        if (pieces[i].start + pieces[i].length != pieces[i + 1].start ||
            (i > a && (pieces[i].fixed() || pieces[i].sill)))
            return false;
    const int s = pieces[a].start, e = pieces[b].start + pieces[b].length, w = e - s;
    if (w > 12) return false;
    auto ok = [&](int u) { return !avoid.count(u) && u != j; };
    std::vector<int> best;
    double best_cost = 1e300;
    for (int q0 = 2; q0 <= 4; ++q0)
        for (int q1 = 2; q1 <= 4; ++q1) {
            const int m = w - q0 - q1;
            if (m < 0 || !ok(s + q0) || (m > 0 && !ok(e - q1))) continue;
            // The middle: pieces of one to four quarters, the fewest.
            std::vector<int> count(static_cast<std::size_t>(m) + 1, 1 << 20),
                from(static_cast<std::size_t>(m) + 1, -1);
            count[0] = 0;
            for (int x = 1; x <= m; ++x) {
                if (x < m && !ok(s + q0 + x)) continue;
                for (int len = 1; len <= 4 && len <= x; ++len)
                    if (count[static_cast<std::size_t>(x - len)] + 1 <
                        count[static_cast<std::size_t>(x)])
                        count[static_cast<std::size_t>(x)] =
                            count[static_cast<std::size_t>(x - len)] + 1,
                        from[static_cast<std::size_t>(x)] = x - len;
            }
            if (count[static_cast<std::size_t>(m)] >= 1 << 20) continue;
            const double cost =
                count[static_cast<std::size_t>(m)] +
                0.1 * (std::abs(q0 - pieces[a].length) + std::abs(q1 - pieces[b].length));
            if (cost >= best_cost) continue;
            best_cost = cost;
            best = {q0};
            std::vector<int> middle;
            for (int x = m; x > 0; x = from[static_cast<std::size_t>(x)])
                middle.insert(middle.begin(), x - from[static_cast<std::size_t>(x)]);
            best.insert(best.end(), middle.begin(), middle.end());
            best.push_back(q1);
        }
    if (best.empty()) return false;
    std::vector<Piece> pier;
    int u = s;
    for (std::size_t i = 0; i < best.size(); ++i) {
        Piece q{u, best[i], false, false};
        q.quoin = i == 0 || i + 1 == best.size();
        q.cut = !q.quoin && best[i] != 4;
        pier.push_back(q);
        u += best[i];
    }
    pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(a),
                 pieces.begin() + static_cast<std::ptrdiff_t>(b) + 1);
    pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(a), pier.begin(), pier.end());
    return true;
}

// Re-cuts the free pieces of `pieces` round joint line j (up to three pieces either side, none
// fixed, a window-bottom header or a king closer) into pieces of one to four quarters whose joints
// keep off `avoid` (the joints of the courses above and below) and off j: each cut costs by what it
// leaves (a stretcher nothing, a header or half bat little, a bat or closer more). False when
// no cut fits.
bool recut(std::vector<Piece>& pieces, int j, const std::set<int>& avoid) {
    std::size_t k = 0;
    while (k + 1 < pieces.size() && pieces[k + 1].start != j) ++k;
    if (k + 1 >= pieces.size() || pieces[k].start + pieces[k].length != j) return false;
    // Window-bottom headers may be cut again too (a queen closer in the header row, as a mason
    // closes it against a quoin), but stay headers where they can.
    auto free = [&](std::size_t i) { return !pieces[i].fixed() && !pieces[i].king; };
    if (!free(k) || !free(k + 1)) return false;
    std::size_t a = k, b = k + 1;
    for (int n = 0; n < 2 && a > 0 && free(a - 1) &&
                    pieces[a - 1].start + pieces[a - 1].length == pieces[a].start;
         ++n)
        --a;
    for (int n = 0; n < 2 && b + 1 < pieces.size() && free(b + 1) &&
                    pieces[b].start + pieces[b].length == pieces[b + 1].start;
         ++n)
        ++b;
    const int s = pieces[a].start, e = pieces[b].start + pieces[b].length;
    const bool left_end = run_end(pieces, a, true), right_end = run_end(pieces, b, false);
    const int w = e - s;
    std::vector<char> sill(static_cast<std::size_t>(w), 0);
    for (std::size_t i = a; i <= b; ++i)
        for (int u = pieces[i].start; u < pieces[i].start + pieces[i].length; ++u)
            sill[static_cast<std::size_t>(u - s)] = pieces[i].sill;
    auto in_sill = [&](int y, int x) {
        for (int u = y; u < x; ++u)
            if (sill[static_cast<std::size_t>(u)]) return true;
        return false;
    };
    // Shortest path over the unit lines s..e: cost[x] to cut [s, x) up.
    std::vector<double> cost(static_cast<std::size_t>(w) + 1, 1e300);
    std::vector<int> from(static_cast<std::size_t>(w) + 1, -1);
    cost[0] = 0;
    for (int x = 1; x <= w; ++x) {
        if (x < w && (avoid.count(s + x) || s + x == j)) continue;
        for (int len = 1; len <= 4 && len <= x; ++len) {
            const int y = x - len;
            if (cost[static_cast<std::size_t>(y)] >= 1e300) continue;
            if (len == 1 && ((y == 0 && left_end) || (x == w && right_end))) continue;
            const bool header_row = in_sill(y, x);
            const double c = cost[static_cast<std::size_t>(y)] + (len == 4   ? (header_row ? 4 : 0)
                                                                  : len == 2 ? (header_row ? 0 : 1)
                                                                  : len == 3 ? 1.5
                                                                             : 2.5);
            if (c < cost[static_cast<std::size_t>(x)])
                cost[static_cast<std::size_t>(x)] = c, from[static_cast<std::size_t>(x)] = y;
        }
    }
    if (cost[static_cast<std::size_t>(w)] >= 1e300) return false;
    std::vector<Piece> cut;
    for (int x = w; x > 0; x = from[static_cast<std::size_t>(x)]) {
        const int y = from[static_cast<std::size_t>(x)];
        Piece p{s + y, x - y, true, false};
        p.sill = true;
        for (int u = y; u < x; ++u) p.sill &= sill[static_cast<std::size_t>(u)] != 0;
        cut.insert(cut.begin(), p);
    }
    pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(a),
                 pieces.begin() + static_cast<std::ptrdiff_t>(b) + 1);
    pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(a), cut.begin(), cut.end());
    return true;
}

}  // namespace

namespace {

// After course `cut` was cut again: each joint of the course beyond it (dir -1 above, 1 below)
// that now stands over one of `cut`'s is cut out of that course, off both its neighbours, or else
// off `cut` alone and the next course on in turn, down to `depth` courses. False when one fails.
bool push(std::vector<std::vector<Piece>>& rows, int cut, int dir, int depth) {
    const int n = static_cast<int>(rows.size()), beyond = cut + dir;
    if (beyond < 0 || beyond >= n) return true;
    auto joints = [&](int r) {
        return r >= 0 && r < n ? joints_of(rows[static_cast<std::size_t>(r)]) : std::set<int>{};
    };
    auto& next = rows[static_cast<std::size_t>(beyond)];
    for (int x : joints(cut)) {
        if (!joints(beyond).count(x)) continue;
        std::set<int> keep = joints(cut);
        for (int y : joints(beyond + dir)) keep.insert(y);
        if (recut(next, x, keep) || recut_pier(next, x, keep)) continue;
        const std::set<int> near = joints(cut);
        if (depth > 0 && (recut(next, x, near) || recut_pier(next, x, near)) &&
            push(rows, beyond, dir, depth - 1))
            continue;
        return false;
    }
    return true;
}

}  // namespace

void repair_straight_joints(BrickLayout& layout) {
    if (layout.bond.bond == Bond::stack) return;
    auto& rows = layout.rows;
    const int n = static_cast<int>(rows.size());
    auto joints = [&](int r) {
        return r >= 0 && r < n ? joints_of(rows[static_cast<std::size_t>(r)]) : std::set<int>{};
    };
    // Bottom up: each joint over one of the course below is cut out of this course, or else out
    // of the one below.
    for (int pass = 0; pass < 3; ++pass) {
        bool changed = false;
        for (int r = n - 2; r >= 0; --r) {
            const std::set<int> below = joints(r + 1);
            for (int j : joints(r)) {
                if (!below.count(j)) continue;
                std::set<int> avoid = below;
                for (int x : joints(r - 1)) avoid.insert(x);
                auto& here = rows[static_cast<std::size_t>(r)];
                if (recut(here, j, avoid) || recut_pier(here, j, avoid)) {
                    changed = true;
                    continue;
                }
                avoid = joints(r);
                for (int x : joints(r + 2)) avoid.insert(x);
                auto& under = rows[static_cast<std::size_t>(r + 1)];
                if (recut(under, j, avoid) || recut_pier(under, j, avoid)) {
                    changed = true;
                    continue;
                }
                // Neither fits between both its neighbours: cut one course off the other alone,
                // and the courses beyond it again, one by one, wherever that leaves a joint over
                // one of theirs (a pier's column flipped down to where it can end).
                for (int dir : {-1, 1}) {
                    const int cut = dir < 0 ? r : r + 1;
                    const auto saved = rows;
                    auto& row = rows[static_cast<std::size_t>(cut)];
                    // Off the other course, and off the fixed ends of the course beyond (a
                    // quoin's or a lintel's end there cannot be pushed on).
                    std::set<int> other = joints(dir < 0 ? r + 1 : r);
                    if (cut + dir >= 0 && cut + dir < n) {
                        const auto& beyond = rows[static_cast<std::size_t>(cut + dir)];
                        for (std::size_t k = 0; k + 1 < beyond.size(); ++k)
                            if (beyond[k].start + beyond[k].length == beyond[k + 1].start &&
                                (beyond[k].fixed() || beyond[k + 1].fixed()))
                                other.insert(beyond[k + 1].start);
                    }
                    if ((recut(row, j, other) || recut_pier(row, j, other)) &&
                        push(rows, cut, dir, 40)) {
                        changed = true;
                        break;
                    }
                    rows = saved;
                }
            }
        }
        if (!changed) break;
    }
}

void set_king_closers(BrickLayout& layout) {
    if (layout.bond.bond != Bond::flemish) return;
    for (int row = 0; row < layout.grid.rows(); ++row) {
        auto& pieces = layout.rows[static_cast<std::size_t>(row)];
        const double h = layout.grid.ys[static_cast<std::size_t>(row) + 1] -
                         layout.grid.ys[static_cast<std::size_t>(row)];
        if (std::abs(h - layout.gauge) > layout.tolerance) continue;  // a cut course
        // Whole quarters only: a piece the jamb cuts between quarters is a cut brick.
        auto whole = [&](int u0, int u1) {
            for (int u = u0; u < u1; ++u)
                if (layout.grid.at(row, u) != kFull) return false;
            return true;
        };
        // Against a reveal: the run's end, or a quoin (the jamb's own dressing).
        auto against = [&](std::size_t k, bool left) {
            if (run_end(pieces, k, left)) return true;
            return pieces[left ? k - 1 : k + 1].quoin;
        };
        auto plain = [&](std::size_t k) {
            return !pieces[k].fixed() && !pieces[k].sill && !pieces[k].king;
        };
        for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
            for (bool left : {true, false}) {
                // The piece at the reveal, its neighbour in the run, and the one beyond.
                const std::size_t end = left ? k : k + 1, next = left ? k + 1 : k;
                if (!plain(end) || !plain(next) || !against(end, left)) continue;
                const bool touching = pieces[k].start + pieces[k].length == pieces[k + 1].start;
                if (!touching) continue;
                // A header and its queen closer: one king closer.
                const int u0 = std::min(pieces[k].start, pieces[k + 1].start);
                if (!whole(pieces[end].start, pieces[end].start + pieces[end].length) ||
                    !whole(pieces[next].start, pieces[next].start + pieces[next].length))
                    continue;
                // The bond goes on with a stretcher beyond the closer (or one cut to an arch,
                // or a lintel's end); before a header or a bat it stays a header and a closer.
                const bool beyond_exists = left ? k + 2 < pieces.size() : k >= 1;
                const std::size_t beyond = left ? k + 2 : k - 1;
                const bool goes_on =
                    beyond_exists &&
                    (left ? pieces[k + 1].start + pieces[k + 1].length == pieces[beyond].start
                          : pieces[beyond].start + pieces[beyond].length == pieces[k].start) &&
                    (pieces[beyond].length == 4 || pieces[beyond].head ||
                     !whole(pieces[beyond].start, pieces[beyond].start + pieces[beyond].length));
                if (pieces[end].length == 2 && pieces[next].length == 1 && goes_on) {
                    Piece kc{u0, 3, true, false};
                    kc.king = true;
                    pieces[k] = kc;
                    pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(k) + 1);
                    break;
                }
                // Three quarters with a stretcher beside: the header and closer the bond's
                // sequence put there (a quarter of a stretcher and a header, taken as one).
                if (pieces[end].length == 3 && pieces[next].length == 4) pieces[end].king = true;
            }
        }
    }
}

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
            for (int d : kMoves) {
                if (d == kRemove) {
                    if (!removable(pieces, k)) continue;
                    if (3 < best_cost) best = d, best_cost = 3;
                    continue;
                }
                if (!movable(pieces, k, d, layout.centred_sills) || below.count(j + d)) continue;
                const int cost = (above.count(j + d) ? 10 : 0) + std::abs(d);
                if (cost < best_cost) best = d, best_cost = cost;
            }
            if (best == 0) {
                // Fixed here (a quoin's or a head's end): move the joint of the course below
                // instead, off this course's joints and those of the course under it.
                move_below(rows, r, j, joints_of(pieces), layout.centred_sills);
                continue;
            }
            apply(pieces, k, best);
            if (best == kRemove) --k;  // the next joint is now k's (wraps to 0 before ++k)
        }
    }
}

}  // namespace acanthus::cells::detail
