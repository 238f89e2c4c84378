// Section 5: synthesis by local growth. Seeds are taken nearest-first from the start (respecting
// symbol priorities), each replaced by the reference element whose 1-ring best matches its
// neighbourhood, whose unmatched ring neighbours become new seeds (section 5.4 heuristics), and
// the pattern around it is relaxed (section 5.5) in a window, so a step costs the same at any size.
#pragma once

#include <acanthus/random.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "arrangement.hpp"
#include "flow_field.hpp"
#include "hole_finder.hpp"
#include "neighbourhood_match.hpp"
#include "panel.hpp"
#include "reference.hpp"

namespace acanthus::growth::detail {

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

  private:
    struct Choice {
        int element = -1;
        RingMatch match;
    };

    int next_seed() const;
    void grow_front();
    // Plants a seed in the largest empty circle that holds a motif at the reference's spacing,
    // linked to the motifs around it; false when no such circle is left.
    bool restart();
    HoleFinder& holes();  // made on first use, over the starts planted by then
    void grow(int seed);
    Choice choose(const Node& seed, const std::vector<RingEntry>& target,
                  const std::vector<OuterEntry>& target_outer);
    // Placed neighbours of the 1-ring nodes, beyond the seed and its 1-ring (Options::two_ring).
    std::vector<OuterEntry> outer_ring(int seed, const std::vector<int>& ring_nodes) const;
    bool motif_fits(int id, Point at, double radius) const;
    // Section 5.4: new seeds from the chosen ring, merged, dropped or extended by the heuristics.
    void spawn(int centre, const Choice& choice, const std::vector<int>& target_nodes);
    void link_ring_pair(int centre, int a, int b, double original, Vector desired);
    int new_seed(Point p, int symbol);
    void drop(int seed);
    void relax_around(int centre);
    bool still_valid(int id) const;
    int priority(int symbol) const;

    const ReferenceData& reference_;
    const Panel& panel_;
    const Options& options_;
    Random& random_;
    Weights weights_;
    std::optional<FlowField> flow_;
    std::vector<std::vector<RingEntry>> rings_;         // per reference element, unrotated
    std::vector<std::vector<OuterEntry>> outer_rings_;  // per reference element (two_ring only)
    std::vector<int> priority_;                         // per symbol id
    bool priorities_differ_ = false;
    double l_ = 1, l_short_ = 0.5, tolerance_ = 0;
    double spacing_ = 1;
    std::optional<HoleFinder> holes_;
    Arrangement pattern_;
    std::set<std::pair<double, int>> queue_;  // (distance from the start, node)
    std::vector<Point> starts_;
    std::vector<int> placed_;
    SynthesisStats stats_;
};

}  // namespace acanthus::growth::detail
