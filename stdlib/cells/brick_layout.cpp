#include "brick_layout.hpp"

#include <acanthus/stdlib/cells/head_joints.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "brick_grid.hpp"
#include "closers.hpp"
#include "context_data.hpp"
#include "face_jambs.hpp"
#include "feature_walk.hpp"
#include "lintel.hpp"
#include "quoin_rows.hpp"
#include "run_ends.hpp"
#include "sill_rows.hpp"

namespace acanthus::cells::detail {

namespace {

// Runs of units in a row that touch the face, cut into pieces.
void row_pieces(const CourseGrid& g, const BondPattern& bond, int phase, int row,
                std::vector<Piece>& out) {
    out.clear();
    const int n = g.units();
    for (int u = 0; u < n;) {
        if (g.at(row, u) == kOutside) {
            ++u;
            continue;
        }
        int a = u;
        while (u < n && g.at(row, u) != kOutside) ++u;
        pieces_of_run(bond, g.course(row), phase, a, u, out);
    }
    for (Piece& p : out) {
        p.full = true;
        for (int k = p.start; k < p.start + p.length; ++k)
            if (g.at(row, k) != kFull) p.full = false;
    }
}

}  // namespace

long cut_pieces(const CourseGrid& grid, const BondPattern& bond, int phase) {
    long cut = 0;
    std::vector<Piece> pieces;
    for (int r = 0; r < grid.rows(); ++r) {
        row_pieces(grid, bond, phase, r, pieces);
        for (const Piece& p : pieces) cut += p.cut;
    }
    return cut;
}

bool BrickLayout::find(Point p, int& row, int& piece) const {
    row = grid.row_at(p.y);
    int u = grid.unit_at(p.x);
    if (row < 0 || u < 0) return false;
    piece = piece_of_unit[static_cast<std::size_t>(row)][static_cast<std::size_t>(u)];
    return piece >= 0;
}

Rect BrickLayout::rect(int row, int piece) const {
    const Piece& p = rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
    return grid.cell(row, p.start, p.start + p.length);
}

Rect BrickLayout::drawn(int row, int u0, int u1) const {
    const Rect claim = grid.cell(row, u0, u1);
    const double slack = 1e-9 * std::max(1.0, std::abs(claim.x1) + std::abs(claim.y1));
    auto size = [&](double claimed, double nominal, double per_joint) {
        return std::abs(claimed - nominal) <= per_joint + slack ? nominal - mortar
                                                                : claimed - mortar;
    };
    // Head joints: the stretch of a whole unit run; bed joints: the course's height.
    const int n = u1 - u0;
    const double w = size(claim.width(), n * unit, tolerance * n / 4);
    const double h = size(claim.height(), gauge, tolerance);
    const Point c = claim.center();
    return {c.x - w / 2, c.y - h / 2, c.x + w / 2, c.y + h / 2};
}

bool BrickLayout::nominal(int row, int u0, int u1) const {
    const Rect claim = grid.cell(row, u0, u1);
    const double slack = 1e-9 * std::max(1.0, std::abs(claim.x1) + std::abs(claim.y1));
    const int n = u1 - u0;
    return std::abs(claim.width() - n * unit) <= tolerance * n / 4 + slack;
}

namespace {

// The piece as set out again from its jambs (relay_runs): (drawn, claim), or none.
const std::pair<Rect, Rect>* relaid_at(const BrickLayout& l, int row, int piece) {
    if (static_cast<std::size_t>(row) >= l.relaid.size()) return nullptr;
    const auto& r = l.relaid[static_cast<std::size_t>(row)];
    const std::size_t k = static_cast<std::size_t>(piece);
    return k < r.size() && r[k].second.width() > 0 ? &r[k] : nullptr;
}

}  // namespace

Rect BrickLayout::claim(int row, int piece) const {
    const auto* r = relaid_at(*this, row, piece);
    return r ? r->second : rect(row, piece);
}

Rect BrickLayout::drawn(int row, int piece) const {
    if (const auto* r = relaid_at(*this, row, piece)) return r->first;
    const Piece& p = rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
    Rect d = drawn(row, p.start, p.start + p.length);
    if (static_cast<std::size_t>(row) < shift.size()) {
        const double dx = shift[static_cast<std::size_t>(row)][static_cast<std::size_t>(piece)];
        d.x0 += dx, d.x1 += dx;
    }
    return d;
}

namespace {

// What `amount` adds to joints whose extra width is `extra` now: the narrowest opened first
// (the widest closed first when it is negative), to one level, so the widest ends narrowest.
std::vector<double> fill(const std::vector<double>& extra, double amount) {
    const double sign = amount < 0 ? -1 : 1;
    std::vector<double> v;
    for (double e : extra) v.push_back(sign * e);
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    double left = sign * amount, level = sorted.empty() ? 0 : sorted[0];
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        const double next = i + 1 < sorted.size() ? sorted[i + 1] : 1e300;
        const double room = (next - sorted[i]) * static_cast<double>(i + 1);
        if (left <= room) {
            level = sorted[i] + left / static_cast<double>(i + 1);
            break;
        }
        left -= room;
    }
    std::vector<double> out;
    for (double e : v) out.push_back(sign * std::max(0.0, level - e));
    return out;
}

// A mason lays the brick at a jamb or the wall's end flush with it and takes up what the
// opened (or closed) units leave in the head joints of the stretch, shared. Per row, each
// stretch of whole pieces drawn at nominal length, between a run's ends (a jamb, a reveal, the
// wall's end) or pieces cut to their claim: centred in their claims each joint lies on its unit
// line; the half joints the end bricks leave at a run's end go to the stretch's narrowest
// joints, as long as each stays within the tolerance; else the pieces stay centred.
void set_joints(BrickLayout& layout) {
    const CourseGrid& g = layout.grid;
    layout.shift.assign(layout.rows.size(), {});
    struct Stretch {
        std::size_t row, a, b;
    };
    std::vector<Stretch> stretches;
    for (std::size_t r = 0; r < layout.rows.size(); ++r) {
        const auto& pieces = layout.rows[r];
        auto& shift = layout.shift[r];
        shift.assign(pieces.size(), 0.0);
        const int row = static_cast<int>(r);
        auto movable = [&](std::size_t k) {
            const Piece& p = pieces[k];
            // A window-bottom row stays on its units, set out about the opening's middle.
            return p.full && !p.head && !(p.sill && layout.centred_sills) &&
                   layout.nominal(row, p.start, p.start + p.length);
        };
        auto abuts = [&](std::size_t k) {  // piece k - 1 ends where piece k starts
            return k > 0 && pieces[k - 1].start + pieces[k - 1].length == pieces[k].start;
        };
        // What piece k's claim leaves round its drawn brick (its two half joints' extra).
        auto spare = [&](std::size_t k) {
            const Piece& p = pieces[k];
            return g.cell(row, p.start, p.start + p.length).width() - layout.mortar -
                   layout.drawn(row, p.start, p.start + p.length).width();
        };
        for (std::size_t a = 0; a < pieces.size();) {
            if (!movable(a)) {
                ++a;
                continue;
            }
            std::size_t b = a + 1;
            while (b < pieces.size() && abuts(b) && movable(b)) ++b;
            const bool left_end = !abuts(a), right_end = !(b < pieces.size() && abuts(b));
            // The stretch's joints: after[i] - 1 is the piece before joint i (a - 1 is the cut
            // piece on the left). What the ends leave goes to the joints between whole bricks;
            // beside a cut piece (which place() may draw longer or shorter) only when there is
            // no other joint.
            std::vector<std::size_t> after;
            for (std::size_t k = a + 1; k < b; ++k) after.push_back(k);
            if (after.empty()) {
                if (!left_end) after.push_back(a);
                if (!right_end) after.push_back(b);
            }
            auto spare_at = [&](std::size_t k) { return k >= a && k < b ? spare(k) : 0.0; };
            std::vector<double> extra;  // with the pieces centred
            for (std::size_t k : after) extra.push_back((spare_at(k - 1) + spare_at(k)) / 2);
            const double ends = (left_end ? spare(a) / 2 : 0) + (right_end ? spare(b - 1) / 2 : 0);
            const double eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
            if (extra.empty() || std::abs(ends) <= eps) {
                a = b;
                continue;
            }
            const std::vector<double> more = fill(extra, ends);
            // Beside a cut piece the joint keeps room for the quarter joint place() may open it
            // by (a brick laid whole against a reveal, context.cpp).
            const double beside_cut = std::min(layout.mortar / 4, layout.tolerance);
            bool within = true;
            for (std::size_t j = 0; j < extra.size(); ++j) {
                const bool cut = after[j] == a || after[j] == b;
                within &=
                    std::abs(extra[j] + more[j]) <= layout.tolerance - (cut ? beside_cut : 0) + eps;
            }
            if (within) {
                // Left to right: the first brick flush at a run's end, each joint opened by its
                // share.
                std::vector<double> opens(b - a + 1, 0.0);  // by joint before piece k: k - a
                for (std::size_t j = 0; j < after.size(); ++j) opens[after[j] - a] = more[j];
                double dx = left_end ? -spare(a) / 2 : 0;
                for (std::size_t k = a; k < b; ++k) {
                    dx += opens[k - a];
                    shift[k] = dx;
                }
                stretches.push_back({r, a, b});
            }
            a = b;
        }
    }
    // A joint moved to within a quarter brick of one in the next course (a straight joint the
    // layout did not have), or, beside a piece cut at a jamb, nearer it and within what place()
    // may still move that piece by (half a quarter joint): its stretches stay centred.
    const double quarter = layout.unit - layout.mortar / 4;
    const double margin = std::min(layout.mortar / 4, layout.tolerance) / 2;
    auto joints = [&](std::size_t r, std::vector<std::pair<double, std::size_t>>& out,
                      bool centred) {
        out.clear();
        const auto& pieces = layout.rows[r];
        for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
            if (pieces[k].start + pieces[k].length != pieces[k + 1].start) continue;
            const int row = static_cast<int>(r);
            Rect a = layout.drawn(row, static_cast<int>(k)),
                 b = layout.drawn(row, static_cast<int>(k + 1));
            if (centred) {
                a = layout.drawn(row, pieces[k].start, pieces[k].start + pieces[k].length);
                b = layout.drawn(row, pieces[k + 1].start,
                                 pieces[k + 1].start + pieces[k + 1].length);
            }
            out.push_back({(a.x1 + b.x0) / 2, k});
        }
    };
    auto cut = [&](std::size_t row, std::size_t k) {  // a joint beside a piece cut at a jamb
        const auto& ps = layout.rows[row];
        return !ps[k].full || !ps[k + 1].full;
    };
    for (int pass = 0; pass < 8; ++pass) {
        std::set<std::pair<std::size_t, std::size_t>> undo;  // (row, piece) beside such a joint
        std::vector<std::pair<double, std::size_t>> lo, hi, lo0, hi0;
        for (std::size_t r = 0; r + 1 < layout.rows.size(); ++r) {
            joints(r, hi, false), joints(r + 1, lo, false);
            joints(r, hi0, true), joints(r + 1, lo0, true);
            std::size_t from = 0;
            for (std::size_t i = 0; i < hi.size(); ++i)
                for (std::size_t j = from; j < lo.size(); ++j) {
                    if (lo[j].first <= hi[i].first - 2 * quarter) {
                        from = j + 1;
                        continue;
                    }
                    if (lo[j].first >= hi[i].first + 2 * quarter) break;
                    const double now = std::abs(hi[i].first - lo[j].first),
                                 was = std::abs(hi0[i].first - lo0[j].first);
                    const double room =
                        cut(r, hi[i].second) || cut(r + 1, lo[j].second) ? margin : 0;
                    if (now < quarter + room && now < was - 1e-9 && was >= quarter - 1e-9) {
                        for (std::size_t d : {0, 1}) {
                            undo.insert({r, hi[i].second + d});
                            undo.insert({r + 1, lo[j].second + d});
                        }
                    }
                }
        }
        if (undo.empty()) break;
        for (const Stretch& st : stretches) {
            bool hit = false;
            for (std::size_t k = st.a; k < st.b; ++k) hit |= undo.count({st.row, k}) > 0;
            if (!hit) continue;
            for (std::size_t k = st.a; k < st.b; ++k) layout.shift[st.row][k] = 0;
        }
    }
}

