// Lattice detection: a regular reference (the paper's Figure 8a class: triangular, square,
// honeycomb, 3-colour, checker, stripes, rosettes) is a set of sites repeated by two translations.
// The translations are found among the offsets between elements like the most central one, as
// those that map (nearly) every element onto an element of the same kind within 0.15 of the
// nearest-neighbour distance, and never onto an empty place inside the reference. Motifs turned
// or sized at random are alike in position and symbol only: then the positions' lattice is
// found, and its smallest sub-lattice under which the symbols repeat. Synthesis then
// keeps its growth on that lattice (synthesis.hpp), so that fronts meeting from two sides agree.
#pragma once

#include <acanthus/point.hpp>
#include <optional>
#include <vector>

namespace acanthus::growth::detail {

struct ReferenceData;

struct Lattice {
    struct Site {
        Vector offset;              // from the lattice origin, within one cell
        int symbol = -1;            // the symbol every element of the site has
        std::vector<int> elements;  // reference elements of this site
        // Of those, the ones matched against: not on the boundary, at most 64, the nearest the
        // reference's central element.
        std::vector<int> candidates;
    };
    Vector t1, t2;             // the two shortest independent translations, |t1| <= |t2|
    std::vector<Site> sites;   // one per kind of element in a cell
    std::vector<int> site_of;  // per reference element
    double spacing = 0;        // the reference's median nearest-neighbour distance
    double tolerance = 0;      // 0.15 spacing: how far an element may lie from its site

    // A point of the lattice placed with `origin`: the site and cell of the lattice point
    // nearest p.
    struct Spot {
        int site = -1;
        long i = 0, j = 0;
        Point at;             // the lattice point
        double residual = 0;  // |p - at|
        bool operator<(const Spot& o) const {
            return site != o.site ? site < o.site : i != o.i ? i < o.i : j < o.j;
        }
    };
    Spot nearest(Point origin, Point p) const;
    Point point(Point origin, int site, long i, long j) const;
};

// The lattice of a reference, or none when it is not regular (irregular or too jittered,
// fewer than one interior element per site, more than 24 sites in a cell).
std::optional<Lattice> detect_lattice(const ReferenceData& reference);
// detect_lattice, once per reference (null: none).
const Lattice* lattice_of(const ReferenceData& reference);

}  // namespace acanthus::growth::detail
