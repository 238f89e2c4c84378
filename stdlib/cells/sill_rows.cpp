#include "sill_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace acanthus::cells::detail {

namespace {

std::set<int> joints_in(const BrickLayout& layout, int row) {
    std::set<int> out;
    if (row < 0 || row >= layout.grid.rows()) return out;
    const auto& pieces = layout.rows[static_cast<std::size_t>(row)];
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
        if (pieces[k].start + pieces[k].length == pieces[k + 1].start)
            out.insert(pieces[k + 1].start);
    return out;
}

// Headers over [a, b): joints every other unit on the parity that meets fewest joints of the
// courses below and above; the end pieces are two or three quarters.
std::vector<int> header_joints(const BrickLayout& layout, int row, int a, int b) {
    const std::set<int> below = joints_in(layout, row + 1), above = joints_in(layout, row - 1);
    int best = 0, fewest = -1;
    for (int parity = 0; parity < 2; ++parity) {
        int straight = 0;
        for (int u = a + 2; u <= b - 2; ++u)
            if (((u % 2) + 2) % 2 == parity) straight += below.count(u) + above.count(u);
        if (fewest < 0 || straight < fewest) fewest = straight, best = parity;
    }
    std::vector<int> joints{a};
    for (int u = a + 2; u <= b - 2; ++u)
        if (((u % 2) + 2) % 2 == best) joints.push_back(u);
    joints.push_back(b);
    return joints;
}

// What is left of the bond's piece that unit line `at` cuts, on its `left` side (0: none cut).
int remnant(const std::vector<Piece>& pieces, int at, bool left) {
    for (const Piece& p : pieces)
        if (p.start < at && at < p.start + p.length)
            return left ? at - p.start : p.start + p.length - at;
    return 0;
}

// The sill row's units [a, b) under an opening over units [u0, u1]: its ends on the unit lines
// one and a half to three and a half units past the jambs, the pair that stands as far past one
// jamb as past the other (a sill with one long horn is set out wrong), then one that leaves no
// quarter bat beside it (unless that costs three tenths of a unit off the middle), then one whose
// two end pieces match.
std::pair<int, int> centred_span(const Edge& sill, const BrickLayout& layout, int row, int u0,
                                 int u1) {
    const CourseGrid& g = layout.grid;
    const double w = layout.unit, x0 = std::min(sill.bounds.x0, sill.bounds.x1),
                 x1 = std::max(sill.bounds.x0, sill.bounds.x1);
    const auto& pieces = layout.rows[static_cast<std::size_t>(row)];
    // The run of units the row lies in: an end less than two units short of the run's end
    // would leave a quarter bat there; it goes on to the end (a wall's end or a reveal).
    int lo = u0, hi = u1 + 1;
    while (lo > 0 && g.at(row, lo - 1) != kOutside) --lo;
    while (hi < g.units() && g.at(row, hi) != kOutside) ++hi;
    auto ends = [&](int from, int to, int run_end) {
        std::vector<int> out;
        for (int u = from; u <= to; ++u)
            if (u == run_end || std::abs(u - run_end) >= 2) out.push_back(u);
        return out;
    };
    // A quarter bat left beside the row; one in a unit the face cuts would be narrower still.
    auto quarter_bat = [&](int at, bool left) {
        if (remnant(pieces, at, left) != 1) return 0.0;
        return g.at(row, left ? at - 1 : at) == kFull ? 0.3 * w : 10 * w;
    };
    std::pair<int, int> best{std::max(lo, u0 - 2), std::min(hi, u1 + 3)};
    double least = INFINITY;
    for (int a : ends(std::max(lo, u0 - 4), u0, lo))
        for (int b : ends(u1 + 1, std::min(hi, u1 + 5), hi)) {
            const double l = x0 - g.xs[static_cast<std::size_t>(a)],
                         r = g.xs[static_cast<std::size_t>(b)] - x1;
            // At the run's end the horn is what is there: no middle to keep.
            const bool at_end = a == lo || b == hi;
            if ((a != lo && (l < 1.5 * w - 1e-9 || l > 3.5 * w + 1e-9)) ||
                (b != hi && (r < 1.5 * w - 1e-9 || r > 3.5 * w + 1e-9)))
                continue;
            const double cost = (at_end ? 0 : std::abs(l - r)) + quarter_bat(a, true) +
                                quarter_bat(b, false) + 0.25 * w * ((b - a) % 2) +
                                0.01 * std::abs(l + r - 5 * w);
            if (cost < least - 1e-9) least = cost, best = {a, b};
        }
    return best;
}

}  // namespace

