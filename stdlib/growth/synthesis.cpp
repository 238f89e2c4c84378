#include "synthesis.hpp"

#include <acanthus/error.hpp>
#include <acanthus/partial_maker.hpp>
#include <acanthus/partial_picture.hpp>
#include <acanthus/progress.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "own_holes.hpp"
#include "relaxation.hpp"

namespace acanthus::growth::detail {

// A pair of symbols with fewer reference edges than this has no reliable shortest edge of its
// own (the spacing rule, Options::gap_factor).
constexpr long kFewEdges = 12;

namespace {
PartialMakerSlot<Motif> g_partial_maker;
}  // namespace

bool set_partial_maker(PartialMaker maker) noexcept { return g_partial_maker.set(maker); }

Synthesis::Synthesis(const ReferenceData& reference, const Panel& panel, const Options& options,
                     Random& random)
    : reference_(reference),
      panel_(panel),
      options_(options),
      random_(random),
      // Positions are compared in mean edge lengths, so that w1 weighs the same against the
      // symbol and sub-id terms whatever the drawing's units.
      weights_{options.w1 / reference.mean_edge, options.w2, options.w3},
      l_(reference.mean_edge),
      l_short_(options.short_factor * reference.shortest_edge),
      tolerance_(1e-9 * reference.mean_edge),
      pattern_(reference.mean_edge) {
    spacing_ = ring_spacing(reference);
    restart_radius_ = reference.restart_radius;
    check_motif_count(reference, panel.area(), options);
    for (std::size_t i = 0; i < reference.elements.size(); ++i) {
        std::vector<RingEntry> ring;
        for (const RingSlot& s : reference.rings[i])
            ring.push_back({s.offset, reference.symbol[s.element], s.element});
        rings_.push_back(std::move(ring));
    }
    if (options.two_ring) {
        for (std::size_t i = 0; i < reference.elements.size(); ++i) {
            std::vector<int> inner{static_cast<int>(i)};
            for (const RingSlot& s : reference.rings[i]) inner.push_back(s.element);
            std::vector<int> outer;
            for (const RingSlot& s : reference.rings[i])
                for (const RingSlot& t : reference.rings[s.element])
                    if (std::find(inner.begin(), inner.end(), t.element) == inner.end() &&
                        std::find(outer.begin(), outer.end(), t.element) == outer.end())
                        outer.push_back(t.element);
            std::vector<OuterEntry> entries;
            for (int e : outer)
                entries.push_back({reference.elements[e].position - reference.elements[i].position,
                                   reference.symbol[e]});
            outer_rings_.push_back(std::move(entries));
        }
    }
    if (options.mode == Mode::flow)
        flow_.emplace(options.flow_strokes, l_,
                      options.guides_name.empty() ? "growth" : options.guides_name);
    // A huge reference is matched against an even sample of its interior elements in file
    // order: its variety is there, at a bounded cost per seed.
    const std::size_t all = reference.candidates.size();
    const std::size_t stride = (all + kMaxCandidates - 1) / kMaxCandidates;
    for (std::size_t k = 0; k < all; k += stride) candidates_.push_back(reference.candidates[k]);
    if (options.lattice && options.mode == Mode::none) {
        lattice_ = lattice_of(reference);
        if (lattice_) stats_.lattice_sites = static_cast<int>(lattice_->sites.size());
    }
    if (!lattice_) {
        const RingRegularity& regularity = regularity_of(reference);
        stats_.ring_order = regularity.order;
        stats_.near_regular = regularity.near_regular;
        stats_.honeycomb = regularity.honeycomb;
        // Like a lattice, only where motifs keep the reference's orientation (mode none).
        if (options.fit_to_ring && options.mode == Mode::none && regularity.near_regular)
            if (const JitteredLattice* fit = jittered_lattice_of(reference)) jittered_ = *fit;
        if (jittered_) stats_.jitter = jittered_->rms;
        // A honeycomb's sites are matched against elements of their own sublattice.
        if (jittered_ && jittered_->vacant >= 0) {
            stats_.honeycomb = true;
            for (int c : candidates_)
                sublattice_candidates_[JitteredLattice::sublattice(jittered_->index(
                                           jittered_->site[static_cast<std::size_t>(c)]))]
                    .push_back(c);
        }
    }
    // On a near-regular reference's lattice a seed is matched about its site (grow()), so each
    // ring is taken about its element's site too: the placed neighbours' own jitter is compared
    // with that of the candidate's neighbours, and the jitter the candidate brings is its own.
    // Matched on the jittered offsets, the candidates whose jitter fits the neighbours' won, and
    // neighbouring motifs' jitter came out alike: the grown lattice more even than the
    // reference, its NN median wider.
    if (jittered_) {
        for (std::size_t c = 0; c < rings_.size(); ++c)
            for (RingEntry& e : rings_[c]) e.offset += jittered_->jitter[c];
        for (std::size_t c = 0; c < outer_rings_.size(); ++c)
            for (OuterEntry& e : outer_rings_[c]) e.offset += jittered_->jitter[c];
    }
    prunable_ = !options.two_ring && options.mode != Mode::rotation && options.w1 > 0;
    if (prunable_) build_slot_index();
    const std::size_t symbols = reference.symbols.size();
    gap_.assign(symbols * symbols, INFINITY);
    std::vector<long> edges(symbols * symbols, 0);
    double shortest = INFINITY;
    for (std::size_t i = 0; i < reference.elements.size(); ++i)
        for (const RingSlot& s : reference.rings[i]) {
            const auto a = static_cast<std::size_t>(reference.symbol[i]);
            const auto b = static_cast<std::size_t>(reference.symbol[s.element]);
            const double d = options.gap_factor * s.offset.length();
            gap_[a * symbols + b] = std::min(gap_[a * symbols + b], d);
            gap_[b * symbols + a] = std::min(gap_[b * symbols + a], d);
            ++edges[a * symbols + b];
            ++edges[b * symbols + a];
            shortest = std::min(shortest, d);
        }
    // The shortest of a handful of edges lies well above the shortest of a hundred: a pair of
    // symbols the reference seldom puts side by side (a rare symbol with itself) would be kept
    // apart more than the reference does. Such a pair keeps the reference's shortest edge of
    // all; overlaps are kept off by the motifs' sizes anyway. Each edge is counted from both
    // ends.
    for (std::size_t k = 0; k < gap_.size(); ++k)
        if (edges[k] > 0 && edges[k] < 2 * kFewEdges) gap_[k] = std::min(gap_[k], shortest);
    // Two symbols never neighbours in the reference keep the closest spacing of either.
    gap_any_.assign(symbols, INFINITY);
    for (std::size_t a = 0; a < symbols; ++a)
        for (std::size_t b = 0; b < symbols; ++b)
            gap_any_[a] = std::min(gap_any_[a], gap_[a * symbols + b]);
    for (std::size_t a = 0; a < symbols; ++a)
        for (std::size_t b = 0; b < symbols; ++b) {
            double& g = gap_[a * symbols + b];
            if (!std::isfinite(g)) g = std::min(gap_any_[a], gap_any_[b]);
            if (!std::isfinite(g)) g = 0;
            gap_max_ = std::max(gap_max_, g);
        }
    for (double& g : gap_any_)
        if (!std::isfinite(g)) g = 0;
    const ReferenceProfile& profile = profile_of(reference);
    crowd_reach_ = profile.checker.reach();
    crowd_limit_ = profile.most_neighbours;
    placed_per_symbol_.assign(symbols, 0);
    reference_share_.assign(reference.symbols.size(), 0.0);
    for (int s : reference.symbol)
        reference_share_[static_cast<std::size_t>(s)] +=
            1.0 / static_cast<double>(reference.symbol.size());
    for (const std::string& name : reference.symbols) {
        auto it = options.priority.find(name);
        priority_.push_back(it == options.priority.end() ? 0 : it->second);
        priorities_differ_ = priorities_differ_ || priority_.back() != priority_.front();
    }
}

double ring_spacing(const ReferenceData& reference) {
    std::call_once(reference.spacing_once, [&] {
        // Each ring's shortest offset: the least square, then hypot() of the offsets within
        // rounding of it (the least hypot() is among them).
        std::vector<double> nearest;
        nearest.reserve(reference.rings.size());
        for (const auto& ring : reference.rings) {
            double least = INFINITY, best = INFINITY;
            for (const RingSlot& s : ring) least = std::min(least, s.offset.dot(s.offset));
            for (const RingSlot& s : ring)
                if (s.offset.dot(s.offset) <= least * (1 + 1e-10))
                    best = std::min(best, s.offset.length());
            if (std::isfinite(best)) nearest.push_back(best);
        }
        double spacing = 1;
        if (!nearest.empty()) {
            std::nth_element(nearest.begin(),
                             nearest.begin() + static_cast<long>(nearest.size() / 2),
                             nearest.end());
            spacing = nearest[nearest.size() / 2];
        }
        reference.spacing = spacing;
        reference.restart_radius = restart_radius(reference, spacing);
    });
    return reference.spacing;
}

void check_motif_count(const ReferenceData& reference, double area, const Options& options) {
    // At the reference's spacing a panel holds at most about one motif per sqrt(3)/2 spacing^2
    // (the densest packing); max_elements caps it.
    const double spacing = ring_spacing(reference);
    double estimate = area / (std::sqrt(3.0) / 2 * spacing * spacing);
    if (options.max_elements > 0)
        estimate = std::min(estimate, static_cast<double>(options.max_elements));
    if (!(estimate > static_cast<double>(options.max_motifs))) return;
    char text[400];
    std::snprintf(text, sizeof text,
                  "growth: %s would grow about %.3g motifs in this panel (area %.4g at the "
                  "reference's spacing %.4g), more than the limit of %ld (Options::max_motifs, "
                  "--param growth_max_motifs); a larger reference spacing, a smaller panel or "
                  "growth_max_elements makes it fit",
                  reference.name.c_str(), estimate, area, spacing, options.max_motifs);
    throw InputError(text);
}

int Synthesis::priority(int symbol) const { return symbol >= 0 ? priority_[symbol] : 0; }

double Synthesis::excess(int symbol) const {
    if (symbol < 0 || coming_total_ == 0) return 0.0;
    const auto s = static_cast<std::size_t>(symbol);
    return static_cast<double>(coming_[s]) / static_cast<double>(coming_total_) -
           reference_share_[s];
}

void Synthesis::count_coming() {
    // The seeds waiting with a symbol are motifs of it to come: counted, so that a symbol the
    // front already carries too much of is not added again.
    coming_ = placed_per_symbol_;
    coming_total_ = static_cast<long>(placed_.size());
    for (const auto* seeds : {&queue_, &waiting_})
        for (auto [d, id] : *seeds) {
            const int symbol = pattern_[id].symbol;
            if (symbol < 0) continue;
            ++coming_[static_cast<std::size_t>(symbol)];
            ++coming_total_;
        }
}

int Synthesis::plant(const std::vector<Point>& starts) {
    int planted = 0;
    for (Point p : starts) {
        if (!p.finite() || !panel_.contains(p)) continue;
        starts_.push_back(p);
        int id = new_seed(p, -1);
        pattern_[id].fixed = true;  // the paper holds the initial element
        ++planted;
    }
    return planted;
}

int Synthesis::new_seed(Point p, int symbol) {
    Node n;
    n.position = p;
    n.symbol = symbol;
    n.start_distance = INFINITY;
    for (Point s : starts_) n.start_distance = std::min(n.start_distance, distance(s, p));
    int id = pattern_.add(std::move(n));
    queue_.insert({pattern_[id].start_distance, id});
    ++stats_.seeds;
    return id;
}

void Synthesis::drop(int seed) {
    queue_.erase({pattern_[seed].start_distance, seed});
    release(seed);
    pattern_.kill(seed);
    ++stats_.dropped;
}

bool Synthesis::blocked(int seed) const {
    const Node& s = pattern_[seed];
    for (int other : pattern_.near(s.position, options_.priority_radius * l_)) {
        const Node& o = pattern_[other];
        if (!o.placed() && priority(o.symbol) > priority(s.symbol)) return true;
    }
    return false;
}

int Synthesis::next_seed() {
    for (;;) {
        if (queue_.empty()) {
            if (waiting_.empty()) return -1;
            // Only blocked seeds left (a higher-priority seed that has moved away): all go back.
            for (auto entry : waiting_) {
                pattern_[entry.second].waiting = false;
                queue_.insert(entry);
            }
            waiting_.clear();
            auto first = *queue_.begin();
            queue_.erase(queue_.begin());
            return first.second;
        }
        auto entry = *queue_.begin();
        queue_.erase(queue_.begin());
        if (!priorities_differ_ || !blocked(entry.second)) return entry.second;
        pattern_[entry.second].waiting = true;
        waiting_.insert(entry);
    }
}

void Synthesis::release(int former_seed) {
    if (!priorities_differ_ || waiting_.empty()) return;
    const Node& f = pattern_[former_seed];
    const int level = priority(f.symbol);
    // A little beyond 5 l: relaxation may have moved a waiting seed since it was blocked.
    for (int other : pattern_.near(f.position, (options_.priority_radius + 2) * l_)) {
        Node& o = pattern_[other];
        if (!o.waiting || priority(o.symbol) >= level) continue;
        o.waiting = false;
        waiting_.erase({o.start_distance, other});
        queue_.insert({o.start_distance, other});
    }
}

// A restart needs an empty circle of at least one spacing (a motif there stands no closer to its
// neighbours than the reference's NN distance), and wider than most of the reference's own:
// kOwnHoleQuantile of its interior neighbourhoods' widest empty circles, times kOwnHoleMargin.
// Narrower holes are ones a faithful copy has (a honeycomb's hexagons, a Poisson set's gaps).
constexpr double kOwnHoleQuantile = 0.9;
constexpr double kOwnHoleMargin = 1.05;
// Holes come largest first and a fruitless restart changes nothing, so after this many in a row
// the smaller circles left would grow nothing either.
constexpr int kFruitlessInARow = 16;

double restart_radius(const ReferenceData& reference, double spacing) {
    std::vector<double> own = own_hole_radii(reference, spacing);
    return std::max(1.0, kOwnHoleMargin * quantile(own, kOwnHoleQuantile));
}

void Synthesis::run() {
    auto begin = std::chrono::steady_clock::now();
    auto room = [&] {
        return options_.max_elements == 0 ||
               static_cast<long>(placed_.size()) < options_.max_elements;
    };
    grow_front();
    bool reopened = false;  // since the last motif placed
    for (int in_a_row = 0;
         room() && in_a_row < kFruitlessInARow && options_.fill_holes && !starts_.empty();) {
        Hole hole;
        ++stats_.hole_searches;
        if (!holes().find(pattern_, restart_radius_ * spacing_, hole)) {
            // Before giving up, once after growth: relaxation may have opened a covered hole.
            if (reopened) break;
            holes_->reopen_covered();
            reopened = true;
            continue;
        }
        const std::size_t before = placed_.size();
        if (restart(hole)) grow_front();
        if (placed_.size() > before) {
            // Offered again while it stays as wide: each such restart adds a motif, so this ends.
            in_a_row = 0;
            reopened = false;
        } else {
            // Never retried; only its middle, as a seed off the middle may still grow there.
            holes_->exclude(hole.center, 0.5 * spacing_);
            ++stats_.fruitless;
            ++in_a_row;
        }
    }
    if (on_lattice() && room()) repair_lattice();
    balance_neighbours();
    match_spacing();
    stats_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

bool Synthesis::restart(const Hole& hole) {
    ++stats_.restarts;
    // Off a lattice, restarts fill the last gaps, where the mix has drifted most: the symbol
    // furthest under its reference share is wanted, at a place where it fits.
    const bool mixing = !lattice_ && reference_.symbols.size() > 1 && !placed_.empty();
    auto under = [&](std::size_t s) {
        return static_cast<double>(placed_per_symbol_[s]) / static_cast<double>(placed_.size()) -
               reference_share_[s];
    };
    auto fits = [&](Point q, int s) {
        if (too_close(-1, q, s, true) >= 0) return false;
        for (int c : candidates_)
            if (reference_.symbol[c] == s &&
                motif_fits(-1, q, reference_.radius[c] * options_.scale_min))
                return true;
        return false;
    };
    int wanted = -1;
    if (mixing) {
        double most = INFINITY;
        for (std::size_t s = 0; s < reference_share_.size(); ++s)
            if (under(s) < most) {
                most = under(s);
                wanted = static_cast<int>(s);
            }
    }
    // Next to motifs, the seed goes where one of them wants a neighbour (an open slot of its
    // reference ring, nearest the hole's centre), so a lattice continues in phase; in an empty
    // lobe it goes to the centre and grows afresh. Slots where the wanted symbol fits first.
    Point at = hole.center;
    int parent = -1, symbol = -1;
    for (int pass = wanted >= 0 ? 0 : 1; pass < 2 && parent < 0; ++pass) {
        double best = INFINITY;
        for (int other : pattern_.near(hole.center, hole.radius + spacing_)) {
            const Node& o = pattern_[other];
            if (!o.placed()) continue;
            for (const RingSlot& slot : reference_.rings[o.source]) {
                Point q = o.position + slot.offset.rotated(o.rotation);
                double r = reference_.radius[slot.element] * options_.scale_min;
                double d = distance(q, hole.center);
                if (d >= best || d > hole.radius || pattern_.nearest(q, 0.9 * spacing_, -1) >= 0 ||
                    !panel_.contains(q) || !panel_.reaches(o.position, q) ||
                    !motif_fits(-1, q, r) || pattern_.crosses(o.position, q, other, -1) ||
                    crowded(-1, q) || (pass == 0 && !fits(q, wanted)))
                    continue;
                best = d;
                at = q;
                parent = other;
                symbol = pass == 0 ? wanted : reference_.symbol[slot.element];
            }
        }
    }
    // Where the wanted symbol fits nowhere, the most wanted of those that fit (one that does not
    // would make the restart fruitless).
    if (mixing && (parent < 0 || symbol != wanted)) {
        double most = INFINITY;
        symbol = -1;
        for (std::size_t s = 0; s < reference_share_.size(); ++s)
            if (under(s) < most && fits(at, static_cast<int>(s))) {
                most = under(s);
                symbol = static_cast<int>(s);
            }
    }
    if (on_lattice()) {
        // The lattice continues in phase, also in an empty lobe.
        Lattice::Spot spot = lattice_->nearest(origin_, at);
        if (pattern_.nearest(spot.at, 0.5 * spacing_, -1) >= 0) return false;
        at = spot.at;
        symbol = lattice_->sites[static_cast<std::size_t>(spot.site)].symbol;
    }
    starts_.push_back(at);
    int id = new_seed(at, symbol);
    restart_seed_ = id;
    // Linked to the motifs around it, the seed is matched against them like any other.
    for (int other : pattern_.near(at, 1.6 * spacing_)) {
        const Node& o = pattern_[other];
        if (other == id || !o.placed() || !panel_.reaches(at, o.position) ||
            (other != parent && pattern_.crosses(at, o.position, id, other)))
            continue;
        pattern_.link(id, other, o.position - at);
    }
    return true;
}

HoleFinder& Synthesis::holes() {
    if (!holes_) {
        double smallest = INFINITY;
        for (double r : reference_.radius) smallest = std::min(smallest, r);
        // A few hundred samples per motif that may still be placed are plenty: a cap of 40 motifs
        // in a panel that holds a million needs no fine grid over all of it.
        double budget = 2.5e5;
        if (options_.max_elements > 0)
            budget = std::min(budget,
                              std::max(4096.0, 256.0 * static_cast<double>(options_.max_elements)));
        holes_.emplace(panel_, starts_, spacing_, smallest * options_.scale_min, tolerance_,
                       budget);
    }
    return *holes_;
}

double Synthesis::largest_hole() { return starts_.empty() ? 0.0 : holes().largest(pattern_); }

void Synthesis::grow_front() {
    while (!queue_.empty() || !waiting_.empty()) {
        if (options_.max_elements > 0 && static_cast<long>(placed_.size()) >= options_.max_elements)
            break;
        int seed = next_seed();
        if (seed < 0) break;
        ++stats_.steps;
        if (!panel_.contains(pattern_[seed].position)) {
            release(seed);
            pattern_.kill(seed);
            ++stats_.dropped;
            continue;
        }
        grow(seed);
    }
}

std::vector<OuterEntry> Synthesis::outer_ring(int seed, const std::vector<int>& ring_nodes,
                                              Point about) const {
    std::vector<OuterEntry> outer;
    std::vector<int> seen = ring_nodes;
    seen.push_back(seed);
    for (int n : ring_nodes)
        for (const Link& l : pattern_[n].links) {
            if (std::find(seen.begin(), seen.end(), l.node) != seen.end()) continue;
            seen.push_back(l.node);
            const Node& o = pattern_[l.node];
            if (o.placed()) outer.push_back({o.position - about, o.symbol});
        }
    return outer;
}

Synthesis::Choice Synthesis::choose(const Node& seed, const std::vector<RingEntry>& target,
                                    const std::vector<OuterEntry>& target_outer,
                                    const std::vector<int>& candidates) {
    // Section 5.2, eq. 1: the reference element minimizing ERROR; exact ties are drawn at random
    // so that a regular reference does not copy one element everywhere.
    std::vector<Choice> best;
    double best_error = INFINITY;
    // Flow mode turns the whole reference so that its x axis follows the field at the seed.
    const bool rotate = options_.mode == Mode::rotation;
    const double turn = flow_ ? flow_->angle(seed.position) : 0.0;
    const bool by_position = on_lattice();
    const bool balance = !by_position && options_.w4 > 0 && reference_.symbols.size() > 1;
    // The index holds every candidate: a restart's narrower list is matched in full.
    if (slot_index_ && &candidates == &candidates_ && !by_position && !target.empty() &&
        target_outer.empty())
        return choose_pruned(seed, target, turn, balance);
    for (int c : candidates) {
        if (!by_position && seed.symbol >= 0 && reference_.symbol[c] != seed.symbol) continue;
        std::vector<int> slots;
        RingMatch m =
            by_position ? match_by_position(target, rings_[c], weights_, 0.3 * spacing_, slots)
            : options_.two_ring
                ? match_two_ring(
                      target, rings_[c], target_outer, outer_rings_[c], weights_, rotate, turn,
                      0.5 * l_,
                      // w4 may lower an error, so nothing is cut early with it
                      best.empty() || balance ? INFINITY : best_error + 1e-9 * (1 + best_error))
                : match_ring(target, rings_[c], weights_, rotate, turn);
        if (!m.found()) continue;
        if (balance) m.error += options_.w4 * balance_over(seed, c, m.shift, target.size());
        // w4 may make errors negative: the slack stays positive.
        double slack = best.empty() ? 0.0 : 1e-9 * (1 + std::abs(best_error));
        if (best.empty() || m.error < best_error - slack) {
            best.clear();
            best_error = m.error;
        }
        if (m.error <= best_error + slack) best.push_back({c, m, std::move(slots)});
    }
    if (best.empty()) return {};
    if (best.size() == 1) return best.front();
    return best[static_cast<std::size_t>(
        random_.uniform_int(0, static_cast<long long>(best.size()) - 1))];
}

double Synthesis::balance_over(const Node& seed, int c, int shift, std::size_t targets) const {
    // The ring slots no target neighbour takes become seeds of their symbols.
    // Slot k is taken when it is within `targets` after `shift` round the ring; summed in slot
    // order (the same bits as marking them), without an allocation per alignment.
    const std::size_t size = rings_[c].size();
    double over = seed.symbol < 0 ? excess(reference_.symbol[c]) : 0.0;
    if (size == 0) return over;
    const std::size_t first = static_cast<std::size_t>(shift) % size;
    for (std::size_t k = 0; k < size; ++k)
        if ((k + size - first) % size >= targets) over += excess(rings_[c][k].symbol);
    return over;
}

bool Synthesis::motif_fits(int id, Point at, double radius) const {
    if (!panel_.admits({at, radius}, tolerance_)) return false;
    for (int other : pattern_.near(at, radius + pattern_.largest_radius())) {
        const Node& o = pattern_[other];
        if (other == id || !o.placed()) continue;
        if (distance(o.position, at) < radius + o.radius - tolerance_) return false;
    }
    return true;
}

int Synthesis::too_close(int id, Point at, int symbol, bool placed_only) const {
    if (on_lattice() || gap_max_ <= 0) return -1;
    const std::size_t symbols = reference_.symbols.size();
    int best = -1;
    double best_distance = INFINITY;
    for (int other : pattern_.near(at, gap_max_)) {
        const Node& o = pattern_[other];
        if (other == id || (placed_only && !o.placed())) continue;
        double gap = 0;
        if (symbol >= 0 && o.symbol >= 0)
            gap = gap_[static_cast<std::size_t>(symbol) * symbols +
                       static_cast<std::size_t>(o.symbol)];
        else if (symbol >= 0 || o.symbol >= 0)
            gap = gap_any_[static_cast<std::size_t>(symbol >= 0 ? symbol : o.symbol)];
        const double d = distance(o.position, at);
        if (d < gap && d < best_distance) {
            best = other;
            best_distance = d;
        }
    }
    return best;
}

bool Synthesis::crowded(int id, Point at) const {
    if (on_lattice() || crowd_limit_ <= 0) return false;
    // Counted in place, stopping as soon as a count is over: this runs per seed, per restart
    // candidate and per relaxation move.
    auto over = [&](Point p, int self, int limit, auto each) {
        int count = 0;
        return pattern_.any_near(p, crowd_reach_, [&](int other) {
            const Node& o = pattern_[other];
            if (other == id || other == self || !o.placed() ||
                !(distance(o.position, p) < crowd_reach_))
                return false;
            return ++count > limit || each(other);
        });
    };
    // A neighbour gains the motif at `at` too: over when it has crowd_limit_ others already.
    return over(at, -1, crowd_limit_, [&](int other) {
        return over(pattern_[other].position, other, crowd_limit_ - 1, [](int) { return false; });
    });
}

void Synthesis::grow(int id) {
    const std::vector<int>* candidates = &candidates_;
    if (on_lattice()) {
        Lattice::Spot spot = lattice_->nearest(origin_, pattern_[id].position);
        if (spot.residual > kOffLattice * spacing_) return drop(id);
        int other = pattern_.nearest(spot.at, 0.5 * spacing_, id);
        if (other >= 0 && pattern_[other].placed()) return drop(id);
        pattern_.move(id, spot.at);
        candidates = &lattice_->sites[static_cast<std::size_t>(spot.site)].candidates;
    } else if (lattice_ && !phase_ && options_.lattice_phase && !phase_tried_) {
        // Once: a first motif that cannot stand there leaves the next seeds as they are.
        phase_tried_ = true;
        if (const auto first = lattice_phase(pattern_[id].position)) {
            pattern_.move(id, first->at);
            candidates = &lattice_->sites[static_cast<std::size_t>(first->site)].candidates;
        }
    }
    // A near-regular reference, once its lattice is down: the seed's site is the one nearest
    // it; a taken site (or a honeycomb's hexagon centre) holds no motif, and on a honeycomb an
    // element of the site's own sublattice is copied there.
    std::pair<long, long> site{0, 0};
    bool on_site = jittered_ && shift_;
    if (on_site) {
        site = jittered_->index(pattern_[id].position - *shift_);
        const int sublattice = JitteredLattice::sublattice(site);
        const bool honeycomb = jittered_->vacant >= 0;
        if ((honeycomb && sublattice == jittered_->vacant) || taken_sites_.count(site) > 0) {
            // A restart fills a hole the lattice leaves (at the panel's edge): off its sites.
            if (id != restart_seed_) return drop(id);
            on_site = false;
        } else if (honeycomb && !sublattice_candidates_[sublattice].empty()) {
            candidates = &sublattice_candidates_[sublattice];
        }
    }
    // The target neighbourhood w(e_tar): linked elements and seeds, CCW from the open side.
    // On a site, about the site (the rings are taken about their elements' sites).
    std::vector<Vector> offsets;
    std::vector<int> neighbours;
    const Point about = on_site ? jittered_->site_at(site) + *shift_ : pattern_[id].position;
    for (const Link& l : pattern_[id].links) {
        neighbours.push_back(l.node);
        offsets.push_back(pattern_[l.node].position - about);
    }
    std::vector<RingEntry> target;
    std::vector<int> target_nodes;
    for (int k : ccw_from_widest_gap(offsets)) {
        const Node& n = pattern_[neighbours[k]];
        target.push_back({offsets[k], n.symbol, n.source});
        target_nodes.push_back(neighbours[k]);
    }
    if (options_.w4 > 0 && reference_.symbols.size() > 1 && !on_lattice()) count_coming();
    Choice choice = choose(pattern_[id], target,
                           options_.two_ring && !on_lattice() ? outer_ring(id, target_nodes, about)
                                                              : std::vector<OuterEntry>{},
                           *candidates);
    if (choice.element < 0) return drop(id);
    double scale = random_.uniform(options_.scale_min, options_.scale_max);
    double jitter = options_.angle_jitter > 0
                        ? random_.uniform(-options_.angle_jitter, options_.angle_jitter)
                        : 0.0;
    double tint = options_.color_variation > 0
                      ? random_.uniform(-options_.color_variation, options_.color_variation)
                      : 0.0;
    double radius = reference_.radius[choice.element] * scale;
    // A fitted motif was checked where it now stands.
    const bool fitted = jittered_ && (!shift_ || on_site) &&
                        fit_to_site(id, choice.element, radius, on_site ? &site : nullptr);
    if (!fitted && !motif_fits(id, pattern_[id].position, radius) && id == restart_seed_) {
        // A restart's hole holds the smallest motif, maybe not the best match: the best of
        // those that fit there (else the hole stays, its middle closed).
        std::vector<int> fitting;
        for (int c : *candidates)
            if (motif_fits(id, pattern_[id].position, reference_.radius[c] * scale))
                fitting.push_back(c);
        if (!fitting.empty()) {
            choice = choose(pattern_[id], target, {}, fitting);
            if (choice.element < 0) return drop(id);
            radius = reference_.radius[choice.element] * scale;
        }
    }
    if (!fitted) {
        if (!motif_fits(id, pattern_[id].position, radius)) return drop(id);
        // Fronts meeting (and relaxation) can bring a seed closer to a motif than the reference
        // ever has those symbols: the reference's own closest spacing holds.
        if (too_close(id, pattern_[id].position, reference_.symbol[choice.element], true) >= 0 ||
            crowded(id, pattern_[id].position))
            return drop(id);
    }

    Node& n = pattern_[id];
    const int c = choice.element;
    n.source = c;
    n.symbol = reference_.symbol[c];
    n.rotation = choice.match.rotation;
    n.angle = reference_.elements[c].angle + n.rotation + jitter;
    n.scale = scale;
    n.tint = tint;
    n.radius = radius;
    pattern_.note_radius(radius);
    placed_.push_back(id);
    ++placed_per_symbol_[static_cast<std::size_t>(n.symbol)];
    release(id);
    // Thousands of motifs are one rule body: the watchdog needs to see them coming.
    report_progress("motifs", static_cast<long>(placed_.size()), options_.max_elements);
    // The motifs so far, for a partial picture while the growth goes on (the elements are made
    // only by the copy of the program that draws it).
    if (PartialMaker make = g_partial_maker.get())
        report_partial(static_cast<long>(placed_.size()),
                       [this, make](std::vector<const Element*>& out) {
                           for (const Motif& m : result().motifs) out.push_back(make(m));
                       });
    if (lattice_ && !phase_) {
        // The first motif puts the lattice down: its site's point is where it stands.
        phase_ = true;
        origin_ =
            n.position - lattice_->sites[static_cast<std::size_t>(lattice_->site_of[c])].offset;
    }
    const auto& ring = reference_.rings[c];
    for (std::size_t i = 0; i < target_nodes.size(); ++i) {
        int slot = choice.slot(i, ring.size());
        if (slot >= 0)
            pattern_.set_desired(id, target_nodes[i],
                                 ring[static_cast<std::size_t>(slot)].offset.rotated(n.rotation));
    }
    spawn(id, choice, target_nodes);
    if (options_.relax) relax_around(id);
}

bool Synthesis::fit_to_site(int id, int element, double radius, const std::pair<long, long>* site) {
    const JitteredLattice& lattice = *jittered_;
    const Point at = pattern_[id].position;
    const Vector own = lattice.jitter[static_cast<std::size_t>(element)];
    // The first fitted motif puts the lattice down: its element's site where it stands.
    const Vector shift =
        shift_ ? *shift_ : (at - own) - lattice.site[static_cast<std::size_t>(element)];
    const std::pair<long, long> index = site ? *site : lattice.index(at - own - shift);
    const Point fitted = lattice.site_at(index) + shift + own;
    if (!panel_.contains(fitted) || !panel_.reaches(at, fitted)) return false;
    pattern_.move(id, fitted);
    if (motif_fits(id, fitted, radius) &&
        too_close(id, fitted, reference_.symbol[static_cast<std::size_t>(element)], true) < 0 &&
        !crowded(id, fitted)) {
        shift_ = shift;
        taken_sites_.insert(index);
        fitted_sites_.push_back({id, fitted - own});
        // On its site: relaxation (whose links a honeycomb's uneven rings misalign) holds it.
        pattern_[id].fixed = true;
        ++stats_.fitted;
        return true;
    }
    pattern_.move(id, at);
    return false;
}

bool Synthesis::still_valid(int id) const {
    const Node& n = pattern_[id];
    return n.placed()
               ? motif_fits(id, n.position, n.radius) &&
                     too_close(id, n.position, n.symbol, true) < 0 && !crowded(id, n.position)
               : panel_.contains(n.position);
}

void Synthesis::relax_around(int centre) {
    auto begin = std::chrono::steady_clock::now();
    // Unknowns: the free nodes in the window; their linked nodes outside it hold still.
    std::map<int, int> local;
    std::vector<Point> positions;
    std::vector<int> free_local, free_nodes;
    std::vector<int> window;
    if (options_.relax_global) {
        for (int id = 0; id < static_cast<int>(pattern_.nodes().size()); ++id)
            if (pattern_[id].alive) window.push_back(id);
    } else {
        window = pattern_.near(pattern_[centre].position, options_.relax_radius * l_);
    }
    for (int id : window) {
        const Node& n = pattern_[id];
        if (n.fixed || n.links.empty()) continue;
        local.emplace(id, static_cast<int>(positions.size()));
        free_local.push_back(static_cast<int>(positions.size()));
        free_nodes.push_back(id);
        positions.push_back(n.position);
    }
    if (free_nodes.empty()) return;
    std::vector<Spring> springs;
    for (int id : free_nodes) {
        for (const Link& l : pattern_[id].links) {
            auto [it, fresh] = local.emplace(l.node, static_cast<int>(positions.size()));
            if (fresh) positions.push_back(pattern_[l.node].position);
            springs.push_back({local[id], it->second, l.desired});
            if (!std::binary_search(free_nodes.begin(), free_nodes.end(), l.node))
                for (const Link& back : pattern_[l.node].links)
                    if (back.node == id) springs.push_back({it->second, local[id], back.desired});
        }
    }
    // Slack: a link within relax_slack * l of its offset holds as it stands (the reference's own
    // jitter, which pulling every link to one ring's offset would even out); a link further off
    // is pulled only back to that distance.
    const double slack = options_.relax_slack * l_;
    for (Spring& s : springs) {
        Vector now =
            positions[static_cast<std::size_t>(s.to)] - positions[static_cast<std::size_t>(s.from)];
        Vector miss = now - s.desired;
        double length = miss.length();
        s.desired = length <= slack ? now : s.desired + miss * (slack / length);
    }
    relax(positions, springs, free_local);
    // Apply, then put back any node whose motif would now overlap or leave the panel, until the
    // moved ones are all valid (all put back is the old, valid state).
    std::vector<std::pair<int, Point>> moved;
    for (std::size_t k = 0; k < free_nodes.size(); ++k) {
        int id = free_nodes[k];
        Point old = pattern_[id].position;
        if (positions[free_local[k]] == old) continue;
        moved.push_back({id, old});
        pattern_.move(id, positions[free_local[k]]);
    }
    for (bool changed = true; changed;) {
        changed = false;
        for (auto& [id, old] : moved) {
            if (pattern_[id].position == old ||
                (still_valid(id) && panel_.reaches(old, pattern_[id].position)))
                continue;
            pattern_.move(id, old);
            changed = true;
        }
    }
    stats_.relax_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

SynthesisResult Synthesis::result() const {
    SynthesisResult r;
    std::map<int, int> index;
    for (int id : placed_) {
        const Node& n = pattern_[id];
        index[id] = static_cast<int>(r.motifs.size());
        const ReferenceElement& e = reference_.elements[n.source];
        r.motifs.push_back(
            {n.position, e.symbol, e.label, n.angle, n.scale, n.radius, n.source, n.tint});
    }
    for (int id : placed_)
        for (const Link& l : pattern_[id].links) {
            auto it = index.find(l.node);
            if (it != index.end() && index[id] < it->second)
                r.edges.emplace_back(index.at(id), it->second);
        }
    std::sort(r.edges.begin(), r.edges.end());
    r.stats = stats_;
    double sum = 0;
    long links = 0;
    for (int id : placed_)
        for (const Link& l : pattern_[id].links)
            if (pattern_[l.node].placed()) {
                Vector miss = (pattern_[l.node].position - pattern_[id].position) - l.desired;
                sum += miss.dot(miss);
                ++links;
            }
    r.stats.link_error = links > 0 ? std::sqrt(sum / static_cast<double>(links)) / l_ : 0.0;
    return r;
}

}  // namespace acanthus::growth::detail