// A run of bricks between two jambs (plumb sides of the face over the whole course) whose width
// is whole quarter bricks within what its head joints can take up, but which the plumb unit
// lines miss at one jamb or both: as the mason sets out a pier, laid again from its own jambs,
// the bond's pieces kept, the end pieces made whole quarters (the one at the left jamb to the
// nearer, the same way in every course beside that jamb, so the courses keep their stagger) and
// the difference shared by the joints. A run whose joints would come within a quarter brick of
// a joint in the course below or above is left as it was.
void relay_runs(const Facade& facade, int face, BrickLayout& layout) {
    const CourseGrid& g = layout.grid;
    const double q = layout.unit, m = layout.mortar, h = m / 2, tol = layout.tolerance;
    const double eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
    layout.relaid.assign(layout.rows.size(), {});
    for (std::size_t r = 0; r < layout.rows.size(); ++r)
        layout.relaid[r].assign(layout.rows[r].size(), {Rect{}, Rect{}});
    const JambIndex jambs(face_jambs(facade, face));
    // Round heads and arcs other generators claim before the bricks (soldiers, lintels and
    // their bearings, rings, walling cut to an extrados): courses there keep their units.
    std::vector<Rect> heads;
    const double reach = 2 * (4 * q);
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (edge.opening && !plumb_edge(edge) && (edge.arc || edge.part != Part::bottom)) {
            // A straight head's soldiers or lintel stand over it; a ring goes round its arc.
            const Rect b = edge.bounds;
            heads.push_back(
                {b.x0 - reach, b.y0 - reach, b.x1 + reach, edge.arc ? b.y1 + reach : b.y1 + m});
        }
    }
    auto at_jamb = [&](int r, int u, bool left, double& x) {
        return jambs.jamb_at(g, q, r, u, left, x);
    };
    const double quarter = q - m / 4;
    // Head joints of a row (centres), as laid now, each with the room it needs: a joint beside a
    // piece cut at a jamb a few millimetres off whole quarters (not laid again) may still move
    // when the piece is placed (laid whole against a reveal, context.cpp), by up to half a
    // quarter joint.
    const double margin = std::min(m / 4, tol) / 2;
    auto joints = [&](std::size_t r) {
        std::vector<std::pair<double, double>> out;
        const auto& ps = layout.rows[r];
        const int row = static_cast<int>(r);
        for (std::size_t k = 0; k + 1 < ps.size(); ++k) {
            if (ps[k].start + ps[k].length != ps[k + 1].start) continue;
            const int a = static_cast<int>(k), b = a + 1;
            // Only a piece a few millimetres off whole quarters is laid whole (nominal_at_jamb).
            auto moves = [&](std::size_t i) {
                if (ps[i].full || relaid_at(layout, row, static_cast<int>(i))) return false;
                // The piece as the face cuts it: its claim to the jamb it stops at.
                const Rect c = layout.rect(row, static_cast<int>(i));
                double lo = c.x0, hi = c.x1, x = 0;
                if (at_jamb(row, ps[i].start, true, x)) lo = std::max(lo, x);
                if (at_jamb(row, ps[i].start + ps[i].length - 1, false, x)) hi = std::min(hi, x);
                const double w = hi - lo - m;
                const double off = std::abs(w + m - std::round((w + m) / q) * q);
                return off > eps && off <= h + eps;
            };
            const bool cut = moves(k) || moves(k + 1);
            out.push_back(
                {(layout.drawn(row, a).x1 + layout.drawn(row, b).x0) / 2, cut ? margin : 0.0});
        }
        return out;
    };
    // Bottom course first, in passes until none changes: a run judged against a course not yet
    // laid again (its joints still on the unit lines) is judged again against it as relaid (a
    // pier in header bond: every other course kept a cut piece whose joint came 5.36 cm under
    // the relaid course's, a straight joint).
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t rr = layout.rows.size(); rr-- > 0;) {
            const int row = static_cast<int>(rr);
            const auto& ps = layout.rows[rr];
            for (std::size_t a = 0; a < ps.size();) {
                std::size_t b = a + 1;
                while (b < ps.size() && ps[b - 1].start + ps[b - 1].length == ps[b].start) ++b;
                const std::size_t n = b - a;
                bool bricks = n >= 2;
                for (std::size_t k = a; k < b; ++k)
                    bricks &=
                        !ps[k].fixed() && !ps[k].sill && ((k > a && k + 1 < b) ? ps[k].full : true);
                double xl = 0, xr = 0;
                const int u0 = ps[a].start, u1 = ps[b - 1].start + ps[b - 1].length - 1;
                const std::size_t a0 = a;
                a = b;
                if (!bricks || relaid_at(layout, row, static_cast<int>(a0)) ||
                    !at_jamb(row, u0, true, xl) || !at_jamb(row, u1, false, xr))
                    continue;
                bool near_head = false;
                for (const Rect& hb : heads)
                    near_head |=
                        hb.x0 < xr && hb.x1 > xl && hb.y0 < g.ys[rr + 1] && hb.y1 > g.ys[rr];
                if (near_head) continue;
                const double w = xr - xl;
                const int total = static_cast<int>(std::lround(w / q));
                // Whole: a pier already flush at both jambs is left as it is.
                const bool on_lines = std::abs(xl - g.xs[static_cast<std::size_t>(u0)]) <= eps &&
                                      std::abs(xr - g.xs[static_cast<std::size_t>(u1 + 1)]) <= eps;
                if (on_lines || total < 2 ||
                    std::abs(w - total * q) > static_cast<double>(n - 1) * tol + eps)
                    continue;
                // The left piece to the nearer whole quarter: what of its first unit lies in the
                // face.
                const double inside = (g.xs[static_cast<std::size_t>(u0) + 1] - xl) /
                                      (g.xs[static_cast<std::size_t>(u0) + 1] - g.xs[u0]);
                std::vector<int> len;
                int inner = 0;
                for (std::size_t k = a0; k < b; ++k) len.push_back(ps[k].length);
                for (std::size_t k = 1; k + 1 < n; ++k) inner += len[k];
                len[0] = len[0] - 1 + (inside >= 0.5 - 1e-9 ? 1 : 0);
                len[n - 1] = total - inner - len[0];
                if (len[0] < 1 || len[n - 1] < 1 || len[0] > 4 || len[n - 1] > 4) continue;
                const double extra = (w - total * q) / static_cast<double>(n - 1);
                std::vector<Rect> laid;
                std::vector<double> mine;
                double x = xl + h;
                const double y0 = layout.drawn(row, static_cast<int>(a0 + 1)).y0,
                             y1 = layout.drawn(row, static_cast<int>(a0 + 1)).y1;
                for (std::size_t k = 0; k < n; ++k) {
                    const double wk = len[k] * q - m;
                    laid.push_back({x, y0, x + wk, y1});
                    x += wk + m + extra;
                    if (k + 1 < n) mine.push_back(x - h - extra / 2);
                }
                // No joint brought within a quarter brick of one in the course below or above.
                bool clear = true;
                for (std::size_t nb : {rr + 1, rr - 1}) {
                    if (layout.bond.bond == Bond::stack) break;
                    if (nb >= layout.rows.size()) continue;
                    for (auto [j, room] : joints(nb))
                        for (double i : mine) clear &= std::abs(i - j) >= quarter + room - eps;
                }
                if (!clear) continue;
                for (std::size_t k = 0; k < n; ++k) {
                    // Its claim: to the middle of its joints, so that what another generator
                    // took first cuts it and not its neighbour.
                    Rect c = layout.rect(row, static_cast<int>(a0 + k));
                    c.x0 = k == 0 ? xl : laid[k].x0 - h - extra / 2;
                    c.x1 = k + 1 == n ? xr : laid[k].x1 + h + extra / 2;
                    layout.relaid[rr][a0 + k] = {laid[k], c};
                }
                changed = true;
            }
        }
    }
}

