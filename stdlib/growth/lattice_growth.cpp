// Growth on a detected lattice after the fronts stop: empty lattice points next to motifs get
// seeds (completion), and motifs whose ring matches no reference ring are removed and grown again
// locally (repair). Neither runs without a lattice (irregular references keep the paper's growth).
#include <algorithm>
#include <cmath>

#include "synthesis.hpp"

namespace acanthus::growth::detail {

int Synthesis::plant_on_lattice(const Lattice::Spot& spot, Point from) {
    const Lattice::Site& site = lattice_->sites[static_cast<std::size_t>(spot.site)];
    if (pattern_.nearest(spot.at, 0.5 * spacing_, -1) >= 0 || !panel_.contains(spot.at) ||
        !panel_.reaches(from, spot.at))
        return -1;
    double smallest = INFINITY;
    for (int c : site.candidates) smallest = std::min(smallest, reference_.radius[c]);
    if (!motif_fits(-1, spot.at, smallest * options_.scale_min)) return -1;
    int seed = new_seed(spot.at, site.symbol);
    // Linked as the site's ring links it (any of its elements: on a lattice their rings agree).
    for (const RingSlot& slot : reference_.rings[site.candidates.front()]) {
        Point q = spot.at + slot.offset;
        int other = pattern_.nearest(q, kOffLattice * spacing_, seed);
        if (other < 0 || !pattern_[other].placed() || pattern_.linked(seed, other)) continue;
        Point po = pattern_[other].position;
        if (!panel_.reaches(spot.at, po) || pattern_.crosses(spot.at, po, seed, other)) continue;
        pattern_.link(seed, other, slot.offset);
    }
    ++stats_.completed;
    return seed;
}

void Synthesis::complete_lattice() {
    auto room = [&] {
        return options_.max_elements == 0 ||
               static_cast<long>(placed_.size()) < options_.max_elements;
    };
    // Each round plants around the motifs of the last; the lattice points are finite, and each
    // is planted at most once (again only after the repair empties it).
    while (room()) {
        bool planted = false;
        const std::vector<int> motifs = placed_;
        for (int id : motifs) {
            if (!pattern_[id].alive || !pattern_[id].placed()) continue;
            // Copied: planting adds nodes, which may move the pattern's storage.
            const Point at = pattern_[id].position;
            const auto source = pattern_[id].source;
            for (const RingSlot& slot : reference_.rings[source]) {
                Lattice::Spot spot = lattice_->nearest(origin_, at + slot.offset);
                if (spot.residual > kOffLattice * spacing_) continue;
                if (!options_.fill_holes && !reopened_.count(spot)) continue;
                if (planted_spots_.count(spot) && !reopened_.count(spot)) continue;
                if (plant_on_lattice(spot, at) < 0) continue;
                planted_spots_.insert(spot);
                reopened_.erase(spot);
                planted = true;
            }
        }
        if (!planted) break;
        grow_front();
    }
    reopened_.clear();
}

void Synthesis::remove_motif(int id) {
    reopened_.insert(lattice_->nearest(origin_, pattern_[id].position));
    --placed_per_symbol_[static_cast<std::size_t>(pattern_[id].symbol)];
    pattern_.kill(id);
    placed_.erase(std::find(placed_.begin(), placed_.end(), id));
    ++stats_.repaired;
}

// A few rounds: each removes what the checker finds and regrows it; a defect that comes back
// (a lattice point the panel or the ornament leaves no room for) is left after the last.
constexpr int kRepairRounds = 3;

void Synthesis::repair_lattice() {
    complete_lattice();
    const RingChecker& checker = profile_of(reference_).checker;
    for (int round = 0; round < kRepairRounds; ++round) {
        std::vector<Point> points;
        std::vector<int> symbols;
        for (int id : placed_) {
            points.push_back(pattern_[id].position);
            symbols.push_back(pattern_[id].symbol);
        }
        const std::vector<bool> good = checker.good(points, symbols);
        std::vector<int> remove;
        auto misplaced = [&](int id) {
            const Node& n = pattern_[id];
            Lattice::Spot spot = lattice_->nearest(origin_, n.position);
            return spot.residual > lattice_->tolerance ||
                   lattice_->sites[static_cast<std::size_t>(spot.site)].symbol != n.symbol;
        };
        for (std::size_t k = 0; k < placed_.size(); ++k) {
            const int id = placed_[k];
            if (good[k] || panel_.clearance(points[k]) < checker.interior_clearance()) continue;
            if (!pattern_[id].fixed) remove.push_back(id);
            for (int other : pattern_.near(points[k], checker.reach()))
                if (other != id && pattern_[other].placed() && !pattern_[other].fixed &&
                    misplaced(other))
                    remove.push_back(other);
        }
        std::sort(remove.begin(), remove.end());
        remove.erase(std::unique(remove.begin(), remove.end()), remove.end());
        if (remove.empty()) break;
        for (int id : remove) remove_motif(id);
        complete_lattice();
    }
}

}  // namespace acanthus::growth::detail
