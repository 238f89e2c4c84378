#include "run_ends.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "face_jambs.hpp"

namespace acanthus::cells::detail {

namespace {

bool is_relaid(const BrickLayout& l, std::size_t row, std::size_t k) {
    return row < l.relaid.size() && k < l.relaid[row].size() && l.relaid[row][k].second.width() > 0;
}

// Up to N values in place (a run end's few pieces and joints: no allocation per way tried).
template <class T, std::size_t N>
struct Few {
    std::array<T, N> v{};
    std::size_t n = 0;
    void push_back(T x) { v[n++] = x; }
    std::size_t size() const { return n; }
    T& operator[](std::size_t i) { return v[i]; }
    const T& operator[](std::size_t i) const { return v[i]; }
    const T* begin() const { return v.data(); }
    const T* end() const { return v.data() + n; }
};

// One way to lay a zone, in its direction (from the joint before it towards the jamb).
struct Plan {
    Few<int, 4> quarters;  // per piece; the cut piece's is its nominal before the cut
    int cut = -1;          // the piece cut to what is left, or none
    double cut_length = 0;
    double extra = 0;  // added to each joint between the zone's pieces
};

// The ways kept per course (the cheapest that lay distinct joints): enough for the column's
// choice (96 lays the same as 160 over the mason's sweep and the fresh facades, 64 and 48
// leave more shaved), few enough that pairs of courses stay cheap to compare.
constexpr std::size_t kMostWays = 96;
constexpr std::size_t kFewPerZone = 8;

// A run of `row` (pieces [a0, b)) whose end on `side` is at the jamb at xj.
struct End {
    std::size_t a0 = 0, b = 0;
    double xj = 0;
};

// One way to lay a run's end (zone 0: as it is), its cost (lower is better) and the head
// joints it lays, in x, in place of the course's joints strictly between lo and hi.
struct Way {
    Plan plan;
    std::size_t zone = 0;
    double c0 = 0;  // in s: the start of the zone's claims
    long cost = 0;
    Few<double, 4> joints;
    double lo = 0, hi = 0;
};

// A key's bytes: every value the ways of a run's end are found from.
template <class T>
void put(std::string& key, T v) {
    key.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

// The most ways a memo keeps (about 17 MB; the fresh facades' largest face finds 85,000): past
// that, a huge face's run ends are found afresh.
constexpr std::size_t kMemoWays = std::size_t{1} << 17;

struct RunEndsMemo::Data {
    std::unordered_map<std::string, std::vector<Way>> ways;
    std::size_t count = 0;  // ways kept, over all keys
    std::size_t hits = 0;
};
RunEndsMemo::RunEndsMemo() : data(std::make_unique<Data>()) {}
RunEndsMemo::~RunEndsMemo() = default;
std::size_t RunEndsMemo::kept() const { return data->ways.size(); }
std::size_t RunEndsMemo::hits() const { return data->hits; }

namespace {

void fit(const Facade& facade, int face, const Options& options, BrickLayout& layout,
         RunEndsMemo* memo, bool arrises, const Jamb* back = nullptr, double reveal = 0) {
    const CourseGrid& g = layout.grid;
    if (layout.relaid.size() != layout.rows.size()) {
        layout.relaid.assign(layout.rows.size(), {});
        for (std::size_t r = 0; r < layout.rows.size(); ++r)
            layout.relaid[r].assign(layout.rows[r].size(), {Rect{}, Rect{}});
    }
    const double q = layout.unit, m = layout.mortar, h = m / 2, tol = layout.tolerance;
    const double eps = 1e-9 * std::max(1.0, std::abs(g.xs.back()));
    const double stretcher = 4 * q - m, header = 2 * q - m;
    std::vector<Jamb> jambs = face_jambs(facade, face);
    if (back) jambs.push_back(*back);
    const JambIndex index(jambs);
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
        return index.jamb_at(g, q, r, u, left, x);
    };
    // A skewback's plumb side (`back`, the skewback between it and the reveal at `reveal`): the
    // courses it bounds whole, the joints under the skewback (their pieces are not laid), and the
    // courses near it whose runs end at a jamb (laid again with those joints gone).
    auto back_covers = [&](std::size_t rr) {
        return back->y0 <= g.ys[rr] + eps && back->y1 >= g.ys[rr + 1] - eps;
    };
    auto under_skewback = [&](std::size_t rr, double x) {
        return back && back_covers(rr) && x > std::min(back->x, reveal) + eps &&
               x < std::max(back->x, reveal) - eps;
    };
    auto near_x = [&](double x) {
        return !back || std::abs(x - back->x) <= 40 * q + std::abs(reveal - back->x) + eps;
    };
    auto near_back = [&](std::size_t rr) {
        const double reach_y = 2 * layout.gauge + eps;
        return g.ys[rr] >= back->y0 - reach_y && g.ys[rr + 1] <= back->y1 + reach_y;
    };
    // Laid already (a skewback set while the face is being laid): not laid again.
    auto taken = [&](std::size_t r, std::size_t k) {
        return r < layout.taken.size() && k < layout.taken[r].size() && layout.taken[r][k];
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
    // Room kept past a quarter brick between a way's joints and those of the courses over and
    // under it (`slack`, and `exf` of what each joint of the way takes up): first a twentieth
    // of a joint, so that joints a quarter brick apart take up a few millimetres; where that
    // leaves a brick shaved at a jamb, the pass again from the start with half the tolerance
    // and half of each joint's take-up, the better kept (a way with little room laid in one
    // column can block a better one in the next). Less than a twentieth of a joint left a
    // straight joint once the bricks were laid.
    double slack = tol / 2, exf = 0.5;
    // What a small piece at an arris in a way costs: only where laid for that (fit_arrises).
    const long arris = arrises ? 100 : 0;
    const double margin = std::min(m / 4, tol) / 2;
    // Head joints of a row (centres) as laid now, each with the room it needs (as relay_runs),
    // in x order; kept per row until the row is laid again (`stamp`, below: a long wall's rows
    // are read again for every run end beside them).
    std::vector<std::vector<std::pair<double, double>>> joints_of(layout.rows.size());
    std::vector<long> joints_when(layout.rows.size(), -1);
    std::vector<long> stamp(layout.rows.size(), 0);
    auto joints = [&](std::size_t r) -> const std::vector<std::pair<double, double>>& {
        if (joints_when[r] == stamp[r]) return joints_of[r];
        joints_when[r] = stamp[r];
        std::vector<std::pair<double, double>>& out = joints_of[r];
        out.clear();
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
            const double x = (layout.drawn(row, static_cast<int>(k)).x1 +
                              layout.drawn(row, static_cast<int>(k + 1)).x0) /
                             2;
            if (!under_skewback(r, x)) out.push_back({x, cut ? margin : 0.0});
        }
        return joints_of[r];
    };
    const bool stack = layout.bond.bond == Bond::stack;
    const std::size_t rows = layout.rows.size();
    // The rows and jambs a pass looks at: at a skewback's side, those near it only (a face
    // with many arches sets many skewbacks, each a pass).
    std::size_t r_lo = 0, r_hi = rows;
    if (back) {
        r_lo = rows, r_hi = 0;
        for (std::size_t rr = 0; rr < rows; ++rr)
            if (near_back(rr)) r_lo = std::min(r_lo, rr), r_hi = rr + 1;
        if (r_lo >= r_hi) return;
    }
    // How far from a jamb the joints a run's end is laid again with may lie, and a quarter
    // brick beyond: the joints of other courses farther off are not compared with them.
    const double reach = 17 * q;
    // Per row and piece: laid again by this pass (a piece is laid again once; those the runs
    // set out from their jambs laid may be laid again here).
    std::vector<std::vector<char>> here(rows);
    for (std::size_t r = 0; r < rows; ++r) here[r].assign(layout.rows[r].size(), 0);
    // When each row was last laid again; per column (side, jamb, first row), the last such
    // time over its rows and the two beside them when it was judged and nothing was laid: a
    // column nothing round has changed in since is not judged again.
    long clock = 0;
    std::map<std::tuple<int, long long, std::size_t>, long> judged;
    auto find_end = [&](std::size_t rr, int side, double at, End& e) {
        const auto& ps = layout.rows[rr];
        // (Where the side bounds the course, only its run ends there: a way from a jamb could
        // reach past the side, and the skewback would cut it.)
        if (back && (!near_back(rr) || (back_covers(rr) && std::abs(at - back->x) > eps)))
            return false;
        if (back && std::abs(at - back->x) <= eps) {
            if (!back_covers(rr)) return false;
            for (std::size_t k = 0; k < ps.size(); ++k) {
                const Rect c = layout.claim(static_cast<int>(rr), static_cast<int>(k));
                if (side > 0 ? c.x0 >= at - eps || c.x1 < at - eps
                             : c.x1 <= at + eps || c.x0 > at + eps)
                    continue;
                // Less than a unit of it outside: the skewback takes it in (its side steps to
                // the joint), and the run ends at that joint as laid.
                const Rect d = layout.drawn(static_cast<int>(rr), static_cast<int>(k));
                if ((side > 0 ? at - d.x0 : d.x1 - at) + h < q) return false;
                std::size_t a = k, b = k + 1;
                while (a > 0 && ps[a - 1].start + ps[a - 1].length == ps[a].start) --a;
                while (b < ps.size() && ps[b - 1].start + ps[b - 1].length == ps[b].start) ++b;
                e = side > 0 ? End{a, k + 1, at} : End{k, b, at};
                return true;
            }
            return false;
        }
        for (std::size_t a = 0; a < ps.size();) {
            std::size_t b = a + 1;
            while (b < ps.size() && ps[b - 1].start + ps[b - 1].length == ps[b].start) ++b;
            const std::size_t end = side > 0 ? b - 1 : a;
            const int ue = side > 0 ? ps[end].start + ps[end].length - 1 : ps[end].start;
            double xj = 0;
            if (at_jamb(static_cast<int>(rr), ue, side < 0, xj) && std::abs(xj - at) <= eps) {
                e = {a, b, xj};
                return true;
            }
            a = b;
        }
        return false;
    };
    // The ways to lay the end `e` of row rr on `side`, clear of the joints of the courses over
    // and under it that are not in `chain` (those are judged with their own ways).
    auto ways = [&](std::size_t rr, int side, const End& e, const std::vector<char>& chain,
                    bool all, bool only_now = false) {
        const int row = static_cast<int>(rr);
        const std::span<const int> bond_lengths = layout.bond.lengths(g.course(row));
        const auto& ps = layout.rows[rr];
        const std::size_t a0 = e.a0, b = e.b, n = b - a0;
        const double xj = e.xj;
        auto at = [&](std::size_t i) { return side > 0 ? b - 1 - i : a0 + i; };
        const std::size_t end = at(0);
        std::vector<std::pair<double, double>> near;  // neighbours' joints, in s = side x
        if (!only_now) {
            for (std::size_t nb : {rr + 1, rr - 1}) {
                if (nb >= layout.rows.size() || chain[nb]) continue;
                const auto& js = joints(nb);
                for (auto it =
                         std::lower_bound(js.begin(), js.end(), std::make_pair(xj - reach, -1.0));
                     it != js.end() && it->first < xj + reach; ++it)
                    if (std::abs(it->first - xj) < reach)
                        near.push_back({side * it->first, it->second});
            }
            // By place, so that a joint is compared only with those that can stand too near it.
            std::sort(near.begin(), near.end());
        }
        // The memo's key: all the ways below are found from (the run's pieces as laid, the
        // joints over and under it, the pass's room), not where the run stands in its row.
        std::string key;
        if (memo && !only_now) {
            double xo = 0;
            const bool known =
                at_jamb(row, side > 0 ? ps[a0].start : ps[b - 1].start + ps[b - 1].length - 1,
                        side > 0, xo);
            put(key, side), put(key, all), put(key, known), put(key, xo), put(key, xj);
            put(key, rr), put(key, g.ys[rr]), put(key, g.ys[rr + 1]), put(key, slack);
            put(key, exf), put(key, eps), put(key, n), put(key, bond_lengths.size());
            for (int k : bond_lengths) put(key, k);
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t k = at(i);
                const Piece& p = ps[k];
                put(key, p.start), put(key, p.length);
                put(key, static_cast<char>(p.full | p.sill << 1 | p.quoin << 2 | p.head << 3 |
                                           p.king << 4 | here[rr][k] << 5));
                for (const Rect& r : {layout.drawn(row, static_cast<int>(k)),
                                      layout.claim(row, static_cast<int>(k))})
                    put(key, r.x0), put(key, r.y0), put(key, r.x1), put(key, r.y1);
            }
            for (auto [j, room] : near) put(key, j), put(key, room);
            if (auto it = memo->data->ways.find(key); it != memo->data->ways.end()) {
                ++memo->data->hits;
                return it->second;
            }
        }
        std::vector<Way> out(1);
        // How many pieces from the jamb end may be laid again.
        std::size_t free = 0, king = n;
        for (std::size_t i = 0; i < n && free < 4; ++i) {
            const Piece& p = ps[at(i)];
            // A quoin beyond the jamb's only as the run's other end (a pier between two). A king
            // closer keeps the stretcher beside it as the bond laid it, but beside a shaved
            // piece at the jamb it is laid again with it (else the piece stayed shaved: a
            // Flemish jamb quoin 1 cm short in every other course of a window; below).
            if (p.sill || p.head || (p.king && i == 0) || here[rr][at(i)] || taken(rr, at(i)) ||
                (p.quoin && i > 0 && i + 1 < n) || (i > 0 && i + 1 < n && !p.full))
                break;
            if (p.king && king == n) king = i;
            ++free;
        }
        const int quoin = ps[end].quoin ? ps[end].length : 0;

        // The run as the mason's rule reads it: each piece as laid now, cut at the jambs; its
        // width when both ends are jambs; whether that forces an odd piece with `joints` head
        // joints (none is forced without a known width).
        double xo = 0;
        const bool known = at_jamb(
            row, side > 0 ? ps[a0].start : ps[b - 1].start + ps[b - 1].length - 1, side > 0, xo);
        const double width = std::abs(xj - xo);
        auto forced = [&](std::size_t joints) {
            const double k = std::round(width / q);
            return !known || k < 1 ||
                   std::abs(width - k * q) > static_cast<double>(joints) * tol + 1e-9;
        };
        std::vector<int> kinds;
        std::vector<double> widths;
        long odd_run = 0, shaved_run = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const int k = static_cast<int>(at(i));
            Rect d = layout.drawn(row, k);
            // A piece cut at a jamb: its claim to the jamb less half joints, or laid whole into
            // the reveal's half joint (as Context::place lays it).
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
            widths.push_back(d.width());
            odd_run += kinds.back() != 0;
            shaved_run += kinds.back() == 2;
        }
        const long unforced_now = std::max(0L, odd_run - (forced(n - 1) ? 1 : 0));
        if (shaved_run == 0) free = std::min(free, king);
        // The quoin at the run's other end is laid again only to mend a shaved brick (laid
        // from here, that end is not laid again from its own jamb).
        const int far_quoin = n > 1 && ps[at(n - 1)].quoin ? ps[at(n - 1)].length : 0;
        // A piece narrower than a header at the jamb, or at the run's other end where that is
        // a jamb too: a mason keeps closers and cuts back from an arris.
        auto small = [&](double w) { return w < header - tol ? 1L : 0L; };
        const long small_far = known && n > 1 ? small(widths[n - 1]) : 0;
        const long small_now = small(widths[0]) + small_far;
        // As it is: a shaved brick costs more than any odd piece, an odd piece more than a
        // small piece at an arris. The ways below are charged for theirs only in fit_arrises:
        // laying run ends for whole bricks, one with a small piece at an arris is laid again by
        // the cheapest way with no more shaved, odd or unforced pieces (charging the ways too
        // there left 1,200 more such pieces over the mason's sweep).
        out[0].cost =
            1000000 * shaved_run + 10000 * unforced_now + 1000 * odd_run + 100 * small_now;
        if (only_now) return out;
        auto clear_near = [&](double s, double room_extra) {
            const double most = quarter + margin + room_extra + slack;
            auto it = std::lower_bound(near.begin(), near.end(), std::make_pair(s - most, -1.0));
            for (; it != near.end() && it->first <= s + most; ++it)
                if (std::abs(s - it->first) < quarter + it->second + room_extra + slack - eps)
                    return false;
            return true;
        };
        for (std::size_t zone = 1; zone <= free; ++zone) {
            double j0 = 0, c0 = 0;  // in s
            double pe = 0;          // in s: the edge of the piece before the zone, if any
            // Four pieces from the jamb only to mend a shaved brick (more ways, more to compare).
            if (zone == 4 && shaved_run == 0 && !all) continue;
            if (zone == n) {  // the whole run, from its other jamb
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
                pe = side * (side > 0 ? layout.drawn(row, static_cast<int>(p)).x1
                                      : layout.drawn(row, static_cast<int>(p)).x0);
            }
            const double lo = std::min(side * j0, xj), hi = std::max(side * j0, xj);
            bool near_head = false;
            for (const Rect& hb : heads)
                near_head |= hb.x0 < hi && hb.x1 > lo && hb.y0 < g.ys[rr + 1] && hb.y1 > g.ys[rr];
            if (near_head) continue;
            long shaved = 0, odd = 0;  // in the zone as laid now
            for (std::size_t i = 0; i < zone; ++i) shaved += kinds[i] == 2, odd += kinds[i] != 0;
            if (odd == 0 && (small_now == 0 || arris == 0) && !all) continue;
            const double span = side * xj - j0;
            // Every sequence of up to zone + 1 pieces of one to four quarters (a quoin at the
            // jamb whole, its own length where it can), none or one of them cut to what is left.
            for (std::size_t t = 1; t <= std::min<std::size_t>(zone + 1, 4); ++t) {
                Few<int, 4> ks;
                for (std::size_t i = 0; i < t; ++i) ks.push_back(1);
                for (bool more = true; more;) {
                    int total = 0;
                    for (std::size_t i = 0; i < t; ++i) total += ks[i];
                    for (int cut = -1; cut < static_cast<int>(t); ++cut) {
                        // The quoin at the jamb is whole (a closer, a bat or a brick). A
                        // pier's far quoin may be the piece cut: where the pier is too narrow
                        // for both whole, a mason cuts one clearly rather than shave a brick.
                        if (quoin && cut == 0) continue;
                        const bool far = zone == n && far_quoin;
                        if (far && t < 2) continue;
                        const double sum =
                            (total - (cut < 0 ? 0 : ks[static_cast<std::size_t>(cut)])) * q;
                        // A cut piece from a queen closer less the tolerance to a brick.
                        if (cut >= 0 && (span - sum < q - tol || span - sum > 4 * q + tol / 3))
                            continue;
                        Way w;
                        Plan& plan = w.plan;
                        plan.quarters = ks;
                        plan.cut = cut;
                        const double rest = span - sum;
                        bool open0 = false;  // the joint before the zone takes its share too
                        if (cut < 0) {
                            if (t == 1 ? std::abs(rest) > tol / 3 - 1e-6 * m
                                       : std::abs(rest) / static_cast<double>(t - 1) > 0.9 * tol) {
                                const double e = rest / static_cast<double>(t);
                                if (zone == n || std::abs(e) > 0.9 * tol ||
                                    std::abs(j0 + h + e - pe - m) > 0.9 * tol)
                                    continue;
                                open0 = true;
                                plan.extra = e;
                            } else {
                                plan.extra = t > 1 ? rest / static_cast<double>(t - 1) : 0;
                            }
                        } else {
                            plan.cut_length = rest - m;
                            if (kind(plan.cut_length, 4) > 1) continue;
                        }
                        // Joints (piece 0 at the jamb: the joints from j0 outward).
                        bool clear = true;
                        double s = j0 + (open0 ? plan.extra : 0);
                        if (open0) {
                            const double j = (pe + j0 + h + plan.extra) / 2;
                            w.joints.push_back(side * j);
                            clear = stack || clear_near(j, exf * std::abs(plan.extra));
                        }
                        for (std::size_t i = t; clear && i-- > 1;) {
                            const double pw =
                                static_cast<int>(i) == plan.cut ? plan.cut_length : ks[i] * q - m;
                            s += (i + 1 == t ? h : h + plan.extra / 2) + pw + h + plan.extra / 2;
                            w.joints.push_back(side * s);
                            if (!stack) clear = clear_near(s, exf * std::abs(plan.extra));
                        }
                        if (!clear) continue;
                        const bool odd_cut = cut >= 0 && kind(plan.cut_length, 4) == 1;
                        long quarters = 0, off_bond = 0;
                        for (std::size_t i = 0; i < t; ++i) {
                            if (static_cast<int>(i) == cut) continue;
                            if ((i == 0 && quoin) || (i + 1 == t && far)) continue;
                            quarters += ks[i] == 1;
                            off_bond += std::find(bond_lengths.begin(), bond_lengths.end(),
                                                  ks[i]) == bond_lengths.end();
                        }
                        // No more odd pieces, nor more the geometry does not force; but a
                        // shaved brick may give way to a clear cut the geometry does not
                        // force (more joints could take the difference up, but none clears
                        // the courses over and under it: the three-storey front's segmental
                        // window, a header 0.9 cm short in every other course). Not at a
                        // quoin: there the trade left the ashlar front an odd piece more.
                        const long odd_then = odd_run - odd + (odd_cut ? 1 : 0);
                        const long unforced_then =
                            std::max(0L, odd_then - (forced(n - zone + t - 1) ? 1 : 0));
                        const bool trade = shaved > 0 && !quoin;
                        if ((unforced_then > unforced_now && !trade) || odd_then > odd_run)
                            continue;
                        // Laid again only where that is better, here or in the courses over
                        // and under it (a pier's courses are chosen together).
                        auto width = [&](std::size_t i) {
                            return static_cast<int>(i) == cut ? plan.cut_length : ks[i] * q - m;
                        };
                        const long small_then =
                            small(width(0)) +
                            (zone == n ? (t > 1 ? small(width(t - 1)) : 0) : small_far);
                        w.cost = 1000000 * (shaved_run - shaved) + 10000 * unforced_then +
                                 1000 * odd_then + arris * small_then + 20 * (cut > 0) +
                                 10 * quarters + 5 * off_bond + 5 * (quoin && ks[0] != quoin) +
                                 5 * (far && ks[t - 1] != far_quoin) +
                                 std::abs(static_cast<long>(t) - static_cast<long>(zone)) + 1;
                        w.zone = zone, w.c0 = c0, w.lo = lo, w.hi = hi;
                        if (open0) (side > 0 ? w.lo : w.hi) -= side * 0.1 * m;
                        out.push_back(std::move(w));
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
        // The cheapest of those that lay the same joints.
        std::stable_sort(out.begin() + 1, out.end(),
                         [](const Way& x, const Way& y) { return x.cost < y.cost; });
        std::vector<Way> kept;
        std::array<std::size_t, 5> per_zone{};  // kept, by how many pieces they lay again
        for (Way& w : out) {
            const std::size_t z = std::min<std::size_t>(w.zone, 4);
            // Past the most, still the cheapest few of each zone: the cheapest ways lay the
            // most pieces again, and where their joints meet the courses over and under it a
            // way of one piece may be the only one left (a closer at the jamb and a cut, the
            // round-ended front in Flemish bond, where a brick stood 7 mm short).
            if (kept.size() > kMostWays && per_zone[z] >= kFewPerZone) continue;
            bool seen = false;
            for (const Way& k : kept) {
                if (k.zone == 0 || std::abs(k.lo - w.lo) > eps || std::abs(k.hi - w.hi) > eps ||
                    k.joints.size() != w.joints.size())
                    continue;
                bool same = true;
                for (std::size_t i = 0; same && i < w.joints.size(); ++i)
                    same = std::abs(k.joints[i] - w.joints[i]) <= 0.1 * m;
                if (same) {
                    seen = true;
                    break;
                }
            }
            if (!seen) kept.push_back(std::move(w)), ++per_zone[z];
        }
        if (memo && !only_now && memo->data->count + kept.size() <= kMemoWays) {
            memo->data->count += kept.size();
            memo->data->ways.emplace(std::move(key), kept);
        }
        return kept;
    };
    // Whether ways x and y of two consecutive courses (their joints as laid now: jx, jy) leave
    // no joint within a quarter brick of one in the other course.
    using Joints = std::vector<std::pair<double, double>>;
    auto clear_of = [&](const Joints& jx, const Way& x, const Joints& jy, const Way& y) {
        if (stack) return true;
        const double ex = exf * std::abs(x.plan.extra), ey = exf * std::abs(y.plan.extra);
        auto inside = [&](const Way& w, double j) {
            return w.zone > 0 && j > w.lo + eps && j < w.hi - eps;
        };
        for (double s : x.joints) {
            for (auto [j, room] : jy)
                if (!inside(y, j) && std::abs(s - j) < quarter + room + ex + slack - eps)
                    return false;
            for (double j : y.joints)
                if (std::abs(s - j) < quarter + ex + ey + slack - eps) return false;
        }
        for (double s : y.joints)
            for (auto [j, room] : jx)
                if (!inside(x, j) && std::abs(s - j) < quarter + room + ey + slack - eps)
                    return false;
        return true;
    };
    // Lay way w at the end e of row rr: pieces from the jamb end inward, in s, then in x left
    // to right.
    auto lay = [&](std::size_t rr, int side, const End& e, const Way& w) {
        const int row = static_cast<int>(rr);
        const std::span<const int> bond_lengths = layout.bond.lengths(g.course(row));
        auto& ps = layout.rows[rr];
        const std::size_t a0 = e.a0, b = e.b;
        const std::size_t end = side > 0 ? b - 1 : a0;
        const int quoin = ps[end].quoin ? ps[end].length : 0;
        const bool far = w.zone == b - a0 && ps[side > 0 ? a0 : b - 1].quoin;
        const double y0 = layout.drawn(row, static_cast<int>(end)).y0,
                     y1 = layout.drawn(row, static_cast<int>(end)).y1;
        const Plan& plan = w.plan;
        const std::size_t t = plan.quarters.size();
        std::vector<std::pair<double, double>> laid(t), claims(t);
        double s = side * e.xj - h;
        for (std::size_t i = 0; i < t; ++i) {
            const double pw =
                static_cast<int>(i) == plan.cut ? plan.cut_length : plan.quarters[i] * q - m;
            laid[i] = {s - pw, s};
            claims[i].second = i == 0 ? side * e.xj : s + h + plan.extra / 2;
            s -= pw + m + plan.extra;
        }
        for (std::size_t i = 0; i < t; ++i)
            claims[i].first = i + 1 == t ? w.c0 : laid[i].first - h - plan.extra / 2;
        const std::size_t zone = w.zone;
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
            p.quoin = (i == 0 && quoin) || (i + 1 == t && far);
            p.cut = static_cast<int>(i) == plan.cut ||
                    std::find(bond_lengths.begin(), bond_lengths.end(), plan.quarters[i]) ==
                        bond_lengths.end();
            p.full = p.length > 0;
            for (int u = p.start; u < p.start + p.length; ++u) p.full &= g.at(row, u) == kFull;
            pieces.push_back(p);
            rects.push_back({Rect{dx0, y0, dx1, y1}, Rect{cx0, g.ys[rr], cx1, g.ys[rr + 1]}});
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
        here[rr].erase(here[rr].begin() + l, here[rr].begin() + u);
        here[rr].insert(here[rr].begin() + l, t, 1);
        if (rr < layout.taken.size() && layout.taken[rr].size() >= hi) {
            layout.taken[rr].erase(layout.taken[rr].begin() + l, layout.taken[rr].begin() + u);
            layout.taken[rr].insert(layout.taken[rr].begin() + l, t, 0);
        }
        stamp[rr] = ++clock;
    };
    // Per jamb, the courses whose runs end at it one above the other (a pier's, or a run end's
    // column) are laid again together: in the bonds whose courses are a quarter brick apart, a
    // closer in one course finds a place only where the course over or under it moves its
    // joints too, which alone would gain that course nothing. The ways of each course are
    // chosen together (the cheapest sum over the column, consecutive courses clear of each
    // other's joints), columns bottom first, left ends first (right ends first, a pier laid
    // whole from the wall's end took the window's end from a column that did better); then all
    // again until a round lays nothing more (a run's end laid again is not laid again).
    auto relay_all = [&] {
        for (bool changed = true; changed;) {
            changed = false;
            for (int side : {-1, 1}) {
                std::vector<double> xs;
                for (const Jamb& j : jambs)
                    if (j.left == (side < 0) && near_x(j.x) &&
                        std::none_of(xs.begin(), xs.end(),
                                     [&](double x) { return std::abs(x - j.x) <= eps; }))
                        xs.push_back(j.x);
                for (double x : xs) {
                    std::vector<char> chain(rows, 0);
                    for (std::size_t rr = r_lo; rr < r_hi; ++rr) {
                        End e;
                        chain[rr] = find_end(rr, side, x, e);
                    }
                    for (std::size_t top = r_hi; top-- > r_lo;) {
                        if (!chain[top]) continue;
                        std::size_t first = top;  // rows [first, top] one above the other
                        while (first > 0 && chain[first - 1]) --first;
                        long last = 0;
                        for (std::size_t r = first == 0 ? 0 : first - 1; r <= top + 1 && r < rows;
                             ++r)
                            last = std::max(last, stamp[r]);
                        const auto key = std::make_tuple(side, std::llround(x / eps), first);
                        if (auto it = judged.find(key); it != judged.end() && it->second == last) {
                            top = first;
                            if (top == 0) break;
                            continue;
                        }
                        std::vector<End> ends(top - first + 1);
                        std::vector<std::vector<Way>> way(ends.size());
                        std::vector<Joints> now(ends.size());
                        std::vector<char> shaved(ends.size(), 0);
                        for (std::size_t i = 0; i < ends.size(); ++i) {
                            find_end(first + i, side, x, ends[i]);
                            shaved[i] =
                                ways(first + i, side, ends[i], chain, false, true)[0].cost >=
                                1000000;
                            for (auto j : joints(first + i))
                                if (std::abs(j.first - x) < reach) now[i].push_back(j);
                        }
                        // Beside a course with a shaved brick, the courses over and under it (two
                        // each way) may lay their ends again though they gain nothing by it.
                        for (std::size_t i = 0; i < ends.size(); ++i) {
                            bool by = false;
                            for (std::size_t d = 0; d <= 4; ++d)
                                by |= i + d >= 2 && i + d - 2 < ends.size() && shaved[i + d - 2];
                            way[i] = ways(first + i, side, ends[i], chain, by);
                        }
                        // The cheapest ways, bottom course first (rows ascend downwards).
                        std::vector<std::vector<long>> total(ends.size());
                        std::vector<std::vector<std::size_t>> from(ends.size());
                        for (std::size_t i = ends.size(); i-- > 0;) {
                            total[i].assign(way[i].size(), -1);
                            from[i].assign(way[i].size(), 0);
                            for (std::size_t k = 0; k < way[i].size(); ++k) {
                                if (i + 1 == ends.size()) {
                                    total[i][k] = way[i][k].cost;
                                    continue;
                                }
                                for (std::size_t l = 0; l < way[i + 1].size(); ++l) {
                                    if (total[i + 1][l] < 0) continue;
                                    const long c = total[i + 1][l] + way[i][k].cost;
                                    if ((total[i][k] < 0 || c < total[i][k]) &&
                                        clear_of(now[i], way[i][k], now[i + 1], way[i + 1][l]))
                                        total[i][k] = c, from[i][k] = l;
                                }
                            }
                        }
                        std::size_t k = 0;
                        for (std::size_t l = 0; l < way[0].size(); ++l)
                            if (total[0][l] >= 0 && (total[0][k] < 0 || total[0][l] < total[0][k]))
                                k = l;
                        bool laid = false;
                        for (std::size_t i = 0; i < ends.size(); ++i) {
                            if (way[i][k].zone > 0)
                                lay(first + i, side, ends[i], way[i][k]), laid = true;
                            if (i + 1 < ends.size()) k = from[i][k];
                        }
                        if (!laid) judged[key] = last;
                        changed |= laid;
                        top = first;
                        if (top == 0) break;
                    }
                }
            }
        }
    };
    // What the mason's rule reads at every run end at a jamb, as laid now (lower is better).
    auto score = [&] {
        long total = 0;
        const std::vector<char> none(rows, 0);
        for (const Jamb& j : jambs) {
            if (!near_x(j.x)) continue;
            const int side = j.left ? -1 : 1;
            for (std::size_t rr = r_lo; rr < r_hi; ++rr)
                if (End e; find_end(rr, side, j.x, e))
                    total += ways(rr, side, e, none, false, true)[0].cost;
        }
        return total;
    };
    auto finish = [&] {
        for (std::size_t rr = r_lo; rr < r_hi; ++rr) {
            auto& index = layout.piece_of_unit[rr];
            index.assign(static_cast<std::size_t>(g.units()), -1);
            const auto& ps = layout.rows[rr];
            for (std::size_t k = 0; k < ps.size(); ++k)
                for (int u = ps[k].start; u < ps[k].start + ps[k].length; ++u)
                    index[static_cast<std::size_t>(u)] = static_cast<int>(k);
            if (!back) layout.taken[rr].assign(ps.size(), 0);  // (lay() keeps them in step)
        }
    };
    // The rows a pass may lay again, kept and put back (at a skewback only those near it: a
    // face with many arches sets many skewbacks).
    struct Rows {
        std::vector<std::vector<Piece>> pieces;
        std::vector<std::vector<double>> shift;
        std::vector<std::vector<std::pair<Rect, Rect>>> relaid;
        std::vector<std::vector<char>> taken;
    };
    auto keep = [&] {
        Rows k;
        for (std::size_t rr = r_lo; rr < r_hi; ++rr) {
            k.pieces.push_back(layout.rows[rr]);
            k.shift.push_back(layout.shift[rr]);
            k.relaid.push_back(layout.relaid[rr]);
            k.taken.push_back(rr < layout.taken.size() ? layout.taken[rr] : std::vector<char>{});
        }
        return k;
    };
    auto put_back = [&](Rows&& k) {
        for (std::size_t rr = r_lo; rr < r_hi; ++rr) {
            const std::size_t i = rr - r_lo;
            layout.rows[rr] = std::move(k.pieces[i]);
            layout.shift[rr] = std::move(k.shift[i]);
            layout.relaid[rr] = std::move(k.relaid[i]);
            if (rr < layout.taken.size()) layout.taken[rr] = std::move(k.taken[i]);
        }
    };
    slack = m / 20, exf = 0;
    if (arrises) {
        relay_all();
        return finish();
    }
    Rows start = keep();
    relay_all();
    const long tight = score();
    if (tight < 1000000) return finish();  // no shaved brick left at a jamb
    Rows kept = keep();
    put_back(std::move(start));
    std::fill(joints_when.begin(), joints_when.end(), -1L);
    for (std::size_t r = r_lo; r < r_hi; ++r) here[r].assign(layout.rows[r].size(), 0);
    std::fill(stamp.begin(), stamp.end(), 0L);
    clock = 0;
    judged.clear();
    slack = tol / 2, exf = 0.5;
    relay_all();
    if (score() > tight) put_back(std::move(kept));
    finish();
}

}  // namespace

void fit_run_ends(const Facade& facade, int face, const Options& options, BrickLayout& layout,
                  RunEndsMemo* memo) {
    fit(facade, face, options, layout, memo, false);
}

void fit_arrises(const Facade& facade, int face, const Options& options, BrickLayout& layout) {
    fit(facade, face, options, layout, nullptr, true);
}

void fit_run_ends_at(const Facade& facade, int face, const Options& options, BrickLayout& layout,
                     const Jamb& back, double reveal) {
    fit(facade, face, options, layout, nullptr, false, &back, reveal);
}

}  // namespace acanthus::cells::detail