// A convex corner (a gable's apex) in a run of units none of them whole and no longer than a
// brick: one brick cut to it, not pieces either side of a joint through the corner, each too
// small to lay, that leave the corner without a brick.
void cut_at_apexes(const Facade& facade, int face, const Options& o, BrickLayout& layout) {
    const CourseGrid& g = layout.grid;
    const double inset = 0.25 * std::min(o.brick_height, o.brick_length / 4);
    for (int k : facade.faces()[static_cast<std::size_t>(face)].corners) {
        const Corner& c = facade.corners()[static_cast<std::size_t>(k)];
        if (!c.convex) continue;
        const Point in = inside_corner(c, inset);
        const int row = g.row_at(in.y), u = g.unit_at(in.x);
        if (row < 0 || u < 0) continue;
        auto& pieces = layout.rows[static_cast<std::size_t>(row)];
        std::size_t a = 0;
        while (a < pieces.size() && pieces[a].start + pieces[a].length <= u) ++a;
        if (a == pieces.size() || pieces[a].start > u) continue;
        std::size_t b = a + 1;
        while (a > 0 && pieces[a - 1].start + pieces[a - 1].length == pieces[a].start) --a;
        while (b < pieces.size() && pieces[b - 1].start + pieces[b - 1].length == pieces[b].start)
            ++b;
        const int u0 = pieces[a].start, u1 = pieces[b - 1].start + pieces[b - 1].length;
        if (b - a < 2 || u1 - u0 > 4) continue;
        bool whole = false, fixed = false;
        for (int v = u0; v < u1; ++v) whole |= g.at(row, v) == kFull;
        for (std::size_t i = a; i < b; ++i) fixed |= pieces[i].fixed() || pieces[i].sill;
        if (whole || fixed) continue;
        Piece one;
        one.start = u0, one.length = u1 - u0, one.cut = true;
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(a + 1),
                     pieces.begin() + static_cast<std::ptrdiff_t>(b));
        pieces[a] = one;
    }
}