bool sill_span(const Facade& facade, const Edge& sill, const BrickLayout& layout, int& row, int& u0,
               int& u1) {
    (void)facade;
    if (!sill.opening || sill.part != Part::bottom || sill.arc) return false;
    const double inset = 0.25 * (layout.gauge - layout.mortar);
    const Point below = sill.at(sill.length / 2) + sill.inward(sill.length / 2) * inset;
    row = layout.grid.row_at(below.y);
    // A sill that falls within a course leaving less than half of it below: the window bottom
    // is the whole course under that, the strip between split bricks (a header thinner than half
    // a course is no header).
    const double y = sill.bounds.y0;
    if (row >= 0 && row + 1 < layout.grid.rows() &&
        layout.grid.ys[static_cast<std::size_t>(row)] < y - 1e-9 * std::max(1.0, std::abs(y)) &&
        layout.grid.ys[static_cast<std::size_t>(row) + 1] - y < layout.gauge / 2)
        ++row;
    const double x0 = std::min(sill.bounds.x0, sill.bounds.x1), x1 = sill.bounds.x1;
    const double tiny = 1e-6 * (x1 - x0);
    u0 = layout.grid.unit_at(x0 + tiny);
    u1 = layout.grid.unit_at(x1 - tiny);
    return row >= 0 && u0 >= 0 && u1 >= 0;
}

void set_sill_rows(const Facade& facade, int face, BrickLayout& layout) {
    // Spans per row, overlapping ones (two windows close together) merged.
    std::map<int, std::vector<std::pair<int, int>>> spans;
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        int row = 0, u0 = 0, u1 = 0;
        if (!sill_span(facade, edge, layout, row, u0, u1)) continue;
        // About a half brick past each jamb, as far past one as past the other, or a quarter
        // brick more or less there (framed_moves.hpp).
        // Otherwise (the face laid both ways, brick_layout.cpp) two units past each jamb.
        const std::pair<int, int> plain{u0 - 2, u1 + 3};
        const auto [a, b] = layout.centred_sills ? centred_span(edge, layout, row, u0, u1) : plain;
        layout.sill_rows = true;
        const FramedMoves& m = layout.moves;
        spans[row].push_back({a - m.count(m.sill_end, e, 0), b + m.count(m.sill_end, e, 1)});
    }
    const int units = layout.grid.units();
    for (auto& [row, list] : spans) {
        std::sort(list.begin(), list.end());
        std::vector<std::pair<int, int>> merged;
        for (auto s : list)
            if (!merged.empty() && s.first <= merged.back().second)
                merged.back().second = std::max(merged.back().second, s.second);
            else
                merged.push_back(s);
        auto& pieces = layout.rows[static_cast<std::size_t>(row)];
        for (auto [a, b] : merged) {
            // Within the run of units holding the sill's middle.
            const int mid = std::clamp((a + b) / 2, 0, units - 1);
            if (layout.grid.at(row, mid) == kOutside) continue;
            int lo = mid, hi = mid + 1;
            while (lo > 0 && lo > a && layout.grid.at(row, lo - 1) != kOutside) --lo;
            while (hi < units && hi < b && layout.grid.at(row, hi) != kOutside) ++hi;
            a = lo, b = hi;
            if (b - a < 2) continue;
            std::vector<int> j = header_joints(layout, row, a, b);
            // Two units past each jamb: no quarter bat beside the row, one end moved a unit.
            if (!layout.centred_sills && j.size() >= 3 && remnant(pieces, a, true) == 1)
                j[0] += j[1] - j[0] == 3 ? 1 : -1;
            if (!layout.centred_sills && j.size() >= 3 && remnant(pieces, b, false) == 1)
                j.back() += j[j.size() - 1] - j[j.size() - 2] == 3 ? -1 : 1;
            a = j.front(), b = j.back();
            std::vector<Piece> out = cut_out(pieces, a, b);
            for (std::size_t k = 0; k + 1 < j.size(); ++k)
                out.push_back({j[k], j[k + 1] - j[k], j[k + 1] - j[k] != 2, false, true});
            std::sort(out.begin(), out.end(),
                      [](const Piece& x, const Piece& y) { return x.start < y.start; });
            pieces = std::move(out);
        }
    }
}

}  // namespace acanthus::cells::detail
