#include "sill_rows.hpp"

#include <algorithm>
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
        // Two units past each jamb, or a quarter brick more or less there (framed_moves.hpp).
        const FramedMoves& m = layout.moves;
        spans[row].push_back(
            {u0 - 2 - m.count(m.sill_end, e, 0), u1 + 3 + m.count(m.sill_end, e, 1)});
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
            // What is left of the bond's pieces either side: no quarter bat beside the row.
            auto remnant = [&](int at, bool left) {
                for (const Piece& p : pieces)
                    if (p.start < at && at < p.start + p.length)
                        return left ? at - p.start : p.start + p.length - at;
                return 0;
            };
            if (j.size() >= 3 && remnant(a, true) == 1) {
                int end = j[1] - j[0];  // the first header: 2 or 3
                if (end == 3)
                    j[0] += 1;  // shorter, the remnant two
                else
                    j[0] -= 1;  // longer, the remnant taken in
            }
            if (j.size() >= 3 && remnant(b, false) == 1) {
                int end = j[j.size() - 1] - j[j.size() - 2];
                if (end == 3)
                    j.back() -= 1;
                else
                    j.back() += 1;
            }
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
