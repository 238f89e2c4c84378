// Section 5: synthesis by local growth. Seeds are taken nearest-first from the start (respecting
// symbol priorities), each replaced by the reference element whose 1-ring best matches its
// neighbourhood, whose unmatched ring neighbours become new seeds (section 5.4 heuristics), and
// the pattern around it is relaxed (section 5.5) in a window, so a step costs the same at any size.
#pragma once

#include <acanthus/random.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <cstdint>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include "arrangement.hpp"
#include "fidelity.hpp"
#include "flow_field.hpp"
#include "hole_finder.hpp"
#include "lattice.hpp"
#include "near_regular.hpp"
#include "neighbourhood_match.hpp"
#include "panel.hpp"
#include "reference.hpp"

namespace acanthus::growth::detail {

// Interior reference elements matched at most (a larger reference: an even sample of them).
inline constexpr std::size_t kMaxCandidates = 8192;

// A seed farther than this (in spacings) from every lattice point is not on the lattice.
inline constexpr double kOffLattice = 0.3;

// The reference's median nearest-neighbour distance through its rings.
double ring_spacing(const ReferenceData& reference);
// Throws InputError, with the estimate, when a panel of this area would hold more than
// Options::max_motifs motifs at the reference's spacing (max_elements caps the estimate).
void check_motif_count(const ReferenceData& reference, double area, const Options& options);
// The radius (in units of `spacing`) an empty circle needs before growth restarts in it: wider
// than what the reference itself leaves open (own_holes.hpp).
double restart_radius(const ReferenceData& reference, double spacing);

class Synthesis {
  public:
    Synthesis(const ReferenceData& reference, const Panel& panel, const Options& options,
              Random& random);

    // Start seeds outside the panel are skipped; returns how many were planted.
    int plant(const std::vector<Point>& starts);
    void run();
    SynthesisResult result() const;
    // The reference's median nearest-neighbour distance (the spacing holes are measured in).
    double spacing() const { return spacing_; }
    // The largest empty circle left where a motif fits, as a radius (0 without a panel box).
    double largest_hole();
    const Arrangement& arrangement() const { return pattern_; }
    // For tests that set up or disturb a pattern by hand before run() or repair().
    Arrangement& arrangement() { return pattern_; }
    // The lattice repair on the pattern as it is (run() ends with it on a lattice).
    void repair() {
        if (on_lattice()) repair_lattice();
    }
    bool lattice_found() const { return lattice_ != nullptr; }
    // Tests compare the pruned choice with matching every candidate.
    void set_pruning(bool on) {
        if (!on)
            slot_index_.reset();
        else if (!slot_index_ && prunable_)
            build_slot_index();
    }

  private:
    struct Choice {
        int element = -1;
        RingMatch match;
        // On a lattice: the ring slot each target neighbour pairs with (-1: none), by position.
        std::vector<int> slots;
        // The reference ring slot target neighbour i pairs with, or -1.
        int slot(std::size_t i, std::size_t ring_size) const {
            if (!slots.empty()) return slots[i];
            return static_cast<int>((static_cast<std::size_t>(match.shift) + i) % ring_size);
        }
    };

