// One shape of a facade drawing, as the SVG reader hands it to Facade::from_shapes. Separate from
// <acanthus/stdlib/cells.hpp> because it needs lib2geom's headers.
#pragma once

#include <2geom/pathvector.h>

#include <string>
#include <vector>

namespace acanthus::cells {

struct FacadeShape {
    Geom::PathVector paths;            // root user units, transforms applied; closed subpaths
    std::string id;                    // the SVG id, may be empty
    std::vector<std::string> classes;  // class words: `wall`, `window`, `arch`, ...
    std::string label;                 // for messages, e.g. "<path id=\"w1\"> (line 12)"
};

}  // namespace acanthus::cells
