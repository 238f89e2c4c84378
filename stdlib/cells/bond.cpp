#include "bond.hpp"

#include <numeric>

namespace acanthus::cells::detail {

namespace {
int floor_mod(int a, int m) { return ((a % m) + m) % m; }
}  // namespace

std::span<const int> BondPattern::lengths(int course) const {
    course += course_shift;
    static constexpr int stretcher[] = {4}, header[] = {2}, flemish[] = {2, 4};
    switch (bond) {
        case Bond::english:
            return course % 2 == 0 ? std::span<const int>(stretcher) : std::span<const int>(header);
        case Bond::flemish:
            return flemish;
        case Bond::header:
            return header;
        default:
            return stretcher;
    }
}

int BondPattern::offset(int course) const {
    course += course_shift;
    switch (bond) {
        case Bond::running:
            return 2 * course;
        case Bond::english:
            return course % 2 == 0 ? 0 : 1;  // headers centred on stretchers
        case Bond::flemish:
            return 3 * course;  // headers centred on the stretchers below
        case Bond::header:
            return course;  // a quarter brick each course
        default:
            return 0;
    }
}

int BondPattern::period() const { return bond == Bond::flemish ? 6 : bond == Bond::header ? 2 : 4; }

void pieces_of_run(const BondPattern& bond, int course, int phase, int a, int b,
                   std::vector<Piece>& out) {
    const std::span<const int> lengths = bond.lengths(course);
    const int period = std::accumulate(lengths.begin(), lengths.end(), 0);
    const int base = bond.offset(course) + phase;
    // The boundary at or before a.
    int at = a - floor_mod(a - base, period);
    std::size_t k = 0;
    while (at + lengths[k] <= a) {
        at += lengths[k];
        k = (k + 1) % lengths.size();
    }
    const std::size_t first = out.size();
    while (at < b) {
        int len = lengths[k];
        int s = std::max(at, a), e = std::min(at + len, b);
        out.push_back({s, e - s, e - s != len, false});
        at += len;
        k = (k + 1) % lengths.size();
    }
    // One-unit remnants at the run's ends join their neighbour.
    auto fix = [&](std::size_t end, std::size_t neighbour, bool at_left) {
        Piece& p = out[end];
        Piece& q = out[neighbour];
        if (p.length != 1) return;
        int total = p.length + q.length;
        int left = at_left ? p.start : q.start;
        if (total <= 4) {
            p = {left, total, true, false};
            out.erase(out.begin() + static_cast<std::ptrdiff_t>(neighbour));
        } else if (at_left) {
            p = {left, 2, true, false};
            q = {left + 2, total - 2, true, false};
        } else {
            q = {left, total - 2, true, false};
            p = {left + total - 2, 2, true, false};
        }
    };
    if (out.size() - first >= 2) fix(first, first + 1, true);
    if (out.size() - first >= 2) fix(out.size() - 1, out.size() - 2, false);
}

std::vector<Piece> cut_out(const std::vector<Piece>& pieces, int a, int b) {
    std::vector<Piece> out;
    out.reserve(pieces.size() + 2);
    for (const Piece& p : pieces) {
        const int s = p.start, e = p.start + p.length;
        if (e <= a || s >= b) {
            out.push_back(p);
            continue;
        }
        if (s < a) out.push_back({s, a - s, true, false, p.sill});
        if (e > b) out.push_back({b, e - b, true, false, p.sill});
    }
    return out;
}

}  // namespace acanthus::cells::detail
