#include "run_ends.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "face_jambs.hpp"

namespace acanthus::cells::detail {

namespace {

bool is_relaid(const BrickLayout& l, std::size_t row, std::size_t k) {
    return row < l.relaid.size() && k < l.relaid[row].size() && l.relaid[row][k].second.width() > 0;
}

// One way to lay a zone, in its direction (from the joint before it towards the jamb).
struct Plan {
    std::vector<int> quarters;  // per piece; the cut piece's is its nominal before the cut
    int cut = -1;               // the piece cut to what is left, or none
    double cut_length = 0;
    double extra = 0;  // added to each joint between the zone's pieces
    long cost = -1;    // lower is better; -1: none found
};

}  // namespace

void fit_run_ends(const Facade& facade, int face, const Options& options, BrickLayout& layout) {
    const CourseGrid& g = layout.grid;
    if (layout.relaid.size() != layout.rows.size()) {
        layout.relaid.assign(layout.rows.size(), {});
        for (std::size_t r = 0; r < layout.rows.size(); ++r)
            layout.relaid[r].assign(layout.rows[r].size(), {Rect{}, Rect{}});
    }
    const double q = layout.unit, m = layout.mortar, h = m / 2, tol = layout.tolerance;
    const double eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
    const double stretcher = 4 * q - m, header = 2 * q - m;
    const std::vector<Jamb> jambs = face_jambs(facade, face);
    // Runs across a head or an arc (within its outline's bounds) stay as they are. Beside one,
    // what its generators claim first (a ring, a lintel's bearing, soldiers) cuts the pieces
    // laid again as it cut those of the bond: that keeps no fewer whole.
    std::vector<Rect> heads;
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (edge.opening && !plumb_edge(edge) && (edge.arc || edge.part != Part::bottom)) {
            const Rect b = edge.bounds;
            heads.push_back({b.x0, b.y0, b.x1, edge.arc ? b.y1 : b.y1 + m});
        }
    }
    auto at_jamb = [&](int r, int u, bool left, double& x) {
        return jamb_at(jambs, g, q, r, u, left, x);
    };
    // What a checker reads a piece of width w as: 0 whole (a brick, header, bat or closer, or a
    // quoin of up to `most` quarters), 1 odd, 2 shaved (within 12% of a brick or header), 3 no
    // piece to lay (narrower than a queen closer, or longer than a brick).
    auto kind = [&](double w, int most) {
        const double k = std::round((w + m) / q);
        if (k >= 1 && k <= most && std::abs(w - (k * q - m)) <= tol / 3 - 1e-6 * m) return 0;
        if (w < q - m - tol + 1e-6 * m || w > stretcher + tol / 3) return 3;
        if (std::abs(w - stretcher) <= 0.125 * stretcher || std::abs(w - header) <= 0.125 * header)
            return 2;
        return 1;
    };
    const double quarter = q - m / 4;
    const double margin = std::min(m / 4, tol) / 2;
    // Head joints of a row (centres) as laid now, each with the room it needs (as relay_runs).
    auto joints = [&](std::size_t r) {
        std::vector<std::pair<double, double>> out;
        const auto& ps = layout.rows[r];
        const int row = static_cast<int>(r);
        for (std::size_t k = 0; k + 1 < ps.size(); ++k) {
            if (ps[k].start + ps[k].length != ps[k + 1].start) continue;
            auto moves = [&](std::size_t i) {
                if (ps[i].full || is_relaid(layout, r, i)) return false;
                const Rect c = layout.rect(row, static_cast<int>(i));
                double lo = c.x0, hi = c.x1, x = 0;
                if (at_jamb(row, ps[i].start, true, x)) lo = std::max(lo, x);
                if (at_jamb(row, ps[i].start + ps[i].length - 1, false, x)) hi = std::min(hi, x);
                const double w = hi - lo - m;
                const double off = std::abs(w + m - std::round((w + m) / q) * q);
                return off > eps && off <= h + eps;
            };
            const bool cut = moves(k) || moves(k + 1);
            out.push_back({(layout.drawn(row, static_cast<int>(k)).x1 +
                            layout.drawn(row, static_cast<int>(k + 1)).x0) /
                               2,
                           cut ? margin : 0.0});
        }
        return out;
    };
    const bool stack = layout.bond.bond == Bond::stack;
    // Courses are judged bottom first against their neighbours as laid by then; a course that
    // found no way clear of the one over it may find one once that is laid again, so the rows
    // are taken again until a round lays nothing more (each run's end is laid again once).
    bool changed = false;
    for (std::size_t rr = layout.rows.size();;) {
        if (rr == 0) {
            if (!changed) break;
            changed = false, rr = layout.rows.size();
        }
        --rr;
        const int row = static_cast<int>(rr);
        const std::span<const int> bond_lengths = layout.bond.lengths(g.course(row));
        for (int side : {1, -1}) {
            for (std::size_t a = 0; a < layout.rows[rr].size();) {
                auto& ps = layout.rows[rr];
                std::size_t b = a + 1;
                while (b < ps.size() && ps[b - 1].start + ps[b - 1].length == ps[b].start) ++b;
                const std::size_t n = b - a, a0 = a;
                a = b;
                // The pieces in the zone's direction: the i-th from the jamb end.
                auto at = [&](std::size_t i) { return side > 0 ? b - 1 - i : a0 + i; };
                const std::size_t end = at(0);
                const int ue = side > 0 ? ps[end].start + ps[end].length - 1 : ps[end].start;
                double xj = 0;
                if (!at_jamb(row, ue, side < 0, xj)) continue;
                // How many pieces from the jamb end may be laid again.
                std::size_t free = 0;
                for (std::size_t i = 0; i < n && free < 3; ++i) {
                    const Piece& p = ps[at(i)];
                    if (p.sill || p.head || p.king || is_relaid(layout, rr, at(i)) ||
                        (p.quoin && i > 0) || (i > 0 && i + 1 < n && !p.full))
                        break;
                    ++free;
                }
                if (free == 0) continue;
                const int quoin = ps[end].quoin ? ps[end].length : 0;
                const double y0 = layout.drawn(row, static_cast<int>(end)).y0,
                             y1 = layout.drawn(row, static_cast<int>(end)).y1;
                std::vector<std::pair<double, double>> near;  // neighbours' joints, in s = side x
                for (std::size_t nb : {rr + 1, rr - 1})
                    if (nb < layout.rows.size())
                        for (auto [j, room] : joints(nb)) near.push_back({side * j, room});
                struct Best {
                    Plan plan;
                    std::size_t zone = 0;
                    double j0 = 0, c0 = 0;  // in s: the joint before the zone, its claims' start
                } best;
                // The run as the mason's rule reads it: each piece as laid now, cut at the
                // jambs; its width when both ends are jambs; whether that forces an odd piece
                // with `joints` head joints (none is forced without a known width).
                double xo = 0;
                const bool known =
                    at_jamb(row, side > 0 ? ps[a0].start : ps[b - 1].start + ps[b - 1].length - 1,
                            side > 0, xo);
                const double width = std::abs(xj - xo);
                auto forced = [&](std::size_t joints) {
                    const double k = std::round(width / q);
                    return !known || k < 1 ||
                           std::abs(width - k * q) > static_cast<double>(joints) * tol + 1e-9;
                };
                std::vector<int> kinds;
                long odd_run = 0;
                for (std::size_t i = 0; i < n; ++i) {
                    const int k = static_cast<int>(at(i));
                    Rect d = layout.drawn(row, k);
                    // A piece cut at a jamb: its claim to the jamb less half joints, or laid
                    // whole into the reveal's half joint (as Context::place lays it).
                    const Rect claim = layout.claim(row, k);
                    Rect r = claim;
                    const bool here = i == 0, there = i + 1 == n && known;
                    if (here) (side > 0 ? r.x1 : r.x0) = xj;
                    if (there) (side > 0 ? r.x0 : r.x1) = xo;
                    if ((here || there) && (r.x0 > claim.x0 + eps || r.x1 < claim.x1 - eps)) {
                        d.x0 = r.x0 + h, d.x1 = r.x1 - h;
                        const Rect whole = nominal_at_jamb(r, claim, layout.drawn(row, k), options);
                        if (whole.width() > 0) d = whole;
                    }
                    kinds.push_back(kind(d.width(), ps[at(i)].quoin ? 12 : 4));
                    odd_run += kinds.back() != 0;
                }
                const long unforced_now = std::max(0L, odd_run - (forced(n - 1) ? 1 : 0));
                for (std::size_t zone = 1; zone <= free; ++zone) {
                    double j0 = 0, c0 = 0;  // in s
                    if (zone == n) {        // the whole run, from its other jamb
                        if (!known) continue;
                        j0 = c0 = side * xo;
                    } else {
                        const std::size_t p = at(zone), z = at(zone - 1);
                        // A king closer keeps the stretcher beside it, as the bond laid it.
                        if (ps[p].king) continue;
                        const double jx = side > 0 ? (layout.drawn(row, static_cast<int>(p)).x1 +
                                                      layout.drawn(row, static_cast<int>(z)).x0) /
                                                         2
                                                   : (layout.drawn(row, static_cast<int>(z)).x1 +
                                                      layout.drawn(row, static_cast<int>(p)).x0) /
                                                         2;
                        const Rect cp = layout.claim(row, static_cast<int>(p));
                        j0 = side * jx;
                        c0 = side * (side > 0 ? cp.x1 : cp.x0);
                    }
                    const double lo = std::min(side * j0, xj), hi = std::max(side * j0, xj);
                    bool near_head = false;
                    for (const Rect& hb : heads)
                        near_head |=
                            hb.x0 < hi && hb.x1 > lo && hb.y0 < g.ys[rr + 1] && hb.y1 > g.ys[rr];
                    if (near_head) continue;
                    long shaved = 0, odd = 0;  // in the zone as laid now
                    for (std::size_t i = 0; i < zone; ++i)
                        shaved += kinds[i] == 2, odd += kinds[i] != 0;
                    if (odd == 0) continue;
                    const double span = side * xj - j0;
                    // Every sequence of up to zone + 1 pieces of one to four quarters (a quoin at
                    // the jamb whole, its own length where it can), none or one of them cut to
                    // what is left.
                    for (std::size_t t = 1; t <= std::min<std::size_t>(zone + 1, 4); ++t) {
                        std::vector<int> ks(t, 1);
                        for (bool more = true; more;) {
                            for (int cut = -1; cut < static_cast<int>(t); ++cut) {
                                // A quoin is whole, half a brick long at least.
                                if (quoin && (cut == 0 || ks[0] < 2)) continue;
                                double sum = 0;
                                for (std::size_t i = 0; i < t; ++i)
                                    if (static_cast<int>(i) != cut) sum += ks[i] * q;
                                Plan plan;
                                plan.quarters = ks;
                                plan.cut = cut;
                                const double rest = span - sum;
                                if (cut < 0) {
                                    if (t == 1 ? std::abs(rest) > tol / 3 - 1e-6 * m
                                               : std::abs(rest) / static_cast<double>(t - 1) >
                                                     0.9 * tol)
                                        continue;
                                    plan.extra = t > 1 ? rest / static_cast<double>(t - 1) : 0;
                                } else {
                                    plan.cut_length = rest - m;
                                    if (kind(plan.cut_length, 4) > 1) continue;
                                }
                                // Joints (piece 0 at the jamb: the joints from j0 outward).
                                bool clear = true;
                                double s = j0;
                                for (std::size_t i = t; i-- > 1;) {
                                    const double w = static_cast<int>(i) == plan.cut
                                                         ? plan.cut_length
                                                         : ks[i] * q - m;
                                    s += (i + 1 == t ? h : h + plan.extra / 2) + w + h +
                                         plan.extra / 2;
                                    if (stack) continue;
                                    for (auto [j, room] : near)
                                        clear &= std::abs(s - j) >= quarter + room +
                                                                        std::abs(plan.extra) / 2 +
                                                                        tol / 2 - eps;
                                }
                                if (!clear) continue;
                                const bool odd_cut = cut >= 0 && kind(plan.cut_length, 4) == 1;
                                long quarters = 0, off_bond = 0;
                                for (std::size_t i = 0; i < t; ++i) {
                                    if (static_cast<int>(i) == cut) continue;
                                    if (i == 0 && quoin) continue;
                                    quarters += ks[i] == 1;
                                    off_bond += std::find(bond_lengths.begin(), bond_lengths.end(),
                                                          ks[i]) == bond_lengths.end();
                                }
                                // No shaved brick left, and no more odd pieces, nor more the
                                // geometry does not force; else fewer of those.
                                const long odd_then = odd_run - odd + (odd_cut ? 1 : 0);
                                const long unforced_then =
                                    std::max(0L, odd_then - (forced(n - zone + t - 1) ? 1 : 0));
                                if (shaved > 0 ? unforced_then > unforced_now || odd_then > odd_run
                                               : unforced_then > unforced_now ||
                                                     (unforced_then == unforced_now &&
                                                      odd_then >= odd_run))
                                    continue;
                                plan.cost =
                                    10000 * unforced_then + 1000 * odd_then + 20 * (cut > 0) +
                                    10 * quarters + 5 * off_bond + 5 * (quoin && ks[0] != quoin) +
                                    std::abs(static_cast<long>(t) - static_cast<long>(zone));
                                if (best.plan.cost < 0 || plan.cost < best.plan.cost)
                                    best = {plan, zone, j0, c0};
                            }
                            // The next sequence of lengths.
                            more = false;
                            for (std::size_t i = t; i-- > 0;) {
                                if (ks[i] < 4) {
                                    ++ks[i];
                                    for (std::size_t k = i + 1; k < t; ++k) ks[k] = 1;
                                    more = true;
                                    break;
                                }
                            }
                        }
                    }
                }
                if (best.plan.cost < 0) continue;
                // Lay it: pieces from the jamb end inward, in s, then in x left to right.
                const Plan& plan = best.plan;
                const std::size_t t = plan.quarters.size();
                std::vector<std::pair<double, double>> laid(t), claims(t);
                double s = side * xj - h;
                for (std::size_t i = 0; i < t; ++i) {
                    const double w = static_cast<int>(i) == plan.cut ? plan.cut_length
                                                                     : plan.quarters[i] * q - m;
                    laid[i] = {s - w, s};
                    claims[i].second = i == 0 ? side * xj : s + h + plan.extra / 2;
                    s -= w + m + plan.extra;
                }
                for (std::size_t i = 0; i < t; ++i)
                    claims[i].first = i + 1 == t ? best.c0 : laid[i].first - h - plan.extra / 2;
                const std::size_t zone = best.zone;
                const std::size_t lo = side > 0 ? b - zone : a0, hi = lo + zone;
                const int u0 = ps[lo].start, u1 = ps[hi - 1].start + ps[hi - 1].length;
                std::vector<Piece> pieces;
                std::vector<std::pair<Rect, Rect>> rects;
                int unit = u0;
                for (std::size_t j = 0; j < t; ++j) {  // left to right
                    const std::size_t i = side > 0 ? t - 1 - j : j;
                    const double cx0 = side > 0 ? claims[i].first : -claims[i].second,
                                 cx1 = side > 0 ? claims[i].second : -claims[i].first;
                    const double dx0 = side > 0 ? laid[i].first : -laid[i].second,
                                 dx1 = side > 0 ? laid[i].second : -laid[i].first;
                    // Its units: those whose middles its claim holds (the last takes the rest).
                    int stop = unit;
                    if (j + 1 == t)
                        stop = u1;
                    else
                        while (stop < u1 && (g.xs[static_cast<std::size_t>(stop)] +
                                             g.xs[static_cast<std::size_t>(stop) + 1]) /
                                                    2 <
                                                cx1)
                            ++stop;
                    Piece p;
                    p.start = unit, p.length = stop - unit;
                    p.quoin = i == 0 && quoin;
                    p.cut = static_cast<int>(i) == plan.cut ||
                            std::find(bond_lengths.begin(), bond_lengths.end(), plan.quarters[i]) ==
                                bond_lengths.end();
                    p.full = p.length > 0;
                    for (int u = p.start; u < p.start + p.length; ++u)
                        p.full &= g.at(row, u) == kFull;
                    pieces.push_back(p);
                    rects.push_back(
                        {Rect{dx0, y0, dx1, y1}, Rect{cx0, g.ys[rr], cx1, g.ys[rr + 1]}});
                    unit = stop;
                }
                const auto l = static_cast<std::ptrdiff_t>(lo), u = static_cast<std::ptrdiff_t>(hi);
                ps.erase(ps.begin() + l, ps.begin() + u);
                ps.insert(ps.begin() + l, pieces.begin(), pieces.end());
                auto& shift = layout.shift[rr];
                shift.erase(shift.begin() + l, shift.begin() + u);
                shift.insert(shift.begin() + l, t, 0.0);
                auto& relaid = layout.relaid[rr];
                relaid.erase(relaid.begin() + l, relaid.begin() + u);
                relaid.insert(relaid.begin() + l, rects.begin(), rects.end());
                a = a0 + n - zone + t;
                changed = true;
            }
        }
        auto& index = layout.piece_of_unit[rr];
        index.assign(static_cast<std::size_t>(g.units()), -1);
        const auto& ps = layout.rows[rr];
        for (std::size_t k = 0; k < ps.size(); ++k)
            for (int u = ps[k].start; u < ps[k].start + ps[k].length; ++u)
                index[static_cast<std::size_t>(u)] = static_cast<int>(k);
        layout.taken[rr].assign(ps.size(), 0);
    }
}

}  // namespace acanthus::cells::detail