BrickLayout lay(const Facade& facade, int face, const Options& o, bool quoins, bool lintels,
                const FramedMoves& moves, bool set_out, bool breaks, bool arched, bool centred) {
    BrickLayout layout;
    layout.moves = moves;
    layout.centred_sills = centred;
    layout.laid_as = {set_out, breaks, arched};
    layout.grid = make_brick_grid(facade, face, o, set_out, breaks, arched);
    layout.unit = (o.brick_length + o.mortar) / 4;
    layout.gauge = o.brick_height + o.mortar;
    layout.tolerance = o.joint_tolerance;
    layout.mortar = o.mortar;
    layout.quoined = quoins;
    layout.bond.bond = o.bond == Bond::ashlar ? Bond::running : o.bond;
    // English bond at a building corner: the corner brick is a stretcher in this face's stretcher
    // courses and the other face's stretcher's end in its header courses, so a face whose
    // corner is at its right end (stretchers there in odd courses, quoin_rows.hpp) takes its
    // stretcher courses odd, and the phase puts a stretcher joint at the corner.
    int corner_unit = -1;
    const int corner = layout.bond.bond == Bond::english
                           ? building_corner_end(facade, face, layout.grid, corner_unit)
                           : 0;
    if (corner == 1) layout.bond.course_shift = 1;
    long best = -1;
    for (int phase = 0; phase < layout.bond.period(); ++phase) {
        if ((corner == -1 && (phase - corner_unit) % 4 != 0) ||
            (corner == 1 && (((phase - corner_unit - 1) % 4) + 4) % 4 != 0))
            continue;
        long cut = cut_pieces(layout.grid, layout.bond, phase);
        if (best < 0 || cut < best) best = cut, layout.phase = phase;
    }
    layout.cut_pieces = best;
    set_breaks(facade, face, layout.bond, layout.phase, layout.grid);
    const int rows = layout.grid.rows();
    layout.rows.resize(static_cast<std::size_t>(rows));
    layout.piece_of_unit.resize(static_cast<std::size_t>(rows));
    layout.taken.resize(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r)
        row_pieces(layout.grid, layout.bond, layout.phase, r,
                   layout.rows[static_cast<std::size_t>(r)]);
    set_sill_rows(facade, face, layout);
    if (quoins) set_quoin_rows(facade, face, o, layout);
    if (lintels) set_lintel_rows(facade, face, o, layout);
    set_corner_rows(facade, face, layout);
    set_closers(layout);
    if (quoins) set_piers(o, layout);
    repair_straight_joints(layout);
    set_king_closers(layout);
    cut_at_apexes(facade, face, o, layout);
    for (int r = 0; r < rows; ++r) {
        auto& pieces = layout.rows[static_cast<std::size_t>(r)];
        for (Piece& p : pieces) {  // closers moved some ends
            p.full = true;
            for (int u = p.start; u < p.start + p.length; ++u)
                if (layout.grid.at(r, u) != kFull) p.full = false;
        }
        auto& index = layout.piece_of_unit[static_cast<std::size_t>(r)];
        index.assign(static_cast<std::size_t>(layout.grid.units()), -1);
        for (std::size_t k = 0; k < pieces.size(); ++k)
            for (int u = pieces[k].start; u < pieces[k].start + pieces[k].length; ++u)
                index[static_cast<std::size_t>(u)] = static_cast<int>(k);
        layout.taken[static_cast<std::size_t>(r)].assign(pieces.size(), 0);
    }
    return layout;
}

// Head joints within a run, by unit line; `beside_head`: those at a lintel's end.
std::set<int> joints_in(const std::vector<Piece>& pieces, std::set<int>* beside_head = nullptr) {
    std::set<int> out;
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
        if (pieces[k].start + pieces[k].length == pieces[k + 1].start) {
            out.insert(pieces[k + 1].start);
            if (beside_head && (pieces[k].head || pieces[k + 1].head))
                beside_head->insert(pieces[k + 1].start);
        }
    return out;
}

