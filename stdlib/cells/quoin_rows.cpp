#include "quoin_rows.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::cells::detail {

namespace {

bool plumb(const Edge& e, double eps) {
    return !e.arc && !e.closed && e.bounds.width() <= eps && e.bounds.height() > eps;
}

// The unit against the edge on the wall's side in `row`, or -1.
int unit_at_edge(const BrickLayout& layout, const Edge& e) {
    const double x = e.bounds.x0;
    const double tiny = 1e-6 * (layout.grid.xs.back() - layout.grid.xs.front());
    return layout.grid.unit_at(e.inward(e.length / 2).x > 0 ? x + tiny : x - tiny);
}

// Puts a quoin over units [a, b) of the row's pieces; a one-unit remnant beside it joins its
// neighbour (as bond.cpp does at a run's end), so no quarter bat is left against the quoin.
// `grid` and `row`, where given, tell a unit the jamb cuts (see below).
void put_quoin(std::vector<Piece>& pieces, int a, int b, bool grows_right, bool merge = true,
               const CourseGrid* grid = nullptr, int row = -1) {
    // A pier too narrow for two quoins: this one takes what the other leaves (at least two
    // quarters; the other gives one up when only one is left), so the pier is two quoins whose
    // joint moves with the other's length, course by course. Where the other is too short to
    // give one up and the one left is cut by the jamb, it takes that one itself: the course
    // across the pier is one quoin, not a quoin and a sliver (a 13.7 cm pier had 2.5 cm pieces
    // in every other course).
    for (Piece& p : pieces) {
        if (!p.quoin || p.start + p.length <= a || p.start >= b) continue;
        // Growing right from its jamb, this quoin meets the other's left end; else its right end.
        const int free = grows_right ? p.start - a : b - (p.start + p.length);
        if (free <= 0) return;
        if (free == 1 && p.length >= 3) {
            --p.length;
            if (grows_right) ++p.start;
        } else if (free == 1) {
            const int left = grows_right ? a : b - 1;
            if (!grid || grid->at(row, left) == kFull) return;
            Piece q = p;
            q.length += 1;
            if (grows_right) --q.start;
            std::vector<Piece> out = cut_out(pieces, q.start, q.start + q.length);
            out.push_back(q);
            std::sort(out.begin(), out.end(),
                      [](const Piece& x, const Piece& y) { return x.start < y.start; });
            pieces = std::move(out);
            return;
        }
        if (grows_right)
            b = p.start;
        else
            a = p.start + p.length;
    }
    std::vector<Piece> out = cut_out(pieces, a, b);
    Piece q{a, b - a, false, false};
    q.quoin = true;
    out.push_back(q);
    std::sort(out.begin(), out.end(),
              [](const Piece& x, const Piece& y) { return x.start < y.start; });
    for (std::size_t k = 0; merge && k < out.size(); ++k) {
        Piece& p = out[k];
        if (p.quoin || p.length != 1) continue;
        // The neighbour away from the quoin, in the same run.
        const bool right_of = k > 0 && out[k - 1].quoin;
        if (!right_of && !(k + 1 < out.size() && out[k + 1].quoin)) continue;
        const std::size_t n = right_of ? k + 1 : k - (k > 0 ? 1 : 0);
        if (n == k || n >= out.size() || out[n].quoin) continue;
        const bool touching =
            right_of ? p.start + 1 == out[n].start : out[n].start + out[n].length == p.start;
        if (!touching) continue;
        const int total = p.length + out[n].length;
        const int left = std::min(p.start, out[n].start);
        if (total <= 4) {
            p = {left, total, true, false, p.sill};
            out.erase(out.begin() + static_cast<std::ptrdiff_t>(n));
            if (n < k) --k;
        } else if (right_of) {
            p = {left, 2, true, false, p.sill};
            out[n] = {left + 2, total - 2, true, false, out[n].sill};
        } else {
            out[n] = {left, total - 2, true, false, out[n].sill};
            p = {left + total - 2, 2, true, false, p.sill};
        }
    }
    pieces = std::move(out);
}

// A pier narrow enough for two quoins (two quoins and the pieces between them, four to eight
// quarters) in one row: its pieces [k, e] from unit `start`, `n` units long.
struct Pier {
    std::size_t k = 0, e = 0;
    int start = 0, n = 0;
};

std::vector<Pier> piers_of(const std::vector<Piece>& pieces) {
    std::vector<Pier> out;
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
        if (!pieces[k].quoin) continue;
        std::size_t e = k + 1;
        while (e < pieces.size() && !pieces[e].quoin) ++e;
        if (e >= pieces.size()) continue;
        bool contiguous = true;
        for (std::size_t i = k; i < e; ++i)
            contiguous &=
                pieces[i].start + pieces[i].length == pieces[i + 1].start && !pieces[i + 1].head;
        const int start = pieces[k].start, n = pieces[e].start + pieces[e].length - start;
        // A pier found ends on its own quoin; the next pier starts past it, since two piers
        // sharing a piece would each set it out.
        if (contiguous && n >= 4 && n <= 8) {
            out.push_back({k, e, start, n});
            k = e;
        } else {
            k = e - 1;
        }
    }
    return out;
}