    // Section 5.1: takes the nearest seed that no higher-priority seed within 5 l blocks off the
    // queue (-1: none). A blocked seed waits aside until a higher-priority seed near it stops
    // being a seed (release), so the queue is not scanned again at every step.
    int next_seed();
    bool blocked(int seed) const;
    void release(int former_seed);
    void grow_front();
    // Plants a seed in `hole` (the largest empty circle that holds a motif at the reference's
    // spacing), linked to the motifs around it; false when none could be planted. Off a
    // lattice its symbol is the one furthest under its reference share.
    bool restart(const Hole& hole);
    HoleFinder& holes();  // made on first use, over the starts planted by then
    void grow(int seed);
    Choice choose(const Node& seed, const std::vector<RingEntry>& target,
                  const std::vector<OuterEntry>& target_outer, const std::vector<int>& candidates);
    // Placed neighbours of the 1-ring nodes, beyond the seed and its 1-ring (Options::two_ring).
    // Offsets from `about` (the seed, or its site on a near-regular reference's lattice).
    std::vector<OuterEntry> outer_ring(int seed, const std::vector<int>& ring_nodes,
                                       Point about) const;
    bool motif_fits(int id, Point at, double radius) const;
    // Off a lattice: the node nearest `at` (other than `id`; placed motifs only when
    // `placed_only`) that a `symbol` would stand closer to than the reference ever puts those
    // two symbols (gap_), or -1.
    int too_close(int id, Point at, int symbol, bool placed_only) const;
    // Off a lattice, the crowding rule: a motif at `at` (node `id`, or -1) would give itself or a
    // placed neighbour more motifs within crowd_reach_ than any interior reference element has
    // (a near-regular reference's own holes, which the spacing rule alone lets fill). Relaxation
    // moves that would crowd are undone too.
    bool crowded(int id, Point at) const;
    // Section 5.4: new seeds from the chosen ring, merged, dropped or extended by the heuristics.
    void spawn(int centre, const Choice& choice, const std::vector<int>& target_nodes);
    void link_ring_pair(int centre, int a, int b, double original, Vector desired);
    int new_seed(Point p, int symbol);
    void drop(int seed);
    void relax_around(int centre);
    bool still_valid(int id) const;
    // A near-regular reference (jittered_): moves seed `id` to lattice site `site` (null: the
    // first motif, which puts the lattice down at its element's site) plus the element's own
    // jitter, when valid there, and holds it there. True when moved (checked once, here). All
    // motifs on the one lattice: sites taken from the neighbours' ring slots drift, as a ring
    // pairs its slots with the neighbours in turn and a jittered ring's slots (a grid's sides
    // and some diagonals, a honeycomb's bonds and some hexagon diagonals) need not be the
    // lattice steps they stand for.
    bool fit_to_site(int id, int element, double radius, const std::pair<long, long>* site);
    int priority(int symbol) const;
    // Options::w4: how far `symbol` is over its reference share among the placed motifs and the
    // waiting seeds (as count_coming() last counted them).
    double excess(int symbol) const;
    void count_coming();

    // On a lattice (lattice.hpp; Options::lattice, mode none): every seed is put on the lattice
    // point nearest it before it grows, or dropped when none is within a third of the spacing;
    // its candidates are the reference elements of that point's site, paired with its
    // neighbours by position.
    bool on_lattice() const { return lattice_ && phase_; }
    // Seeds on the empty lattice points next to motifs (all of them with fill_holes, else only
    // the points `repair` emptied), grown until none is left.
    void complete_lattice();
    // A seed on lattice point `spot`, linked to the motifs on its site's ring; -1 when the
    // point is taken, outside, or no motif of its site fits there.
    int plant_on_lattice(const Lattice::Spot& spot, Point from);
    // Where the first motif goes (its seed's place or half a cell from it) and which site it
    // takes (the lattice's phase): of the phases under which the panel holds the most lattice
    // points, the one whose points come nearest the reference's symbol shares per cell (a
    // stripe or a colour more or less where the panel's edge cuts the lattice). None: as
    // matched (one symbol, or a panel too large to count).
    struct Phase {
        int site = -1;
        Point at;
    };
    std::optional<Phase> lattice_phase(Point start) const;
    // Motifs whose ring matches no reference ring (RingChecker), with their neighbours that lie
    // off the lattice or carry another site's symbol, removed and grown again, a few rounds.
    void repair_lattice();
    // Irregular references (Options::neighbour_share): motifs of two symbols exchange their
    // reference elements until the close pairs' same-symbol share is the reference's
    // (neighbour_share.cpp).
    void balance_neighbours();
    // A near-regular reference (Options::match_spacing): the fitted motifs' jitter scaled by one
    // factor until the NN median is the reference's (spacing_match.cpp).
    void match_spacing();
    void remove_motif(int id);