// Joints over joints: (upper row, unit line). With `at_heads`, those at a lintel's end (a
// lintel is one stone two courses deep: its end is no head joint of a course) are counted there
// instead.
std::vector<std::pair<int, int>> straight_in(const BrickLayout& layout, long* at_heads = nullptr) {
    std::vector<std::pair<int, int>> out;
    if (layout.bond.bond == Bond::stack) return out;
    std::set<int> below, below_heads;
    for (int r = layout.grid.rows() - 1; r >= 0; --r) {
        std::set<int> heads;
        const std::set<int> here = joints_in(layout.rows[static_cast<std::size_t>(r)], &heads);
        for (int j : here) {
            // On the same line, or across a break's odd unit narrower than a quarter brick.
            auto near = [&](int k) {
                return k >= 0 && k <= layout.grid.units() && below.count(k) &&
                       std::abs(layout.grid.xs[static_cast<std::size_t>(k)] -
                                layout.grid.xs[static_cast<std::size_t>(j)]) <
                           layout.unit - layout.mortar / 4;
            };
            if (!below.count(j) && !near(j - 1) && !near(j + 1)) continue;
            if (at_heads && (heads.count(j) || below_heads.count(j)))
                ++*at_heads;
            else
                out.push_back({r, j});
        }
        below = here, below_heads = heads;
    }
    return out;
}

// What a mason minds most, then less: straight joints in the courses, then quarter bats at a
// run's end (a moved end may leave one at a jamb or the wall's end) and joints under a lintel's
// end.
long badness(const BrickLayout& layout) {
    long quarters = 0, at_heads = 0;
    for (const auto& pieces : layout.rows)
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            if (pieces[k].length != 1) continue;
            const bool left =
                k == 0 || pieces[k - 1].start + pieces[k - 1].length != pieces[k].start;
            const bool right =
                k + 1 == pieces.size() || pieces[k].start + pieces[k].length != pieces[k + 1].start;
            quarters += left || right;
        }
    const long straight = static_cast<long>(straight_in(layout, &at_heads).size());
    return 100 * straight + 2 * quarters + at_heads;
}

// The moves one step from `moves` that could break straight joint (row, unit): a bearing, a
// window-bottom row's end or a quoin near it moved a quarter brick.
std::vector<FramedMoves> moves_near(const Facade& facade, int face, const Options& o,
                                    const BrickLayout& layout, const FramedMoves& moves, int row,
                                    int unit) {
    std::vector<FramedMoves> out;
    auto add = [&](std::map<std::pair<int, int>, int> FramedMoves::*field, int edge, int side,
                   int d, int lo, int hi) {
        FramedMoves m = moves;
        int& v = (m.*field)[{edge, side}];
        v += d;
        if (v < lo || v > hi) return;
        if (v == 0) (m.*field).erase({edge, side});
        out.push_back(std::move(m));
    };
    const CourseGrid& g = layout.grid;
    const double tiny = 1e-6 * (g.xs.back() - g.xs.front());
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (auto it = layout.lintel_units.find(e); it != layout.lintel_units.end()) {
            for (int side : {0, 1}) {
                const int end = side == 0 ? it->second.first : it->second.second;
                if (std::abs(unit - end) > 8) continue;
                for (int d : {1, -1, 2}) add(&FramedMoves::bearing, e, side, d, -1, 3);
            }
        }
        int sr = 0, u0 = 0, u1 = 0;
        if (sill_span(facade, edge, layout, sr, u0, u1) && std::abs(sr - row) <= 40) {
            for (int side : {0, 1}) {  // two units past each jamb: one end at a time
                const int end = side == 0 ? u0 - 2 : u1 + 3;
                if (layout.centred_sills || std::abs(unit - end) > 6) continue;
                for (int d : {1, -1}) add(&FramedMoves::sill_end, e, side, d, -1, 1);
            }
            // Both ends at once: the row stays as far past one jamb as past the other.
            if (layout.centred_sills &&
                (std::abs(unit - (u0 - 2)) <= 6 || std::abs(unit - (u1 + 3)) <= 6))
                for (int d : {1, -1}) {
                    FramedMoves m = moves;
                    bool within = true;
                    for (int side : {0, 1}) within &= m.move_sill_end(e, side, d);
                    if (within) out.push_back(std::move(m));
                }
        }
        if (plumb_edge(edge)) {
            const bool right = edge.inward(edge.length / 2).x > 0;
            const int u = g.unit_at(right ? edge.bounds.x0 + tiny : edge.bounds.x0 - tiny);
            if (u < 0 || std::abs(u - unit) > 5) continue;
            for (int r = row - 1; r <= row + 2; ++r) {
                if (r < 0 || r >= g.rows()) continue;
                const double mid = (g.ys[static_cast<std::size_t>(r)] + g.ys[r + 1]) / 2;
                if (mid < edge.bounds.y0 || mid > edge.bounds.y1) continue;
                const int usual = g.course(r) % 2 == 0 ? o.quoin_long : o.quoin_short;
                auto it = moves.quoin_length.find({e, r});
                const int now = it == moves.quoin_length.end() ? usual : it->second;
                for (int len : {o.quoin_short, 3, o.quoin_long}) {
                    if (len == now) continue;
                    FramedMoves m = moves;
                    if (len == usual)
                        m.quoin_length.erase({e, r});
                    else
                        m.quoin_length[{e, r}] = len;
                    out.push_back(std::move(m));
                }
            }
        }
    }
    return out;
}

}  // namespace

