// Growth on a detected lattice after the fronts stop: empty lattice points next to motifs get
// seeds (completion), and motifs whose ring matches no reference ring are removed and grown again
// locally (repair). Neither runs without a lattice (irregular references keep the paper's growth).
#include <algorithm>
#include <climits>
#include <cmath>
#include <iterator>
#include <optional>

#include "synthesis.hpp"

namespace acanthus::growth::detail {
namespace {

// Lattice points tried over all phases at most; a larger panel takes the first motif's site as
// it is matched, where its seed is.
constexpr double kMostPhasePoints = 40000;
// Shifts of the first motif from its seed tried, in lattice coordinates each way (the seed's
// own place first).
constexpr double kShifts[] = {0.0, 0.25, -0.25, 0.5};
// A point lost weighs as this many times its share of the points in the mix's error.
constexpr double kLostPoint = 3;

}  // namespace

std::optional<Synthesis::Phase> Synthesis::lattice_phase(Point start) const {
    const std::size_t sites = lattice_->sites.size();
    const std::size_t symbols = reference_.symbols.size();
    std::vector<double> share(symbols, 0.0);
    for (const Lattice::Site& site : lattice_->sites)
        share[static_cast<std::size_t>(site.symbol)] += 1.0 / static_cast<double>(sites);
    bool mixed = false;
    for (double v : share) mixed = mixed || (v > 0 && v < 1);
    const Rect box = panel_.bounds();
    const double det = lattice_->t1.cross(lattice_->t2);
    if (!mixed || panel_.symmetric() || !(box.width() > 0) || !(std::abs(det) > 0))
        return std::nullopt;
    const double cells = box.width() * box.height() / std::abs(det);
    const double shifts = std::size(kShifts) * std::size(kShifts);
    if (cells * static_cast<double>(sites * sites) * shifts > kMostPhasePoints) return std::nullopt;
    std::vector<double> smallest(sites, INFINITY);
    for (std::size_t k = 0; k < sites; ++k)
        for (int c : lattice_->sites[k].candidates)
            smallest[k] = std::min(smallest[k], reference_.radius[c] * options_.scale_min);
    // The lattice points: the region alone (its edge, not what stands in it), as the engine's
    // full test per point would cost more than the growth of a small panel. The first motif
    // itself must stand where it goes (clear of what stands there, its own images under a
    // symmetry group too).
    auto holds = [&](Point q, double radius) {
        return panel_.contains(q) && panel_.clearance(q) >= radius - tolerance_;
    };
    struct Tried {
        Phase phase;
        long total;
        double error;
    };
    std::vector<Tried> tried;
    for (double sa : kShifts)
        for (double sb : kShifts)
            for (std::size_t first = 0; first < sites; ++first) {
                const Vector shift = lattice_->t1 * sa + lattice_->t2 * sb;
                const Point at = start + shift;
                if (!std::isfinite(smallest[first]) || !panel_.contains(at) ||
                    !panel_.reaches(start, at) || !panel_.admits({at, smallest[first]}, tolerance_))
                    continue;
                // The lattice put down by a first motif of site `first` there.
                const Point origin = at - lattice_->sites[first].offset;
                long lo[2] = {LONG_MAX, LONG_MAX}, hi[2] = {LONG_MIN, LONG_MIN};
                for (Point corner : {Point{box.x0, box.y0}, Point{box.x1, box.y0},
                                     Point{box.x0, box.y1}, Point{box.x1, box.y1}}) {
                    const Vector d = corner - origin;
                    const double a = d.cross(lattice_->t2) / det, b = lattice_->t1.cross(d) / det;
                    lo[0] = std::min(lo[0], static_cast<long>(std::floor(a)) - 1);
                    hi[0] = std::max(hi[0], static_cast<long>(std::ceil(a)) + 1);
                    lo[1] = std::min(lo[1], static_cast<long>(std::floor(b)) - 1);
                    hi[1] = std::max(hi[1], static_cast<long>(std::ceil(b)) + 1);
                }
                // What the panel holds of it: the points where the site's smallest motif fits.
                std::vector<long> count(symbols, 0);
                long total = 0;
                for (std::size_t k = 0; k < sites; ++k) {
                    const Lattice::Site& site = lattice_->sites[k];
                    if (!std::isfinite(smallest[k])) continue;
                    for (long i = lo[0]; i <= hi[0]; ++i)
                        for (long j = lo[1]; j <= hi[1]; ++j) {
                            const Point q = lattice_->point(origin, static_cast<int>(k), i, j);
                            if (!box.contains(q) || !holds(q, smallest[k])) continue;
                            ++count[static_cast<std::size_t>(site.symbol)];
                            ++total;
                        }
                }
                if (total == 0) continue;
                double error = 0;
                for (std::size_t sym = 0; sym < symbols; ++sym)
                    error = std::max(error, std::abs(static_cast<double>(count[sym]) /
                                                         static_cast<double>(total) -
                                                     share[sym]));
                tried.push_back({Phase{static_cast<int>(first), at}, total, error});
            }
    // The mix, less a share of kLostPoint for each point a phase holds under the most any holds
    // (a phase that loses points loses them together: a hole, say in a neck).
    long most = 0;
    for (const Tried& t : tried) most = std::max(most, t.total);
    std::optional<Phase> best;
    double best_score = INFINITY;
    for (const Tried& t : tried) {
        const double score =
            t.error + kLostPoint * static_cast<double>(most - t.total) / static_cast<double>(most);
        if (score < best_score - 1e-12) {
            best_score = score;
            best = t.phase;
        }
    }
    return best;
}

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