// Each pier is set out again as a column of courses at once: two quoins, or two quoins with a
// brick between, so that no joint in it stands within a quarter brick of one in the course above
// or below, the courses beyond the pier included (the split that always fits, four and four,
// would stand in every course); among the ways that do, the left quoin long or short by course,
// as up a jamb, and two pieces rather than three. A shortest path over the column's courses.
}  // namespace

void set_piers(const Options& o, BrickLayout& layout) {
    const CourseGrid& g = layout.grid;
    const double quarter =
        o.brick_length / 4 - 1e-9 * std::max(1.0, std::abs(g.xs.back()) + std::abs(g.xs.front()));
    const int rows = g.rows();
    std::vector<std::vector<Pier>> piers(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r)
        piers[static_cast<std::size_t>(r)] = piers_of(layout.rows[static_cast<std::size_t>(r)]);
    auto find = [&](int r, int start, int n) -> const Pier* {
        if (r < 0 || r >= rows) return nullptr;
        for (const Pier& p : piers[static_cast<std::size_t>(r)])
            if (p.start == start && p.n == n) return &p;
        return nullptr;
    };
    auto joints_of_row = [&](int r, int u0, int u1) {
        std::vector<double> out;
        if (r < 0 || r >= rows) return out;
        for (const Piece& p : layout.rows[static_cast<std::size_t>(r)])
            for (int u : {p.start, p.start + p.length})
                if (u > u0 && u < u1) out.push_back(g.xs[static_cast<std::size_t>(u)]);
        return out;
    };
    std::vector<std::vector<char>> done(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r)
        done[static_cast<std::size_t>(r)].assign(piers[static_cast<std::size_t>(r)].size(), 0);
    for (int top = 0; top < rows; ++top)
        for (std::size_t i = 0; i < piers[static_cast<std::size_t>(top)].size(); ++i) {
            if (done[static_cast<std::size_t>(top)][i]) continue;
            const int start = piers[static_cast<std::size_t>(top)][i].start;
            const int n = piers[static_cast<std::size_t>(top)][i].n;
            // The column: rows top..bottom holding the same pier.
            int bottom = top;
            while (find(bottom + 1, start, n)) ++bottom;
            for (int r = top; r <= bottom; ++r) {
                auto& ps = piers[static_cast<std::size_t>(r)];
                for (std::size_t j = 0; j < ps.size(); ++j)
                    if (ps[j].start == start && ps[j].n == n)
                        done[static_cast<std::size_t>(r)][j] = 1;
            }
            // Every way of n quarters in pieces of two to four, a quoin at each end.
            std::vector<std::vector<int>> ways;
            std::vector<int> way;
            auto split = [&](auto&& self, int left) -> void {
                if (left == 0) {
                    if (way.size() >= 2) ways.push_back(way);
                    return;
                }
                for (int l = 2; l <= std::min(4, left); ++l) {
                    way.push_back(l);
                    self(self, left - l);
                    way.pop_back();
                }
            };
            split(split, n);
            std::vector<std::vector<double>> at(ways.size());
            for (std::size_t w = 0; w < ways.size(); ++w) {
                int u = start;
                for (std::size_t j = 0; j + 1 < ways[w].size(); ++j)
                    at[w].push_back(g.xs[static_cast<std::size_t>(u += ways[w][j])]);
            }
            auto clashes = [&](const std::vector<double>& a, const std::vector<double>& b) {
                int c = 0;
                for (double x : a)
                    for (double y : b) c += std::abs(x - y) < quarter;
                return c;
            };
            const std::vector<double> above = joints_of_row(top - 1, start, start + n);
            const std::vector<double> below = joints_of_row(bottom + 1, start, start + n);
            auto own = [&](int r, std::size_t w) {
                const int want = g.course(r) % 2 == 0 ? o.quoin_long : o.quoin_short;
                double c = (ways[w].front() == want ? 0 : 0.01) +
                           0.001 * static_cast<double>(ways[w].size());
                if (r == top) c += clashes(at[w], above);
                if (r == bottom) c += clashes(at[w], below);
                return c;
            };
            const std::size_t count = static_cast<std::size_t>(bottom - top + 1), m = ways.size();
            std::vector<std::vector<double>> cost(count, std::vector<double>(m));
            std::vector<std::vector<std::size_t>> from(count, std::vector<std::size_t>(m, 0));
            for (std::size_t w = 0; w < m; ++w) cost[0][w] = own(top, w);
            for (std::size_t r = 1; r < count; ++r)
                for (std::size_t w = 0; w < m; ++w) {
                    cost[r][w] = 1e300;
                    for (std::size_t v = 0; v < m; ++v) {
                        const double c = cost[r - 1][v] + clashes(at[v], at[w]);
                        if (c < cost[r][w]) cost[r][w] = c, from[r][w] = v;
                    }
                    cost[r][w] += own(top + static_cast<int>(r), w);
                }
            std::size_t w = 0;
            for (std::size_t v = 1; v < m; ++v)
                if (cost[count - 1][v] < cost[count - 1][w]) w = v;
            for (std::size_t r = count; r-- > 0;) {
                const int row = top + static_cast<int>(r);
                auto& pieces = layout.rows[static_cast<std::size_t>(row)];
                const Pier* p = find(row, start, n);
                std::vector<Piece> pier;
                int u = start;
                for (std::size_t j = 0; j < ways[w].size(); ++j) {
                    Piece q{u, ways[w][j], false, false};
                    q.quoin = j == 0 || j + 1 == ways[w].size();
                    q.cut = !q.quoin && ways[w][j] != 4;
                    pier.push_back(q);
                    u += ways[w][j];
                }
                const std::size_t k = p->k, e = p->e;
                pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(k),
                             pieces.begin() + static_cast<std::ptrdiff_t>(e) + 1);
                pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(k), pier.begin(),
                              pier.end());
                // The row's other piers moved along with the pieces inserted.
                const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(pier.size()) -
                                             static_cast<std::ptrdiff_t>(e - k + 1);
                for (Pier& o2 : piers[static_cast<std::size_t>(row)])
                    if (o2.k > e)
                        o2.k += static_cast<std::size_t>(shift),
                            o2.e += static_cast<std::size_t>(shift);
                w = from[r][w];
            }
        }
}