namespace {

// The layout on the unit lines `set_out` picks (brick_grid.hpp). The framed tree: where fixed
// ends still meet over each other, move the ones round each such joint a quarter brick, the move
// that leaves the wall best first, while one helps.
BrickLayout settled(const Facade& facade, int face, const Options& o, bool quoins, bool lintels,
                    bool set_out, bool centred, bool breaks = false, bool arched = true) {
    BrickLayout layout =
        lay(facade, face, o, quoins, lintels, {}, set_out, breaks, arched, centred);
    if (!quoins || !lintels) return layout;
    long worst = badness(layout);
    for (int step = 0; step < 6 && worst >= 100; ++step) {
        long at_heads = 0;
        const auto straight = straight_in(layout, &at_heads);
        BrickLayout best;
        long best_badness = worst;
        std::set<FramedMoves> tried;
        for (auto [row, unit] : straight)
            for (FramedMoves& m : moves_near(facade, face, o, layout, layout.moves, row, unit)) {
                if (!tried.insert(m).second) continue;
                BrickLayout next =
                    lay(facade, face, o, quoins, lintels, m, set_out, breaks, arched, centred);
                const long b = badness(next);
                if (b < best_badness) best_badness = b, best = std::move(next);
            }
        if (best_badness >= worst) break;
        worst = best_badness;
        layout = std::move(best);
    }
    return layout;
}

// Odd pieces (no whole number of quarter bricks less a joint) in runs whose width, jamb to
// jamb, is whole quarters within what their joints take up: those whole bricks and standard
// closers could have filled (the mason's rule in the tests). In a run that ends other than at a
// plumb jamb or the wall's end (an arc, a slope), the cut end pieces count and none is forced.
long unforced_odd(const Facade& facade, int face, const BrickLayout& l) {
    const CourseGrid& g = l.grid;
    std::vector<Rect> plumb;
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (plumb_edge(edge)) plumb.push_back(edge.bounds);
    }
    const double q = l.unit, m = l.mortar, eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
    // Where the face ends within unit u of row r: a plumb edge over the whole course.
    auto end_in = [&](int r, int u, double& x) {
        for (const Rect& b : plumb)
            if (b.x0 >= g.xs[static_cast<std::size_t>(u)] - eps && b.x0 <= g.xs[u + 1] + eps &&
                b.y0 <= g.ys[static_cast<std::size_t>(r)] + eps && b.y1 >= g.ys[r + 1] - eps) {
                x = b.x0;
                return true;
            }
        return false;
    };
    long out = 0;
    for (std::size_t r = 0; r < l.rows.size(); ++r) {
        const auto& ps = l.rows[r];
        const int row = static_cast<int>(r);
        for (std::size_t a = 0; a < ps.size();) {
            std::size_t b = a + 1;
            while (b < ps.size() && ps[b - 1].start + ps[b - 1].length == ps[b].start) ++b;
            const std::size_t a0 = a;
            a = b;
            double xl = l.claim(row, static_cast<int>(a0)).x0,
                   xr = l.claim(row, static_cast<int>(b - 1)).x1;
            const int u0 = ps[a0].start, u1 = ps[b - 1].start + ps[b - 1].length - 1;
            // An end at an arc or a slope: its pieces counted as they are claimed, none forced.
            const bool known = (g.at(row, u0) == kFull || end_in(row, u0, xl)) &&
                               (g.at(row, u1) == kFull || end_in(row, u1, xr));
            long odd = 0;
            for (std::size_t k = a0; k < b; ++k) {
                Rect d = l.drawn(row, static_cast<int>(k));
                if (k == a0) d.x0 = std::max(d.x0, xl + m / 2);
                if (k + 1 == b) d.x1 = std::min(d.x1, xr - m / 2);
                const double w = d.width(), n = std::round((w + m) / q);
                const bool cut = !ps[k].full && (k == a0 || k + 1 == b);
                odd +=
                    (!known && cut) || n < 1 || std::abs(w - (n * q - m)) > l.tolerance / 3 + 1e-9;
            }
            const double width = xr - xl, n = std::round(width / q);
            const bool forced =
                known && (n < 1 || std::abs(width - n * q) >
                                       static_cast<double>(b - a0 - 1) * l.tolerance + 1e-9);
            out += std::max(0L, odd - (forced ? 1 : 0));
        }
    }
    return out;
}

// What the mason minds in a face laid two ways, most first: pieces narrower than a queen
// closer, bricks shaved to fit (run_ends.hpp: within 12% of a brick or a header but not one),
// odd pieces (no whole number of quarters less a joint), in full-height courses, each as drawn:
// cut at a plumb side of the facade's outlines (a jamb, or an inset's side, cut out of the face
// later), or laid whole into the reveal's half joint.
std::tuple<long, long, long> faults(const Facade& facade, const Options& o, const BrickLayout& l,
                                    std::vector<std::pair<int, Rect>>* shaved_at = nullptr) {
    const CourseGrid& g = l.grid;
    std::vector<Rect> plumb;
    for (const Edge& e : facade.edges())
        for (const Segment& sg : e.segments)
            if (!sg.arc && std::abs(sg.a.x - sg.b.x) <= 1e-9 * std::max(1.0, std::abs(sg.a.x)) &&
                sg.a.y != sg.b.y)
                plumb.push_back(
                    {sg.a.x, std::min(sg.a.y, sg.b.y), sg.a.x, std::max(sg.a.y, sg.b.y)});
    const double m = l.mortar, h = m / 2, q = l.unit;
    const double eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
    const double stretcher = 4 * q - m, header = 2 * q - m;
    long out = 0, odd = 0, narrow = 0;
    for (std::size_t r = 0; r < l.rows.size(); ++r) {
        const int row = static_cast<int>(r);
        if (std::abs(g.ys[r + 1] - g.ys[r] - l.gauge) > 0.2 * o.brick_height) continue;
        std::vector<double> sides;  // over the whole course
        for (const Rect& b : plumb)
            if (b.y0 <= g.ys[r] + eps && b.y1 >= g.ys[r + 1] - eps) sides.push_back(b.x0);
        const auto& ps = l.rows[r];
        for (std::size_t k = 0; k < ps.size(); ++k) {
            const int i = static_cast<int>(k);
            Rect d = l.drawn(row, i);
            const Rect claim = l.claim(row, i);
            Rect c = claim;
            for (double x : sides)
                if (x > c.x0 + eps && x < c.x1 - eps)
                    (x > (claim.x0 + claim.x1) / 2 ? c.x1 : c.x0) = x;
            if (c.x0 > claim.x0 + eps || c.x1 < claim.x1 - eps) {
                d.x0 = std::max(d.x0, c.x0 + h), d.x1 = std::min(d.x1, c.x1 - h);
                const Rect whole = nominal_at_jamb(c, claim, l.drawn(row, i), o);
                if (whole.width() > 0) d = whole;
            }
            const double w = d.width();
            const double nominal = std::abs(w - stretcher) <= 0.12 * stretcher ? stretcher
                                   : std::abs(w - header) <= 0.12 * header     ? header
                                                                               : 0;
            const bool shaved = nominal > 0 && std::abs(w - nominal) > l.tolerance / 3;
            out += shaved;
            if (shaved && shaved_at) shaved_at->push_back({row, d});
            narrow += w > 0 && w < q - m - l.tolerance;
            const double n = std::round((w + m) / q);
            odd +=
                n < 1 || n > (ps[k].quoin ? 12 : 4) || std::abs(w - (n * q - m)) > l.tolerance / 3;
        }
    }
    return {narrow, out, odd};
}

// Straight joints between the full-height courses' pieces as drawn, read as the checker and the
// straight-joint map read laid cells (the layout's own reading, by units, misses a joint that a
// way's joints moved a millimetre past a quarter brick).
long drawn_straight_joints(const Options& o, const BrickLayout& l) {
    std::vector<Cell> cells;
    for (std::size_t r = 0; r < l.rows.size(); ++r) {
        if (std::abs(l.grid.ys[r + 1] - l.grid.ys[r] - l.gauge) > 0.2 * o.brick_height) continue;
        for (std::size_t k = 0; k < l.rows[r].size(); ++k) {
            Cell& c = cells.emplace_back();
            c.generator = "bricks";
            c.polygon = polygon_of(l.drawn(static_cast<int>(r), static_cast<int>(k)));
        }
    }
    return static_cast<long>(straight_joints(cells, o.brick_length, o.mortar).straight.size());
}

