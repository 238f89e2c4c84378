// Candidate pruning for large references. An alignment pairs the target's first neighbour with
// some ring slot, and its error is at least w1 times their distance; so with the (candidate,
// slot) pairs on a grid by the slot's offset, the cells are visited ring by ring around the first
// neighbour and the search stops when the nearest unvisited cell is too far to beat the best
// error so far. Each pair found costs one alignment, cut short once it is beaten; the candidates
// found are then chosen among exactly as choose() does over all of them (ties within 1e-9
// relative, drawn at random in candidate order), so the result does not depend on the index.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "synthesis.hpp"

namespace acanthus::growth::detail {
namespace {

std::int64_t pack(long x, long y) {
    return (static_cast<std::int64_t>(x) << 32) ^ (static_cast<std::int64_t>(y) & 0xffffffff);
}

// alignment_error_within with sqrt for hypot (which rounds alike to within an ulp or so): a
// cheap estimate, exact only for the few alignments that come close; infinity past `limit`.
double alignment_estimate(const std::vector<RingEntry>& target, const RingEntry* reference,
                          std::size_t m, int shift, double cos_r, double sin_r, const Weights& w,
                          double limit) {
    double error = 0;
    std::size_t k = static_cast<std::size_t>(shift) % m;
    for (std::size_t i = 0; i < target.size(); ++i, k = k + 1 == m ? 0 : k + 1) {
        const RingEntry& t = target[i];
        const RingEntry& r = reference[k];
        const Vector d = t.offset - Vector{cos_r * r.offset.x - sin_r * r.offset.y,
                                           sin_r * r.offset.x + cos_r * r.offset.y};
        error += w.w1 * std::sqrt(d.dot(d));
        if (t.symbol >= 0 && t.symbol != r.symbol) error += w.w2;
        if (t.sub >= 0 && t.sub == r.sub) error += w.w3;
        if (error > limit) return INFINITY;
    }
    return error;
}

}  // namespace

void Synthesis::build_slot_index() {
    SlotIndex index;
    // A tenth of the mean edge: the search radius (the best error over w1, a few tenths of an
    // edge) is a few cells.
    index.cell = 0.1 * l_;
    auto cell = [&](double v) { return static_cast<long>(std::floor(v / index.cell)); };
    struct Keyed {
        long x0, y0, x1, y1;
        SlotEntry e;
    };
    std::vector<Keyed> all;
    for (std::size_t n = 0; n < candidates_.size(); ++n) {
        const int c = candidates_[n];
        const auto& ring = rings_[c];
        const std::size_t m = ring.size();
        index.ring_begin.push_back(static_cast<int>(index.rings.size()));
        for (const RingEntry& r : ring) {
            index.rings.push_back(r);
            index.ring_symbols.push_back(r.symbol);
        }
        for (std::size_t k = 0; k < m; ++k) {
            SlotEntry e;
            for (std::size_t j = 0; j < 3; ++j) e.slot[j] = ring[(k + j) % m].offset;
            e.element = c;
            e.shift = static_cast<int>(k);
            e.symbol = reference_.symbol[c];
            e.slots = static_cast<int>(m);
            e.candidate = static_cast<int>(n);
            all.push_back(
                {cell(e.slot[0].x), cell(e.slot[0].y), cell(e.slot[1].x), cell(e.slot[1].y), e});
        }
    }
    index.ring_begin.push_back(static_cast<int>(index.rings.size()));
    if (all.empty()) return;
    std::stable_sort(all.begin(), all.end(), [](const Keyed& a, const Keyed& b) {
        return std::tie(a.x0, a.y0, a.e.symbol, a.x1, a.y1) <
               std::tie(b.x0, b.y0, b.e.symbol, b.x1, b.y1);
    });
    index.lo = index.hi = all.front().x0;
    for (const Keyed& k : all) {
        index.max_slots = std::max(index.max_slots, k.e.slots);
        index.lo = std::min({index.lo, k.x0, k.y0});
        index.hi = std::max({index.hi, k.x0, k.y0});
        const int id = static_cast<int>(index.entries.size());
        index.entries.push_back(k.e);
        auto& groups = index.cells[pack(k.x0, k.y0)];
        if (groups.empty() || groups.back().x != k.x1 || groups.back().y != k.y1 ||
            groups.back().symbol != k.e.symbol)
            groups.push_back({k.x1, k.y1, k.e.symbol, id, id});
        groups.back().end = id + 1;
    }
    slot_index_ = std::move(index);
    seen_.assign(candidates_.size(), -1);
    found_at_.assign(candidates_.size(), -1);
    bounded_.assign(candidates_.size(), -1);
    balance_low_.assign(candidates_.size(), 0.0);
    balance_high_.assign(candidates_.size(), 0.0);
}

Synthesis::Choice Synthesis::choose_pruned(const Node& seed, const std::vector<RingEntry>& target,
                                           double turn, bool balance) {
    const SlotIndex& index = *slot_index_;
    ++seen_generation_;
    // The first neighbours in the reference's frame (flow mode turns the reference by `turn`):
    // cheap lower bounds on an alignment's error before it is summed exactly.
    Vector q[3];
    for (std::size_t j = 0; j < 3 && j < target.size(); ++j) q[j] = target[j].offset.rotated(-turn);
    const std::size_t bounded = std::min<std::size_t>(3, target.size());
    const double cos_t = std::cos(turn), sin_t = std::sin(turn);
    const double w1 = weights_.w1, h = index.cell;
    struct Found {
        int element;
        double error;
        int shift;
    };
    std::vector<Found> found;
    // With w4, an element's error is its least ring error plus w4 times the excess of the slots
    // it leaves open (and its own symbol for a seed without one): at least w4 * low per such
    // slot. `best` is the least upper bound on a chosen element's error so far.
    double low = 0;
    if (balance)
        for (std::size_t k = 0; k < reference_.symbols.size(); ++k)
            low = std::min(low, excess(static_cast<int>(k)));
    const double w4 = balance ? options_.w4 * (1 + 1e-9) : 0.0;
    auto open_slots = [&](int slots) {
        return static_cast<double>(slots - static_cast<int>(target.size()) + (seed.symbol < 0));
    };
    // The least w4 term of any alignment (<= 0): how much further out a ring error may lie.
    const double any_low = w4 * low * std::max(0.0, open_slots(index.max_slots));
    // An element's own w4 terms, least and most over its shifts: the term of a shift is its
    // symbol's excess (a seed without one) plus its ring's excess less that of the window of
    // slots the targets take, so the extremes come from the windows' most and least excess.
    // The margins keep rounding (the sum's order differs from balance_over's) on the safe side.
    std::vector<double> symbol_excess(reference_.symbols.size());
    for (std::size_t k = 0; k < symbol_excess.size(); ++k)
        symbol_excess[k] = excess(static_cast<int>(k));
    const std::size_t taken = target.size();
    auto bound_balance = [&](const SlotEntry& s) {
        const auto n = static_cast<std::size_t>(s.candidate);
        const int* ring = index.ring_symbols.data() + index.ring_begin[n];
        const auto m = static_cast<std::size_t>(s.slots);
        auto ex = [&](std::size_t k) { return symbol_excess[static_cast<std::size_t>(ring[k])]; };
        double whole = 0;
        for (std::size_t k = 0; k < m; ++k) whole += ex(k);
        double window = 0;
        for (std::size_t j = 0; j < taken && j < m; ++j) window += ex(j);
        double most = window, least = window;
        // The window from slot k to slot `last`, round the ring.
        for (std::size_t k = 1, last = taken % m; k < m && taken < m;
             ++k, last = last + 1 == m ? 0 : last + 1) {
            window += ex(last) - ex(k - 1);
            most = std::max(most, window);
            least = std::min(least, window);
        }
        const double own =
            seed.symbol < 0 ? symbol_excess[static_cast<std::size_t>(s.symbol)] : 0.0;
        const double lo = options_.w4 * (own + whole - most);
        const double hi = options_.w4 * (own + whole - least);
        balance_low_[n] = lo - 1e-9 * (1 + std::abs(lo));
        balance_high_[n] = hi + 1e-9 * (1 + std::abs(hi));
        bounded_[n] = seen_generation_;
    };
    double best = INFINITY;
    auto bound = [&] { return best + 1e-9 * (1 + std::abs(best)); };
    // Bounds leave a margin, so that rounding never prunes an alignment the exact sum keeps.
    auto limit = [&] { return bound() + 1e-9 * std::abs(bound()) + 1e-12; };
    auto consider = [&](int id) {
        const SlotEntry& s = index.entries[static_cast<std::size_t>(id)];
        if (seed.symbol >= 0 && s.symbol != seed.symbol) return;
        if (target.size() > static_cast<std::size_t>(s.slots)) return;
        // The ring error past which this alignment's whole error cannot be chosen: first with
        // the least w4 term of any ring this size, then with the element's own.
        double ring_limit = limit() - w4 * low * open_slots(s.slots);
        double lower = 0;
        for (std::size_t j = 0; j < bounded; ++j) {
            const Vector d = s.slot[j] - q[j];
            lower += w1 * std::sqrt(d.dot(d));
            if (lower > ring_limit) return;
        }
        const auto n = static_cast<std::size_t>(s.candidate);
        if (balance) {
            if (bounded_[n] != seen_generation_) bound_balance(s);
            ring_limit = limit() - balance_low_[n];
            if (lower > ring_limit) return;
        }
        if (target.size() > 3 &&
            !(alignment_estimate(target, index.rings.data() + index.ring_begin[n],
                                 static_cast<std::size_t>(s.slots), s.shift, cos_t, sin_t, weights_,
                                 ring_limit) <= ring_limit))
            return;
        double e = alignment_error_within(target, index.rings.data() + index.ring_begin[n],
                                          static_cast<std::size_t>(s.slots), s.shift, cos_t, sin_t,
                                          weights_, balance ? ring_limit : bound());
        if (!std::isfinite(e)) return;
        const int c = s.element, k = s.shift;
        if (seen_[n] != seen_generation_) {
            seen_[n] = seen_generation_;
            found_at_[n] = static_cast<int>(found.size());
            found.push_back({c, e, k});
        } else {
            Found& f = found[static_cast<std::size_t>(found_at_[n])];
            // match_ring keeps the first shift of the least error.
            if (e < f.error || (e == f.error && k < f.shift)) {
                f.error = e;
                f.shift = k;
            }
        }
        // Its least ring error is at most e: its error is at most e plus the most w4 adds.
        best = std::min(best, balance ? e + balance_high_[n] : e);
    };
    // The distance from p to cell (x, y)'s nearest point, a hair short.
    auto gap = [&](Vector p, long x, long y) {
        const double cx =
            std::clamp(p.x, static_cast<double>(x) * h, static_cast<double>(x + 1) * h);
        const double cy =
            std::clamp(p.y, static_cast<double>(y) * h, static_cast<double>(y + 1) * h);
        return std::sqrt((cx - p.x) * (cx - p.x) + (cy - p.y) * (cy - p.y)) * (1 - 1e-9);
    };
    // First slots' cells ring by ring around the first neighbour, while one can be within the
    // bound; in each, the groups whose next slot's cell can be too.
    const long px = static_cast<long>(std::floor(q[0].x / h));
    const long py = static_cast<long>(std::floor(q[0].y / h));
    const long reach = std::max({px - index.lo, index.hi - px, py - index.lo, index.hi - py});
    for (long r = 0; r <= reach; ++r) {
        if (r >= 1 && w1 * static_cast<double>(r - 1) * h > limit() - any_low) break;
        for (long x = px - r; x <= px + r; ++x)
            for (long y = py - r; y <= py + r; ++y) {
                if (std::max(std::abs(x - px), std::abs(y - py)) != r) continue;
                const double g0 = gap(q[0], x, y);
                if (w1 * g0 > limit() - any_low) continue;
                auto it = index.cells.find(pack(x, y));
                if (it == index.cells.end()) continue;
                for (const SlotGroup& group : it->second) {
                    if (seed.symbol >= 0 && group.symbol != seed.symbol) continue;
                    if (target.size() > 1 &&
                        w1 * (g0 + gap(q[1], group.x, group.y)) > limit() - any_low)
                        continue;
                    for (int id = group.begin; id < group.end; ++id) consider(id);
                }
            }
    }
    std::sort(found.begin(), found.end(),
              [](const Found& a, const Found& b) { return a.element < b.element; });
    std::vector<Choice> ties;
    double best_error = INFINITY;
    for (const Found& f : found) {
        // choose()'s sum, in its order: the same bits.
        double error = f.error;
        if (balance) error += options_.w4 * balance_over(seed, f.element, f.shift, target.size());
        double slack = ties.empty() ? 0.0 : 1e-9 * (1 + std::abs(best_error));
        if (ties.empty() || error < best_error - slack) {
            ties.clear();
            best_error = error;
        }
        if (error <= best_error + slack) ties.push_back({f.element, {error, f.shift, turn}, {}});
    }
    if (ties.empty()) return {};
    if (ties.size() == 1) return ties.front();
    return ties[static_cast<std::size_t>(
        random_.uniform_int(0, static_cast<long long>(ties.size()) - 1))];
}

}  // namespace acanthus::growth::detail
