#include "ashlar_rules.hpp"

#include <acanthus/progress.hpp>
#include <algorithm>
#include <functional>
#include <tuple>
#include <utility>

namespace acanthus::cells::detail {

AshlarRules::AshlarRules(const CourseGrid& g, int max_w, int max_h, int max_seam, int first_id,
                         double square)
    : g_(g),
      rows_(g.rows()),
      units_(g.units()),
      max_w_(std::max(1, max_w)),
      max_h_(std::max(1, max_h)),
      max_seam_(max_seam),
      first_id_(first_id),
      owner_(static_cast<std::size_t>(g.rows()) * static_cast<std::size_t>(g.units()), kBlocked),
      square_(square),
      jamb_(owner_.size(), 0),
      shaped_(owner_.size(), 0),
      small_held_(owner_.size(), 0),
      share_(owner_.size(), 1.0) {}

void AshlarRules::lay(Random& random) {
    for (int r = 0; r < rows_; ++r) {
        for (int u = 0; u < units_; ++u)
            if (get(r, u) == kEmpty) lay_at(r, u, random);
        report_progress("ashlar rows", r + 1, rows_);
    }
    // A unit square on a row taller than its column stands on end where nothing wider fitted:
    // it joins the narrower one-row stone beside it (a joint less cannot make a four-way one),
    // or, with none, the row it shares of a taller stone beside it, split off for it, where
    // that makes no more four-way joints than the face may have (the rest of that stone keeps its
    // width).
    std::vector<char> gone(stones_.size(), 0);
    four_way_ = four_ways(0, rows_, 0, units_);
    std::vector<int> held;
    for (std::size_t n = 0; n < owner_.size(); ++n)
        if (owner_[n] >= 0 && owner_[n] < first_id_ && !shaped_[n]) held.push_back(owner_[n]);
    std::sort(held.begin(), held.end());
    held_ = static_cast<int>(std::unique(held.begin(), held.end()) - held.begin());
    // Each repair can leave work for the other (a stone split off makes a four-way joint, a
    // joint moved frees a unit): all run until none changes anything. Every repair is taken
    // only where it lowers the face's key (see `Key`), so none undoes another's and the rounds
    // end; the bound is a guard.
    for (rounds_ = 1; rounds_ <= kMaxRounds; ++rounds_) {
        four_way_ = four_ways(0, rows_, 0, units_);
        const bool joined = join_on_end(gone);
        const bool broken = break_four_ways(gone);
        const bool relaid = relay_faults(gone);
        gone.resize(stones_.size(), 0);
        if (!joined && !broken && !relaid) break;
    }
    std::size_t n = 0;
    for (std::size_t k = 0; k < stones_.size(); ++k)
        if (!gone[k]) stones_[n++] = stones_[k];
    stones_.resize(n);
}

bool AshlarRules::on_end(const Stone& s) const {
    double w = 0;  // along its top row, less what a jamb or skewback cuts off
    for (int u = s.unit; u < s.unit + s.w; ++u)
        w += (g_.xs[static_cast<std::size_t>(u + 1)] - g_.xs[static_cast<std::size_t>(u)]) *
             share_[static_cast<std::size_t>(s.row * units_ + u)];
    const auto y0 = static_cast<std::size_t>(s.row), y1 = y0 + static_cast<std::size_t>(s.h);
    return g_.ys[y1] - g_.ys[y0] > 1.1 * w &&
           !jamb_[static_cast<std::size_t>(s.row * units_ + s.unit)];
}

bool AshlarRules::upright(const Stone& s) const {
    if (s.h == 1) return true;
    if (s.w == 1 && jamb_[static_cast<std::size_t>(s.row * units_ + s.unit)]) return true;
    double w = 0;
    for (int u = s.unit; u < s.unit + s.w; ++u)
        w += (g_.xs[static_cast<std::size_t>(u + 1)] - g_.xs[static_cast<std::size_t>(u)]) *
             share_[static_cast<std::size_t>(s.row * units_ + u)];
    return w >=
           g_.ys[static_cast<std::size_t>(s.row + s.h)] - g_.ys[static_cast<std::size_t>(s.row)];
}

long AshlarRules::live(const std::vector<char>& gone) const {
    return std::count(gone.begin(), gone.end(), 0) +
           static_cast<long>(stones_.size() - gone.size()) + held_;
}

bool AshlarRules::relay(std::vector<int> ks, std::vector<char>& gone, long max_nodes) {
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    if (ks.empty()) return false;
    int r0 = rows_, r1 = 0, u0 = units_, u1 = 0;
    std::vector<std::pair<int, int>> units;  // the region, in reading order
    for (int k : ks) {
        const Stone& s = stones_[static_cast<std::size_t>(k)];
        r0 = std::min(r0, s.row), r1 = std::max(r1, s.row + s.h);
        u0 = std::min(u0, s.unit), u1 = std::max(u1, s.unit + s.w);
        for (int r = s.row; r < s.row + s.h; ++r)
            for (int u = s.unit; u < s.unit + s.w; ++u) units.emplace_back(r, u);
    }
    std::sort(units.begin(), units.end());
    std::vector<int> ids;
    for (int k : ks) ids.push_back(first_id_ + k);
    auto id_of = [&](std::size_t n) {
        return n < ids.size() ? ids[n]
                              : first_id_ + static_cast<int>(stones_.size() + n - ids.size());
    };
    // Sides shared by two unit squares, one of them the region's, each counted twice (from
    // both sides when both are the region's) so that where the region ends does not count.
    auto squares = [&](const std::vector<Stone>& laid) {
        long n = 0;
        for (const Stone& s : laid)
            if (small(s))
                each_beside(s, [&](int a, int b) {
                    const int id = get(a, b);
                    std::size_t m = 0;
                    while (m < laid.size() && id_of(m) != id) ++m;
                    if (m < laid.size()) {
                        n += small(laid[m]);
                    } else if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
                        const Stone* t = own(id);
                        n += 2 * (t ? small(*t) : small_at(a, b));
                    }
                });
        return n;
    };
    // The face's count of four-way joints and stones with the region's `fw` and `n`.
    const int fw_before = four_ways(r0, r1, u0, u1);
    const long fw_other = four_way_ - fw_before;
    const long live_other = live(gone) - static_cast<long>(ks.size());
    auto over = [&](long fw, std::size_t n) {
        return static_cast<int>(100 * (fw_other + fw) > live_other + static_cast<long>(n));
    };
    std::vector<Stone> now;
    long ends_now = 0;
    for (int k : ks) {
        now.push_back(stones_[static_cast<std::size_t>(k)]);
        ends_now += on_end(now.back());
    }
    const Key before{over(fw_before, now.size()), ends_now, fw_before, squares(now)};
    // A relay that found nothing finds nothing again while the units round it and the room the
    // face has for four-way joints (up to five more) are as they were: the rounds ask again.
    std::uint64_t memo = 1469598103934665603ULL;
    auto mix = [&](long v) { memo = (memo ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL; };
    mix(max_nodes);
    mix(std::clamp(live_other - 100 * fw_other, -1000L, 500L));
    for (int r = r0 - 1; r <= r1; ++r)
        for (int u = u0 - 1; u <= u1; ++u) {
            const int id = get(r, u);
            mix(id);
            if (const Stone* t = own(id)) mix(t->row), mix(t->unit), mix(t->h), mix(t->w);
        }
    if (failed_.count(memo)) return false;
    // Laid again: the region's units free, then every tiling (largest stones first) up to a
    // bound, each stone taking the id of the region's stone it replaces (new ids past the end).
    // Four-way joints and stones on end only grow as stones are laid (a point all four of whose
    // units are laid cannot lose its joint), so a tiling begun worse than the best is left.
    for (auto [r, u] : units) at(r, u) = kEmpty;
    const long base = four_ways(r0, r1, u0, u1);  // those the region's units do not touch
    const Key ideal{over(base, units.size()), 0, base, 0};
    std::vector<Stone> laid, best_laid;
    Key best = before;
    long nodes = 0;
    std::function<void(std::size_t, long, long)> search = [&](std::size_t next, long ends,
                                                              long fw) {
        if (++nodes > max_nodes || best <= ideal) return;
        while (next < units.size() && get(units[next].first, units[next].second) != kEmpty) ++next;
        if (next == units.size()) {
            if (const Key k{over(fw, laid.size()), ends, fw, squares(laid)}; k < best)
                best = k, best_laid = laid;
            return;
        }
        const auto [r, u] = units[next];
        for (int h = max_h_; h >= 1; --h)
            for (int w = max_w_; w >= 1; --w) {
                const Stone s{r, u, h, w};
                if (!fits(r, u, h, w) || !upright(s)) continue;
                const int id = id_of(laid.size());
                for (int i = r; i < r + h; ++i)
                    for (int j = u; j < u + w; ++j) at(i, j) = id;
                laid.push_back(s);
                const long e = ends + on_end(s), f = fw + four_ways(r, r + h, u, u + w);
                if (Key{over(f, units.size()), e, f, 0} < best) search(next + 1, e, f);
                laid.pop_back();
                for (int i = r; i < r + h; ++i)
                    for (int j = u; j < u + w; ++j) at(i, j) = kEmpty;
            }
    };
    if (before > ideal) search(0, 0, base);
    const bool better = !best_laid.empty() && best < before;
    const std::vector<Stone>& use = better ? best_laid : now;
    for (std::size_t n = 0; n < use.size(); ++n) {
        const Stone& s = use[n];
        const int id = better ? id_of(n) : ids[n];
        for (int i = s.row; i < s.row + s.h; ++i)
            for (int j = s.unit; j < s.unit + s.w; ++j) at(i, j) = id;
    }
    if (!better) {
        failed_.insert(memo);
        return false;
    }
    four_way_ += std::get<2>(best) - fw_before;
    for (std::size_t n = 0; n < best_laid.size(); ++n) {
        if (n < ks.size()) {
            stones_[static_cast<std::size_t>(ks[n])] = best_laid[n];
        } else {
            stones_.push_back(best_laid[n]);
            gone.push_back(0);
        }
    }
    for (std::size_t n = best_laid.size(); n < ks.size(); ++n)
        gone[static_cast<std::size_t>(ks[n])] = 1;
    return true;
}

bool AshlarRules::relay_faults(std::vector<char>& gone) {
    bool changed = false;
    four_way_ = four_ways(0, rows_, 0, units_);  // the joins above may have taken some away
    // The layout's stones among units (rows r0..r1, units u0..u1, inclusive).
    auto around = [&](int ra, int rb, int ua, int ub) {
        std::vector<int> ks;
        for (int r = ra; r <= rb; ++r)
            for (int u = ua; u <= ub; ++u)
                if (const Stone* s = own(get(r, u)))
                    ks.push_back(static_cast<int>(s - stones_.data()));
        return ks;
    };
    for (int i = 1; i < rows_; ++i)
        for (int j = 1; j < units_; ++j)
            if (four_ways(i, i, j, j) > 0)
                changed |= relay(around(i - 1, i, j - 1, j), gone) ||
                           relay(around(i - 2, i + 1, j - 2, j + 1), gone) ||
                           relay(around(i - 3, i + 2, j - 3, j + 2), gone);
    for (std::size_t k = 0; k < stones_.size(); ++k) {
        if (gone[k]) continue;
        const Stone s = stones_[k];
        const bool square = lone_square(s, kBlocked);
        if (!on_end(s) && !square) continue;
        const int r0 = s.row, r1 = s.row + s.h - 1, u0 = s.unit, u1 = s.unit + s.w - 1;
        // Wider round it where the stones beside it cannot take it, and for a stone on end
        // deeper (a unit square on end at the heart of a pinwheel of two-row stones, on a grid
        // stretched between a lintel and a sill).
        changed |= relay(around(r0 - 1, r1 + 1, u0 - 1, u1 + 1), gone) ||
                   relay(around(r0 - 2, r1 + 2, u0 - 2, u1 + 2), gone) ||
                   (on_end(s) && (relay(around(r0 - 3, r1 + 3, u0 - 3, u1 + 3), gone) ||
                                  relay(around(r0 - 2, r1 + 2, u0 - 2, u1 + 2), gone, 200000)));
    }
    return changed;
}

bool AshlarRules::join_on_end(std::vector<char>& gone) {
    bool changed = false;
    for (std::size_t k = 0; k < stones_.size(); ++k) {
        const Stone s = stones_[k];
        if (gone[k] || s.h != 1 || s.w != 1 || !on_end(s)) continue;
        int best = -1;
        for (int j : {s.unit - 1, s.unit + 1})
            if (const Stone* t = own(get(s.row, j));
                t && t->row == s.row && t->h == 1 &&
                (best < 0 || t->w < stones_[static_cast<std::size_t>(best)].w))
                best = static_cast<int>(t - stones_.data());
        // A stone fewer must not take the face over 1% of four-way joints.
        const long n = live(gone);
        if (best >= 0 && (100L * four_way_ > n || 100L * four_way_ <= n - 1)) {
            Stone& b = stones_[static_cast<std::size_t>(best)];
            b.unit = std::min(b.unit, s.unit);
            b.w += 1;
            at(s.row, s.unit) = first_id_ + best;
            gone[k] = 1;
            changed = true;
            continue;
        }
        if (split_beside(static_cast<int>(k), gone)) {
            gone.resize(stones_.size(), 0);
            gone[k] = 1;
            changed = true;
        }
    }
    return changed;
}

// A unit square of the layout, or one beside another (`other` aside): what a joint moved may
// not leave.
bool AshlarRules::lone_square(const Stone& s, int other) const {
    if (!small(s)) return false;
    bool found = false;
    each_beside(s, [&](int a, int b) { found |= get(a, b) != other && small_at(a, b); });
    return found;
}

bool AshlarRules::small(const Stone& s) const {
    double w = 0;
    for (int u = s.unit; u < s.unit + s.w; ++u)
        w += (g_.xs[static_cast<std::size_t>(u + 1)] - g_.xs[static_cast<std::size_t>(u)]) *
             share_[static_cast<std::size_t>(s.row * units_ + u)];
    return w < square_ &&
           g_.ys[static_cast<std::size_t>(s.row + s.h)] - g_.ys[static_cast<std::size_t>(s.row)] <
               square_;
}

bool AshlarRules::small_at(int r, int u) const {
    if (r < 0 || u < 0 || r >= rows_ || u >= units_) return false;
    if (const Stone* t = own(get(r, u))) return small(*t);
    return get(r, u) >= 0 && small_held_[static_cast<std::size_t>(r * units_ + u)];
}

bool AshlarRules::break_four_ways(std::vector<char>& gone) {
    bool changed = false;
    for (int i = 1; i < rows_; ++i)
        for (int j = 1; j < units_; ++j) {
            if (four_ways(i, i, j, j) == 0) continue;
            bool done = false;
            for (int row : {i - 1, i}) {
                const int ia = get(row, j - 1), ib = get(row, j);
                const Stone *a = own(ia), *b = own(ib);
                if (!a || !b || a == b || a->row != b->row || a->h != b->h) continue;
                if (a->unit + a->w != j) continue;
                const int r0 = a->row, r1 = a->row + a->h, u0 = a->unit, u1 = b->unit + b->w;
                const int before = four_ways(r0, r1, u0, u1);
                // 0: a unit of `a` to `b`; 1: a unit of `b` to `a`; 2: `b` joined to `a`.
                for (int way = 0; way < 3 && !done; ++way) {
                    Stone da = *a, db = *b;
                    if (way == 0) da.w -= 1, db.unit -= 1, db.w += 1;
                    if (way == 1) da.w += 1, db.unit += 1, db.w -= 1;
                    if (way == 2) da.w += db.w, db.w = 0;
                    if (da.w < 1 || da.w > max_w_ || db.w > max_w_ || (way < 2 && db.w < 1))
                        continue;
                    if (on_end(da) || (way < 2 && on_end(db))) continue;
                    auto give = [&](int u, int w, int id) {
                        for (int r = r0; r < r1; ++r)
                            for (int x = u; x < u + w; ++x) at(r, x) = id;
                    };
                    give(da.unit, da.w, ia);
                    if (way < 2) give(db.unit, db.w, ib);
                    const bool square = lone_square(da, ib) || (way < 2 && lone_square(db, ia));
                    const int after = four_ways(r0, r1, u0, u1);
                    if (square || after >= before) {
                        give(a->unit, a->w, ia);
                        give(b->unit, b->w, ib);
                        continue;
                    }
                    four_way_ -= before - after;
                    stones_[static_cast<std::size_t>(ia - first_id_)] = da;
                    if (way < 2)
                        stones_[static_cast<std::size_t>(ib - first_id_)] = db;
                    else
                        gone[static_cast<std::size_t>(ib - first_id_)] = 1;
                    changed = done = true;
                }
                if (done) break;
            }
            // Else two stones of one column over each other joined, where no taller than wide.
            for (int col : {j - 1, j}) {
                if (done) break;
                const int ia = get(i - 1, col), ib = get(i, col);
                const Stone *a = own(ia), *b = own(ib);
                if (!a || !b || a == b || a->unit != b->unit || a->w != b->w ||
                    a->row + a->h != i || a->h + b->h > max_h_)
                    continue;
                const Stone joined{a->row, a->unit, a->h + b->h, a->w};
                const auto x0 = static_cast<std::size_t>(joined.unit);
                const auto x1 = x0 + static_cast<std::size_t>(joined.w);
                if (g_.xs[x1] - g_.xs[x0] < g_.ys[static_cast<std::size_t>(joined.row + joined.h)] -
                                                g_.ys[static_cast<std::size_t>(joined.row)] ||
                    on_end(joined))
                    continue;
                const int r0 = joined.row, r1 = joined.row + joined.h, u0 = joined.unit,
                          u1 = joined.unit + joined.w;
                const int before = four_ways(r0, r1, u0, u1);
                for (int r = b->row; r < b->row + b->h; ++r)
                    for (int x = u0; x < u1; ++x) at(r, x) = ia;
                const int after = four_ways(r0, r1, u0, u1);
                if (after >= before) {
                    for (int r = b->row; r < b->row + b->h; ++r)
                        for (int x = u0; x < u1; ++x) at(r, x) = ib;
                    continue;
                }
                four_way_ -= before - after;
                gone[static_cast<std::size_t>(ib - first_id_)] = 1;
                stones_[static_cast<std::size_t>(ia - first_id_)] = joined;
                changed = done = true;
            }
        }
    return changed;
}

int AshlarRules::four_ways(int r0, int r1, int u0, int u1) const {
    int n = 0;
    for (int i = r0; i <= r1; ++i)
        for (int j = u0; j <= u1; ++j) {
            const int a = get(i - 1, j - 1), b = get(i - 1, j), c = get(i, j - 1), d = get(i, j);
            if (std::min({a, b, c, d}) < 0) continue;  // outside the wall or not laid
            bool shaped = false;
            for (int y : {i - 1, i})
                for (int x : {j - 1, j})
                    shaped |= shaped_[static_cast<std::size_t>(y * units_ + x)];
            if (shaped) continue;
            n += a != b && c != d && a != c && b != d;
        }
    return n;
}

bool AshlarRules::four_way_allowed(const std::vector<char>& gone) const {
    return 100L * (four_way_ + 1) <= live(gone);
}

bool AshlarRules::split_beside(int k, const std::vector<char>& gone) {
    const Stone s = stones_[static_cast<std::size_t>(k)];
    std::vector<int> beside;  // taller stones beside it, the narrower first
    for (int j : {s.unit - 1, s.unit + 1}) {
        const Stone* t = own(get(s.row, j));
        if (!t || t->h < 2) continue;
        // What is left of it above or below keeps to one side of the row, and stands on end
        // only at a jamb.
        if (t->row != s.row && t->row + t->h != s.row + 1) continue;
        const int r0 = t->row == s.row ? s.row + 1 : t->row;
        if (g_.ys[static_cast<std::size_t>(r0 + t->h - 1)] - g_.ys[static_cast<std::size_t>(r0)] >
                1.1 * (g_.xs[static_cast<std::size_t>(t->unit + t->w)] -
                       g_.xs[static_cast<std::size_t>(t->unit)]) &&
            !jamb_[static_cast<std::size_t>(r0 * units_ + t->unit)])
            continue;
        beside.push_back(static_cast<int>(t - stones_.data()));
    }
    if (beside.size() == 2 && stones_[static_cast<std::size_t>(beside[1])].w <
                                  stones_[static_cast<std::size_t>(beside[0])].w)
        std::swap(beside[0], beside[1]);
    for (int best : beside) {
        const Stone t = stones_[static_cast<std::size_t>(best)];
        const int ra = std::min(t.row, s.row), rb = t.row + t.h;
        const int ua = std::min(t.unit, s.unit), ub = std::max(t.unit + t.w, s.unit + 1);
        const int before = four_ways(ra, rb, ua, ub);
        // The row beside the unit joins it; the rest becomes a stone of its own.
        const Stone joined{s.row, std::min(t.unit, s.unit), 1, t.w + 1};
        const Stone rest{t.row == s.row ? s.row + 1 : t.row, t.unit, t.h - 1, t.w};
        const int rest_id = first_id_ + static_cast<int>(stones_.size());
        const int id = first_id_ + best;
        auto give = [&](int owner) {
            for (int i = rest.row; i < rest.row + rest.h; ++i)
                for (int j = rest.unit; j < rest.unit + rest.w; ++j) at(i, j) = owner;
        };
        give(rest_id);
        at(s.row, s.unit) = id;
        // A four-way joint is allowed (1% of stones); a stone on end is not: one more is
        // taken while the face stays within that (counted on the grid, where the stones laid
        // before count too, against the face's own stones).
        const int more = four_ways(ra, rb, ua, ub) - before;
        if (more > 1 || (more == 1 && !four_way_allowed(gone))) {
            // undo
            give(id);
            at(s.row, s.unit) = first_id_ + k;
            continue;
        }
        four_way_ += more;
        stones_[static_cast<std::size_t>(best)] = joined;
        stones_.push_back(rest);
        return true;
    }
    return false;
}

const Stone* AshlarRules::own(int id) const {
    const int k = id - first_id_;
    return k >= 0 && k < static_cast<int>(stones_.size()) ? &stones_[static_cast<std::size_t>(k)]
                                                          : nullptr;
}

bool AshlarRules::fits(int r, int u, int h, int w) const {
    for (int i = r; i < r + h; ++i)
        for (int j = u; j < u + w; ++j)
            if (get(i, j) != kEmpty) return false;
    return true;
}

// 1 when four stones meet at grid point (i, j) with the candidate stone laid: the four units
// round it held by four stones. A free unit counts as a stone of its own when it is the only
// free one there (whatever is laid on it later is a fourth stone); two free units may yet share
// one.
int AshlarRules::cross(int r, int u, int h, int w, int i, int j) const {
    constexpr int kCandidate = -3, kFuture = -4;
    int id[4], empty = 0;
    const int at[4][2] = {{i - 1, j - 1}, {i - 1, j}, {i, j - 1}, {i, j}};
    for (int k = 0; k < 4; ++k) {
        const int a = at[k][0], b = at[k][1];
        if (a >= r && a < r + h && b >= u && b < u + w)
            id[k] = kCandidate;
        else
            id[k] = get(a, b);
        if (id[k] == kBlocked) return 0;
        if (id[k] == kEmpty) ++empty, id[k] = kFuture;
    }
    if (empty > 1) return 0;
    return id[0] != id[1] && id[2] != id[3] && id[0] != id[2] && id[1] != id[3];
}

int AshlarRules::faults(int r, int u, int h, int w) const {
    int f = cross(r, u, h, w, r, u) + cross(r, u, h, w, r, u + w) + cross(r, u, h, w, r + h, u) +
            cross(r, u, h, w, r + h, u + w);
    // Unit squares: a last resort, and never two side by side (measured: two grid units
    // narrower than a unit and a half are a unit square too, and so is a stone laid before).
    if (h == 1 && w == 1) {
        // A narrow unit (grid lines close together) alone would stand on end: worse.
        const double uw = g_.xs[static_cast<std::size_t>(u + 1)] -
                          g_.xs[static_cast<std::size_t>(u)],
                     uh = g_.ys[static_cast<std::size_t>(r + 1)] -
                          g_.ys[static_cast<std::size_t>(r)];
        f += uh > 1.1 * uw && !jamb_[static_cast<std::size_t>(r * units_ + u)] ? 3 : 1;
    }
    if (const Stone c{r, u, h, w}; small(c))
        each_beside(c, [&](int a, int b) { f += small_at(a, b) ? 2 : 0; });
    // A bed joint under the stone along more than max_seam stones of this layout.
    const int x = u + w, y = r + h;
    int run = 1;
    for (int j = u - 1; j >= 0;) {
        const Stone* s = own(get(y - 1, j));
        if (!s || s->row + s->h != y) break;
        ++run;
        j = s->unit - 1;
    }
    for (int j = x; j < units_;) {
        const Stone* s = own(get(y - 1, j));
        if (!s || s->row + s->h != y) break;
        ++run;
        j = s->unit + s->w;
    }
    if (run > max_seam_ && y < rows_ && get(y, u) != kBlocked) ++f;
    // A side joint right of it, likewise.
    run = 1;
    for (int i = r - 1; i >= 0;) {
        const Stone* s = own(get(i, x - 1));
        if (!s || s->unit + s->w != x) break;
        ++run;
        i = s->row - 1;
    }
    if (run > max_seam_ && get(r, x) != kBlocked) ++f;
    return f;
}

void AshlarRules::lay_at(int r, int u, Random& random) {
    // No stone on end: as wide as high at least (measured, the grid's units need not be
    // square), up to max_w units wide; a single unit only where nothing else fits.
    std::vector<std::pair<int, int>> sizes;
    for (int h = 1; h <= max_h_; ++h)
        for (int w = h; w <= max_w_; ++w)
            if (fits(r, u, h, w) && upright({r, u, h, w})) sizes.emplace_back(h, w);
    if (jamb_[static_cast<std::size_t>(r * units_ + u)])
        for (int h = 2; h <= max_h_; ++h)
            if (fits(r, u, h, 1)) sizes.emplace_back(h, 1);
    for (std::size_t i = sizes.size(); i > 1; --i)  // Fisher-Yates with our own numbers
        std::swap(
            sizes[i - 1],
            sizes[static_cast<std::size_t>(random.uniform_int(0, static_cast<long long>(i) - 1))]);
    std::pair<int, int> best = sizes.front();
    int best_faults = 1 << 30;
    for (auto [h, w] : sizes) {
        const int f = faults(r, u, h, w);
        if (f < best_faults) best_faults = f, best = {h, w};
        if (f == 0) break;
    }
    const int id = first_id_ + static_cast<int>(stones_.size());
    stones_.push_back({r, u, best.first, best.second});
    for (int i = r; i < r + best.first; ++i)
        for (int j = u; j < u + best.second; ++j) at(i, j) = id;
}

}  // namespace acanthus::cells::detail