void set_quoin_rows(const Facade& facade, int face, const Options& o, BrickLayout& layout) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const double eps = 1e-9 * std::max({1.0, std::abs(f.bounds.x1), std::abs(f.bounds.y1)});
    const CourseGrid& g = layout.grid;
    for (int e : f.edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (!plumb(edge, eps)) continue;
        const int u = unit_at_edge(layout, edge);
        if (u < 0) continue;
        const bool right = edge.inward(edge.length / 2).x > 0;
        for (int row = 0; row < g.rows(); ++row) {
            const double mid = (g.ys[static_cast<std::size_t>(row)] + g.ys[row + 1]) / 2;
            if (mid < edge.bounds.y0 || mid > edge.bounds.y1) continue;
            if (g.at(row, u) == kOutside) continue;
            // Long and short by course, or as the layout moved it (framed_moves.hpp).
            int len = g.course(row) % 2 == 0 ? o.quoin_long : o.quoin_short;
            if (auto it = layout.moves.quoin_length.find({e, row});
                it != layout.moves.quoin_length.end())
                len = it->second;
            int a = right ? u : u - len + 1, b = right ? u + len : u + 1;
            // Within the run.
            int lo = u, hi = u + 1;
            while (lo > a && lo > 0 && g.at(row, lo - 1) != kOutside) --lo;
            while (hi < b && hi < g.units() && g.at(row, hi) != kOutside) ++hi;
            a = lo, b = hi;
            if (b - a < 1) continue;
            put_quoin(layout.rows[static_cast<std::size_t>(row)], a, b, right, true, &g, row);
        }
    }
    set_piers(o, layout);
}

namespace {

// The building corner an outline edge is: -1 at the wall's left end, 1 at its right end, else 0.
int corner_end(const Facade& facade, const Face& f, const Edge& e, double eps) {
    if (e.opening || !plumb(e, eps)) return 0;
    auto labelled = [&](const char* l) {
        return std::find(e.labels.begin(), e.labels.end(), l) != e.labels.end();
    };
    (void)facade;
    if (std::abs(e.bounds.x0 - f.bounds.x0) <= eps && labelled("corner-left")) return -1;
    if (std::abs(e.bounds.x0 - f.bounds.x1) <= eps && labelled("corner-right")) return 1;
    return 0;
}

}  // namespace