// A settled layout's head joints, its runs set out from their jambs, their ends fitted.
void joints_and_run_ends(const Facade& facade, int face, const Options& o, BrickLayout& layout,
                         RunEndsMemo& memo) {
    set_joints(layout);
    relay_runs(facade, face, layout);
    fit_run_ends(facade, face, o, layout, &memo);
}

// The face laid with its window-bottom rows set out about their openings' middles (`centred`)
// or two units past each jamb.
BrickLayout laid(const Facade& facade, int face, const Options& o, bool quoins, bool lintels,
                 bool centred, RunEndsMemo& memo) {
    // Perpends set out from the jambs (with or without those of arched openings, below), kept
    // unless the bond comes out worse for them. Worse is a straight joint more; a queen closer
    // more at a run's end is a standard closer.
    auto set_out = [&](bool arched) {
        BrickLayout layout =
            settled(facade, face, o, quoins, lintels, true, centred, false, arched);
        if (badness(layout) >= 100) {
            BrickLayout plain = settled(facade, face, o, quoins, lintels, false, centred);
            if (plain.grid.xs != layout.grid.xs && badness(plain) / 100 < badness(layout) / 100)
                layout = std::move(plain);
        }
        joints_and_run_ends(facade, face, o, layout, memo);
        // Bond breaks over and under the openings whose width is no whole number of quarters,
        // the piers beside them set out from their jambs: kept when they leave fewer odd pieces
        // the geometry does not force and no straight joint more.
        if (!make_brick_grid(facade, face, o, true, true, arched).breaks.empty()) {
            BrickLayout broken =
                settled(facade, face, o, quoins, lintels, true, centred, true, arched);
            if (badness(broken) / 100 <= badness(layout) / 100) {
                joints_and_run_ends(facade, face, o, broken, memo);
                if (unforced_odd(facade, face, broken) < unforced_odd(facade, face, layout))
                    layout = std::move(broken);
            }
        }
        return layout;
    };
    BrickLayout layout = set_out(true);
    // An arched opening's jamb stands as high as its springing, and the set-out weighs jambs by
    // height; but where reaching it costs the lines a flat-headed opening's jamb, the piers of
    // that opening are cut in every course it stands while the arched jamb's pier may be laid
    // from its own jambs anyway (a door 7.9 cm from the wall's end: the lines reach the door's
    // left jamb or the hatch's right one, not both). So the set-out without arched jambs is laid
    // too where its lines differ, and kept where it leaves fewer odd pieces the geometry does not
    // force and no straight joint more.
    if (make_brick_grid(facade, face, o, true, false, false).xs !=
        make_brick_grid(facade, face, o, true, false, true).xs) {
        BrickLayout flat = set_out(false);
        if (badness(flat) / 100 <= badness(layout) / 100 &&
            unforced_odd(facade, face, flat) < unforced_odd(facade, face, layout))
            layout = std::move(flat);
    }
    return layout;
}

// How far a window-bottom row stands further past one jamb of its opening than past the other
// (its sill pieces joined under the opening's middle), or 0 where there is none or it runs on
// to a reveal or the wall's end.
double sill_row_offset(const Facade& facade, const Edge& edge, const BrickLayout& layout) {
    int row = 0, u0 = 0, u1 = 0;
    if (!sill_span(facade, edge, layout, row, u0, u1)) return 0;
    const auto& ps = layout.rows[static_cast<std::size_t>(row)];
    const int mid = (u0 + u1) / 2;
    std::size_t k = 0;
    while (k < ps.size() && ps[k].start + ps[k].length <= mid) ++k;
    if (k == ps.size() || !ps[k].sill || ps[k].start > mid) return 0;
    std::size_t a = k, b = k + 1;
    while (a > 0 && ps[a - 1].sill && ps[a - 1].start + ps[a - 1].length == ps[a].start) --a;
    while (b < ps.size() && ps[b].sill && ps[b - 1].start + ps[b - 1].length == ps[b].start) ++b;
    // Run on to a reveal or the wall's end: no horn there to match.
    if (a == 0 || ps[a - 1].start + ps[a - 1].length != ps[a].start || b == ps.size() ||
        ps[b - 1].start + ps[b - 1].length != ps[b].start)
        return 0;
    const double lo = layout.claim(row, static_cast<int>(a)).x0,
                 hi = layout.claim(row, static_cast<int>(b - 1)).x1;
    const double x0 = std::min(edge.bounds.x0, edge.bounds.x1),
                 x1 = std::max(edge.bounds.x0, edge.bounds.x1);
    return std::abs((x0 - lo) - (hi - x1));
}