    const ReferenceData& reference_;
    const Panel& panel_;
    const Options& options_;
    Random& random_;
    Weights weights_;
    std::optional<FlowField> flow_;
    std::vector<std::vector<RingEntry>> rings_;  // per reference element, unrotated
    // Per pair of symbols (row-major), the shortest connectivity edge between them in the
    // reference, times Options::gap_factor; gap_any_ per symbol the shortest to any symbol (for
    // seeds without one). Irregular growth keeps the reference's own closest spacing.
    std::vector<double> gap_, gap_any_;
    double gap_max_ = 0;
    double crowd_reach_ = 0;  // 1.2 NN (RingChecker::reach)
    int crowd_limit_ = 0;     // ReferenceProfile::most_neighbours; 0: no rule
    std::vector<std::vector<OuterEntry>> outer_rings_;  // per reference element (two_ring only)
    // Candidate pruning (mode none or flow, 1-ring): every (candidate, ring slot) by the slot's
    // offset on a grid, so that a seed evaluates only the alignments whose first pair is close
    // enough to beat the best error so far (prune.cpp).
    struct SlotEntry {
        Vector slot[3];  // slot k's offset and the next two (cyclically)
        int element = -1, shift = 0, symbol = -1, slots = 0;
        int candidate = -1;  // its place in candidates_ (the index's rings_ below)
    };
    struct SlotGroup {
        long x = 0, y = 0;       // the next slot's cell
        int symbol = -1;         // its entries' element's symbol
        int begin = 0, end = 0;  // its entries
    };
    struct SlotIndex {
        double cell = 0;
        long lo = 0, hi = -1;            // the cell coordinates of first slots, both axes
        int max_slots = 0;               // the largest ring
        std::vector<SlotEntry> entries;  // grouped by first slot's cell, symbol, next slot's cell
        std::unordered_map<std::int64_t, std::vector<SlotGroup>> cells;  // looked up only
        // The candidates' rings side by side (candidate k's from ring_begin[k]), and their
        // symbols alone: what a choice reads of them, packed.
        std::vector<RingEntry> rings;
        std::vector<int> ring_symbols;
        std::vector<int> ring_begin;
    };
    void build_slot_index();
    // choose() over the index: the same choice as matching every candidate, with the w4 term
    // when `balance`.
    Choice choose_pruned(const Node& seed, const std::vector<RingEntry>& target, double turn,
                         bool balance);
    // The w4 term's sum of excess() for reference element c aligned at `shift` with `targets`
    // target neighbours: its own symbol for a seed without one, and its ring's untaken slots.
    double balance_over(const Node& seed, int c, int shift, std::size_t targets) const;
    std::optional<SlotIndex> slot_index_;
    bool prunable_ = false;
    std::vector<int> seen_;      // per candidate: the choose_pruned call that last found it
    std::vector<int> found_at_;  // per candidate found in this call: its place in `found`
    // Per candidate, in the choose_pruned call of bounded_ (else stale): the least and the most
    // w4 term over its ring's shifts.
    std::vector<int> bounded_;
    std::vector<double> balance_low_, balance_high_;
    int seen_generation_ = 0;
    std::vector<int> candidates_;  // the reference's, or an even sample of a huge one
    std::vector<int> priority_;    // per symbol id
    bool priorities_differ_ = false;
    double l_ = 1, l_short_ = 0.5, tolerance_ = 0;
    double spacing_ = 1;
    double restart_radius_ = 1.1;  // in spacings (restart_radius)
    std::optional<HoleFinder> holes_;
    const Lattice* lattice_ = nullptr;  // the reference's (lattice_of), when used
    // Off a lattice, a near-regular reference's sites and jitter (fit_jittered_lattice).
    std::optional<JitteredLattice> jittered_;
    // Where the first fitted motif put the jittered lattice (grown site = reference site +
    // shift_), and the sites taken (lattice coordinates).
    std::optional<Vector> shift_;
    std::set<std::pair<long, long>> taken_sites_;
    std::vector<std::pair<int, Point>> fitted_sites_;  // (node, its site), in placement order
    // A honeycomb's candidates per sublattice: a site's bonds point one of two ways, and an
    // element copied onto a site of the other way would put its ring seeds in hexagon centres.
    std::vector<int> sublattice_candidates_[3];
    bool phase_ = false;        // the lattice's origin is set (by the first motif)
    bool phase_tried_ = false;  // lattice_phase() asked (for the first seed grown)
    Point origin_;
    std::set<Lattice::Spot> planted_spots_;  // completion seeds, each point once
    std::set<Lattice::Spot> reopened_;       // emptied by the repair
    Arrangement pattern_;
    std::set<std::pair<double, int>> queue_;    // (distance from the start, node)
    std::set<std::pair<double, int>> waiting_;  // blocked seeds, the same way
    std::vector<Point> starts_;
    std::vector<int> placed_;
    int restart_seed_ = -1;                // the last restart's seed
    std::vector<long> placed_per_symbol_;  // per symbol id
    std::vector<double> reference_share_;  // per symbol id
    std::vector<long> coming_;             // per symbol id: placed and waiting (count_coming)
    long coming_total_ = 0;
    SynthesisStats stats_;
};

}  // namespace acanthus::growth::detail
