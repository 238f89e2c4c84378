// How faithfully a grown arrangement keeps a regular reference, measured as an author would look
// at it: motifs in the interior whose ring of neighbours matches no reference ring (defects), the
// share of close pairs with the same symbol, and the nearest-neighbour spacing.
#pragma once

#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace growth_fidelity {

using acanthus::Point;
using acanthus::Vector;

struct Site {
    Point position;
    std::string symbol;
};

struct Fidelity {
    int interior = 0;           // motifs checked (at least 1.5 spacings inside the panel)
    int defects = 0;            // of those, rings that match no reference ring
    double same_share = 0;      // close pairs (within 1.2 spacings) with one symbol
    double reference_same = 0;  // the same share in the reference
    double spacing_ratio = 0;   // median nearest-neighbour distance, result / reference
    double defect_share() const { return interior > 0 ? double(defects) / interior : 0.0; }
};

inline double median_nn(const std::vector<Site>& sites) {
    std::vector<double> d;
    for (std::size_t i = 0; i < sites.size(); ++i) {
        double best = INFINITY;
        for (std::size_t j = 0; j < sites.size(); ++j)
            if (i != j)
                best = std::min(best, acanthus::distance(sites[i].position, sites[j].position));
        d.push_back(best);
    }
    std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
    return d[d.size() / 2];
}

// Neighbours of each site within `reach`: offsets and symbols.
struct Ring {
    std::vector<Vector> offsets;
    std::vector<std::string> symbols;
};

inline std::vector<Ring> rings(const std::vector<Site>& sites, double reach) {
    std::vector<Ring> out(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i)
        for (std::size_t j = 0; j < sites.size(); ++j)
            if (i != j && acanthus::distance(sites[i].position, sites[j].position) < reach) {
                out[i].offsets.push_back(sites[j].position - sites[i].position);
                out[i].symbols.push_back(sites[j].symbol);
            }
    return out;
}

// Every neighbour of `a` pairs with a distinct one of `b` within `tolerance` and of its symbol.
inline bool same_ring(const Ring& a, const Ring& b, double tolerance) {
    if (a.offsets.size() != b.offsets.size()) return false;
    std::vector<bool> used(b.offsets.size(), false);
    for (std::size_t k = 0; k < a.offsets.size(); ++k) {
        bool found = false;
        for (std::size_t m = 0; m < b.offsets.size() && !found; ++m)
            if (!used[m] && b.symbols[m] == a.symbols[k] &&
                (b.offsets[m] - a.offsets[k]).length() < tolerance)
                used[m] = found = true;
        if (!found) return false;
    }
    return true;
}

inline double same_symbol_share(const std::vector<Site>& sites, double reach) {
    int close = 0, same = 0;
    for (std::size_t i = 0; i < sites.size(); ++i)
        for (std::size_t j = i + 1; j < sites.size(); ++j)
            if (acanthus::distance(sites[i].position, sites[j].position) < reach) {
                ++close;
                same += sites[i].symbol == sites[j].symbol;
            }
    return close > 0 ? double(same) / close : 0.0;
}

// The reference's full rings (as many neighbours as its fullest element) are what a motif of
// the same symbol may look like; tolerance 0.15 x the reference's nearest-neighbour distance.
inline Fidelity measure(const std::vector<Site>& reference, const std::vector<Site>& result,
                        const acanthus::Region& region) {
    Fidelity f;
    const double d = median_nn(reference);
    const double reach = 1.2 * d;
    std::vector<Ring> reference_rings = rings(reference, reach);
    std::size_t full = 0;
    for (const Ring& r : reference_rings) full = std::max(full, r.offsets.size());
    std::vector<Ring> result_rings = rings(result, reach);
    for (std::size_t i = 0; i < result.size(); ++i) {
        if (region.distance_to_boundary(result[i].position) < 1.5 * d) continue;
        ++f.interior;
        bool matched = false;
        for (std::size_t k = 0; k < reference.size() && !matched; ++k)
            matched = reference_rings[k].offsets.size() == full &&
                      reference[k].symbol == result[i].symbol &&
                      same_ring(result_rings[i], reference_rings[k], 0.15 * d);
        f.defects += !matched;
    }
    f.same_share = same_symbol_share(result, reach);
    f.reference_same = same_symbol_share(reference, reach);
    f.spacing_ratio = result.size() > 1 ? median_nn(result) / d : 0.0;
    return f;
}

inline std::vector<Site> sites(const acanthus::growth::Reference& reference) {
    std::vector<Site> out;
    for (std::size_t i = 0; i < reference.size(); ++i)
        out.push_back({reference.element(i).position, reference.element(i).symbol});
    return out;
}

inline std::vector<Site> sites(const acanthus::growth::SynthesisResult& result) {
    std::vector<Site> out;
    for (const auto& m : result.motifs) out.push_back({m.position, m.symbol});
    return out;
}

}  // namespace growth_fidelity