// A window-bottom row's ends moved a quarter brick (a centred row's both, so that it stays
// centred; another's the end with the shaved brick) where a shaved brick stands in the courses
// round the row's end: the courses beside the jamb over the row are bonded to the wall above, the
// row to its opening's middle, and where the two miss each other by less than a quarter brick no
// way at the run's end clears both. Every such row is moved out, then in, at once; a row keeps a
// move that leaves fewer shaved bricks round it and the row about its opening's middle, and the
// moves kept are laid together where the wall then has fewer shaved bricks and nothing worse
// (else one at a time: a face of a hundred windows is laid a few times, not once per sill).
BrickLayout sills_moved_for_shaved(const Facade& facade, int face, const Options& o, bool quoins,
                                   bool lintels, BrickLayout layout, RunEndsMemo& memo) {
    if (!layout.sill_rows) return layout;
    const CourseGrid& g = layout.grid;
    const auto [set_out, breaks, arched] = layout.laid_as;
    const bool centred = layout.centred_sills;
    std::vector<std::pair<int, Rect>> shaved;
    const auto now = faults(facade, o, layout, &shaved);
    if (std::get<1>(now) == 0) return layout;
    struct Sill {
        int edge = 0, row = 0;
        double x0 = 0, x1 = 0, a = 0, b = 0;  // the neighbourhood; the row's first and last unit
        std::array<bool, 2> side{};           // a shaved brick beyond its left, right end
        double offset = 0;
        int moved = 0;
    };
    // Shaved bricks within two courses of the row and eight units past either end.
    auto count_near = [&](const Sill& s, const std::vector<std::pair<int, Rect>>& list,
                          std::array<bool, 2>* side = nullptr) {
        long n = 0;
        for (const auto& [r, d] : list) {
            if (std::abs(r - s.row) > 2 || d.x1 <= s.x0 || d.x0 >= s.x1) continue;
            if (d.x1 < s.a) {
                ++n;
                if (side) (*side)[0] = true;
            } else if (d.x0 > s.b) {
                ++n;
                if (side) (*side)[1] = true;
            }
        }
        return n;
    };
    std::vector<Sill> sills;
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        Sill s;
        int u0 = 0, u1 = 0;
        if (!sill_span(facade, edge, layout, s.row, u0, u1)) continue;
        s.edge = e;
        s.x0 = g.xs[static_cast<std::size_t>(std::max(0, u0 - 8))];
        s.x1 = g.xs[static_cast<std::size_t>(std::min(g.units(), u1 + 9))];
        s.a = g.xs[static_cast<std::size_t>(std::min(g.units(), u0 + 1))];
        s.b = g.xs[static_cast<std::size_t>(u1)];
        if (count_near(s, shaved, &s.side) == 0) continue;
        s.offset = sill_row_offset(facade, edge, layout);
        sills.push_back(s);
    }
    if (sills.empty()) return layout;
    auto move = [&](FramedMoves& m, const Sill& s, int d) {
        bool within = true;
        for (int end : {0, 1})
            if (centred || s.side[static_cast<std::size_t>(end)])
                within &= m.move_sill_end(s.edge, end, d);
        return within;
    };
    auto relaid = [&](const FramedMoves& m) {
        BrickLayout next =
            lay(facade, face, o, quoins, lintels, m, set_out, breaks, arched, centred);
        joints_and_run_ends(facade, face, o, next, memo);
        return next;
    };
    const auto about_middle = [&](const Sill& s, const BrickLayout& l) {
        // (A row cut short by a run's end on one side only is off its opening's middle.)
        return sill_row_offset(facade, facade.edges()[static_cast<std::size_t>(s.edge)], l) <=
               std::max(s.offset, layout.unit / 2) + 1e-9;
    };
    FramedMoves kept = layout.moves;
    bool any = false;
    for (int d : {1, -1}) {
        FramedMoves m = kept;
        std::vector<std::size_t> tried;
        for (std::size_t i = 0; i < sills.size(); ++i) {
            FramedMoves one = m;
            if (sills[i].moved == 0 && move(one, sills[i], d))
                m = std::move(one), tried.push_back(i);
        }
        if (tried.empty()) continue;
        const BrickLayout next = relaid(m);
        std::vector<std::pair<int, Rect>> shaved_next;
        faults(facade, o, next, &shaved_next);
        for (std::size_t i : tried)
            if (count_near(sills[i], shaved_next) < count_near(sills[i], shaved) &&
                about_middle(sills[i], next)) {
                move(kept, sills[i], d);
                sills[i].moved = d;
                any = true;
            }
    }
    if (!any) return layout;
    // Nothing worse than before: no narrow, shaved or odd piece, straight joint or odd piece
    // the geometry does not force more, and fewer shaved bricks.
    const long straight = layout.bond.bond == Bond::stack ? 0 : drawn_straight_joints(o, layout);
    const long unforced = unforced_odd(facade, face, layout);
    auto better = [&](const BrickLayout& next, const std::tuple<long, long, long>& base) {
        const auto then = faults(facade, o, next);
        return badness(next) / 100 <= badness(layout) / 100 &&
               std::get<1>(then) < std::get<1>(base) && std::get<0>(then) <= std::get<0>(base) &&
               std::get<2>(then) <= std::get<2>(base) &&
               (layout.bond.bond == Bond::stack || drawn_straight_joints(o, next) <= straight) &&
               unforced_odd(facade, face, next) <= unforced;
    };
    BrickLayout all = relaid(kept);
    if (better(all, now)) return all;
    auto base = now;
    for (const Sill& s : sills) {
        if (s.moved == 0) continue;
        FramedMoves m = layout.moves;
        move(m, s, s.moved);
        BrickLayout next = relaid(m);
        if (about_middle(s, next) && better(next, base))
            base = faults(facade, o, next), layout = std::move(next);
    }
    return layout;
}

}  // namespace

BrickLayout make_brick_layout(const Facade& facade, int face, const Options& o, bool quoins,
                              bool lintels) {
    // Window-bottom rows centred on their openings, unless the courses round a row's kept ends
    // then come out worse than with every row two units past each jamb (a narrow piece, a shaved
    // brick or an odd piece more, in that order; no straight joint more): a mason shifts a
    // sill's row before he cuts the bond worse for it.
    RunEndsMemo memo;  // the ways of run ends the sills do not reach, found once
    BrickLayout layout = laid(facade, face, o, quoins, lintels, true, memo);
    if (layout.sill_rows) {
        const auto now = faults(facade, o, layout);
        // Laid again on the same unit lines, the rows two units past each jamb.
        const auto [set_out, breaks, arched] = layout.laid_as;
        BrickLayout plain =
            settled(facade, face, o, quoins, lintels, set_out, false, breaks, arched);
        joints_and_run_ends(facade, face, o, plain, memo);
        if (badness(plain) / 100 <= badness(layout) / 100 && faults(facade, o, plain) < now)
            layout = std::move(plain);
    }
    layout = sills_moved_for_shaved(facade, face, o, quoins, lintels, std::move(layout), memo);
    // Closers and cuts set back from the arrises, kept where that costs the wall no narrow
    // piece, shaved brick or odd piece more, nor a straight joint (the layout's own reading:
    // a way's pieces beside an arch or a sill row come out other than it reckons).
    BrickLayout set_back = layout;
    fit_arrises(facade, face, o, set_back);
    const auto [narrow, shaved, odd] = faults(facade, o, layout);
    const auto [narrow2, shaved2, odd2] = faults(facade, o, set_back);
    if (narrow2 <= narrow && shaved2 <= shaved && odd2 <= odd &&
        badness(set_back) / 100 <= badness(layout) / 100 &&
        (layout.bond.bond == Bond::stack ||
         drawn_straight_joints(o, set_back) <= drawn_straight_joints(o, layout)) &&
        unforced_odd(facade, face, set_back) <= unforced_odd(facade, face, layout))
        layout = std::move(set_back);
    return layout;
}

BrickLayout& brick_layout(Context& context, int face) {
    return context.data().layout<BrickLayout>("bricks:" + std::to_string(face), [&] {
        return make_brick_layout(context.facade(), face, context.options(), context.data().quoined,
                                 context.data().lintels);
    });
}

}  // namespace acanthus::cells::detail