bool has_building_corner(const Facade& facade, int face) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const double eps = 1e-9 * std::max({1.0, std::abs(f.bounds.x1), std::abs(f.bounds.y1)});
    for (int e : f.edges)
        if (corner_end(facade, f, facade.edges()[static_cast<std::size_t>(e)], eps) != 0)
            return true;
    return false;
}

int building_corner_end(const Facade& facade, int face, const CourseGrid& grid, int& unit) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const double eps = 1e-9 * std::max({1.0, std::abs(f.bounds.x1), std::abs(f.bounds.y1)});
    const double tiny = 1e-6 * (grid.xs.back() - grid.xs.front());
    int ends = 0;
    for (int e : f.edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        const int end = corner_end(facade, f, edge, eps);
        if (end == 0) continue;
        const int u = grid.unit_at(end < 0 ? edge.bounds.x0 + tiny : edge.bounds.x0 - tiny);
        if (u < 0) continue;
        ends |= end < 0 ? 1 : 2;
        unit = u;
    }
    return ends == 3 ? 2 : ends == 2 ? 1 : ends == 1 ? -1 : 0;
}

void set_corner_rows(const Facade& facade, int face, BrickLayout& layout) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const double eps = 1e-9 * std::max({1.0, std::abs(f.bounds.x1), std::abs(f.bounds.y1)});
    const CourseGrid& g = layout.grid;
    for (int e : f.edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        const int end = corner_end(facade, f, edge, eps);
        if (end == 0) continue;
        const int u = unit_at_edge(layout, edge);
        if (u < 0) continue;
        for (int row = 0; row < g.rows(); ++row) {
            const double mid = (g.ys[static_cast<std::size_t>(row)] + g.ys[row + 1]) / 2;
            if (mid < edge.bounds.y0 || mid > edge.bounds.y1 || g.at(row, u) == kOutside) continue;
            // Even courses: a stretcher at a left end, a stretcher's end at a right end.
            const bool stretcher = (g.course(row) % 2 == 0) == (end < 0);
            const int len = stretcher ? 4 : 2;
            int a = end < 0 ? u : u - len + 1, b = end < 0 ? u + len : u + 1;
            int lo = u, hi = u + 1;
            while (lo > a && lo > 0 && g.at(row, lo - 1) != kOutside) --lo;
            while (hi < b && hi < g.units() && g.at(row, hi) != kOutside) ++hi;
            if (hi - lo < len) continue;  // a pier narrower than the brick: the bond's own
            auto& pieces = layout.rows[static_cast<std::size_t>(row)];
            // English bond: the header course's quoin header is followed by a queen closer.
            put_quoin(pieces, lo, hi, end < 0, layout.bond.bond != Bond::english);
            // A half bat left beside the corner brick, a stretcher beyond it: two three-quarter
            // bats instead, so no joint stands over the corner brick's joint in the next course.
            for (std::size_t k = 0; k < pieces.size(); ++k) {
                if (!pieces[k].quoin || pieces[k].start != lo) continue;
                const std::ptrdiff_t step = end < 0 ? 1 : -1;
                const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(k) + step, m = n + step;
                if (m < 0 || m >= static_cast<std::ptrdiff_t>(pieces.size())) break;
                Piece &p = pieces[static_cast<std::size_t>(n)],
                      &q = pieces[static_cast<std::size_t>(m)];
                if (p.quoin || q.quoin || p.sill || q.sill || p.length != 2 || q.length != 4) break;
                const int left = std::min(p.start, q.start);
                if (std::max(p.start, q.start) - left != (end < 0 ? 2 : 4)) break;  // touching
                Piece& l = end < 0 ? p : q;
                Piece& r = end < 0 ? q : p;
                l = {left, 3, true, false};
                r = {left + 3, 3, true, false};
                break;
            }
        }
    }
}

int quoin_piece(const BrickLayout& layout, const Edge& edge, Point inside, int& row) {
    row = layout.grid.row_at(inside.y);
    const int u = unit_at_edge(layout, edge);
    if (row < 0 || u < 0) return -1;
    const int k = layout.piece_of_unit[static_cast<std::size_t>(row)][static_cast<std::size_t>(u)];
    if (k < 0 || !layout.rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(k)].quoin)
        return -1;
    return k;
}

}  // namespace acanthus::cells::detail
