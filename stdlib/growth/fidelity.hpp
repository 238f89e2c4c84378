// The fidelity report (Options-independent): the grown motifs measured against the reference as
// an author would look at them, so a run says at once when a reference grows badly. Its defect
// check (RingChecker) is also what synthesis repairs a lattice by.
#pragma once

#include <acanthus/stdlib/growth.hpp>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "panel.hpp"
#include "reference.hpp"

namespace acanthus::growth::detail {

// The expert's ring check. A motif's ring is its neighbours within 1.2 NN (the reference's median
// nearest-neighbour distance, measured on its points); it is good when it matches a full ring of
// a reference element of its symbol (as many neighbours as the fullest reference ring), each
// neighbour paired with a distinct one of its symbol within 0.15 NN. Reference rings within
// 0.005 NN of one already kept are counted once, so that a huge lattice checks as fast as a small
// one.
class RingChecker {
  public:
    explicit RingChecker(const ReferenceData& reference);
    double spacing() const { return spacing_; }
    double reach() const { return 1.2 * spacing_; }
    double tolerance() const { return 0.15 * spacing_; }
    // Per point: its ring matches a reference ring. `symbols` are the reference's symbol ids.
    std::vector<bool> good(const std::vector<Point>& points, const std::vector<int>& symbols) const;
    // Motifs at least this far inside the panel are the ones a report checks (1.5 NN).
    double interior_clearance() const { return 1.5 * spacing_; }
    // Per reference element: its nearest neighbour's distance, or nn_cap() when none is nearer
    // (what spacing() is the median of).
    const std::vector<double>& reference_nn() const { return nn_; }
    double nn_cap() const { return nn_cap_; }

    struct Ring {
        std::vector<Vector> offsets;
        std::vector<int> symbols;
    };

  private:
    bool matches(const Ring& ring, int symbol) const;
    std::int64_t key(Vector v) const;

    std::vector<double> nn_;
    double nn_cap_ = 0;
    double spacing_ = 1;
    std::size_t full_ = 0;
    std::vector<Ring> distinct_;
    std::vector<int> distinct_symbol_;
    std::unordered_map<std::int64_t, std::vector<int>> index_;  // offset cell -> rings; looked up
};

// Per point, the distance to its nearest other point, or `cap` when none is nearer.
std::vector<double> nn_distances(const std::vector<Point>& points, double cap);
// The middle value (the upper of the two middle ones); 0 for none.
double median(std::vector<double> values);

// The reference's median nearest-neighbour distance, measured on its points.
double reference_spacing(const ReferenceData& reference);

// The reference's side of the report and its ring checker, made once per reference.
struct ReferenceProfile {
    explicit ReferenceProfile(const ReferenceData& reference);
    RingChecker checker;
    std::vector<double> nn_histogram;
    std::map<std::string, double> symbol_mix;
    double same_symbol_share = 0;
    double copied_nn_median = 1;  // Fidelity::reference_nn_median
    double inner_nn_median = 1;   // Fidelity::reference_nn_median_inner
    // The most neighbours within the checker's reach any interior (candidate) element has: the
    // crowding rule's limit (synthesis.hpp).
    int most_neighbours = 0;
};
const ReferenceProfile& profile_of(const ReferenceData& reference);

// `largest_hole`: in drawing units.
Fidelity measure_fidelity(const ReferenceData& reference, const std::vector<Motif>& motifs,
                          const Panel& panel, double largest_hole);

}  // namespace acanthus::growth::detail
