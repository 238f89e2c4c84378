// One filled shape as an input declares it, before shapes are combined into a region.
#pragma once

#include <2geom/pathvector.h>

#include <string>

namespace acanthus::detail {

// Closed subpaths read with their own fill rule (open ones are filled as if closed).
struct FilledShape {
    Geom::PathVector paths;
    bool evenodd = false;
    std::string label;  // "<path id="x"> (line 12)" for messages
};

}  // namespace acanthus::detail
