// Internal representation of a Region: exact lib2geom paths plus cached measures.
#pragma once

#include <2geom/pathvector.h>

#include <acanthus/point.hpp>
#include <memory>
#include <string>

namespace acanthus::detail {

class RegionBoundary;

struct RegionData {
    std::string name;        // file name or built-in spec, for messages
    Geom::PathVector paths;  // closed subpaths in user units (y down)
    bool evenodd = false;    // fill rule; nonzero otherwise
    Rect bounds;
    double area = 0;
    // Built once from `paths` (set_boundary) and shared by copies: it owns its own loops.
    std::shared_ptr<const RegionBoundary> boundary;
};

// Builds data.boundary from data.paths and data.evenodd.
void set_boundary(RegionData& data);

}  // namespace acanthus::detail
