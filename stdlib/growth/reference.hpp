// The analysed reference arrangement behind growth::Reference: elements with interned symbols,
// the connectivity, and each element's 1-ring as offsets (section 4). An element's sub-id is its
// index: section 3 gives every reference element a sub-id of its own.
#pragma once

#include <acanthus/stdlib/growth.hpp>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "connectivity.hpp"

namespace acanthus::growth::detail {

struct ReferenceProfile;  // fidelity.hpp
struct Lattice;           // lattice.hpp
struct RingRegularity;    // near_regular.hpp
struct JitteredLattice;   // near_regular.hpp

// One neighbour in a reference 1-ring.
struct RingSlot {
    int element = -1;
    Vector offset;        // neighbour minus centre
    bool closed = false;  // this slot, the next one and the centre form a kept triangle
};

struct ReferenceData {
    std::string name;
    std::vector<ReferenceElement> elements;
    std::vector<std::string> symbols;            // sorted names; symbol ids index it
    std::vector<int> symbol;                     // per element
    std::vector<double> radius;                  // collision radius per element
    std::vector<std::vector<Outline>> outlines;  // per element (empty lists for JSON)
    Connectivity connectivity;
    std::vector<std::vector<RingSlot>> rings;  // per element, counter-clockwise
    std::vector<int> candidates;               // elements matched against (not boundary)
    double mean_edge = 0;
    double shortest_edge = 0;

    int symbol_id(const std::string& name) const;  // -1 when unknown

    // What every synthesis from this reference measures it by and grows it on, worked out once
    // (the first synthesis asks; a huge reference costs it once, not per run).
    mutable std::once_flag profile_once, lattice_once;
    mutable std::shared_ptr<const ReferenceProfile> profile;
    mutable std::shared_ptr<const Lattice> lattice;  // null: not a lattice
    // The rings' spacing and the restart radius in it (synthesis.hpp), the rings' regularity and
    // the jittered lattice fitted to them (near_regular.hpp; null: none fits).
    mutable std::once_flag spacing_once, regularity_once, jittered_once;
    mutable double spacing = 0, restart_radius = 0;
    mutable std::shared_ptr<const RingRegularity> regularity;
    mutable std::shared_ptr<const JitteredLattice> jittered;
};

// Validates (finite coordinates and sizes, at least 3 distinct points, flips) and analyses.
// Errors name `name` and the element index.
std::shared_ptr<const ReferenceData> analyse_reference(
    std::string name, std::vector<ReferenceElement> elements,
    std::vector<std::pair<int, int>> flips, std::vector<std::vector<Outline>> outlines = {});

}  // namespace acanthus::growth::detail
