// Turns the filled shapes of an input (SVG elements or a built-in shape) into one RegionData:
// validated, with every boundary subpath oriented so the filled side lies on its left
// (outer rings have positive signed area, holes negative) and overlapping shapes merged.
#pragma once

#include <2geom/pathvector.h>

#include <memory>
#include <string>
#include <vector>

#include "region_data.hpp"

namespace acanthus::detail {

// One filled shape as the input declares it: closed subpaths read with their own fill rule.
struct FilledShape {
    Geom::PathVector paths;
    bool evenodd = false;
    std::string label;  // "<path id="x"> (line 12)" for messages
};

// Exact signed area, (1/2)∮(x dy - y dx) summed over subpaths: positive for paths whose
// interior lies on their left (counter-clockwise with y up, clockwise on screen with y down).
double signed_area(const Geom::PathVector& paths);
double signed_area(const Geom::Path& path);

// Throws InputError "<name>: <label>: ..." when a coordinate is NaN or infinite.
void require_finite(const Geom::PathVector& paths, const std::string& name,
                    const std::string& label);

// Combines the shapes into one region (their union). A single shape keeps its fill rule;
// several shapes give a nonzero region. Throws InputError naming `name` when nothing is left
// or the union has no area.
std::unique_ptr<RegionData> build_region_data(const std::string& name,
                                              std::vector<FilledShape> shapes);

}  // namespace acanthus::detail
