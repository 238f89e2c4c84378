// Internal representation of a Region: exact lib2geom paths plus cached measures.
#pragma once

#include <2geom/pathvector.h>

#include <acanthus/point.hpp>
#include <string>

namespace acanthus::detail {

struct RegionData {
    std::string name;        // file name or built-in spec, for messages
    Geom::PathVector paths;  // closed subpaths in user units (y down)
    bool evenodd = false;    // fill rule; nonzero otherwise
    Rect bounds;
    double area = 0;
};

}  // namespace acanthus::detail
