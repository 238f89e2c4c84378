// Turns the filled shapes of an input (SVG elements or a built-in shape) into one RegionData:
// validated, filled as a renderer fills them (region_fill.hpp), every boundary loop with the
// filled side on its left (outer loops have positive signed area, holes negative).
#pragma once

#include <2geom/pathvector.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "region/filled_shape.hpp"
#include "region/region_data.hpp"

namespace acanthus::detail {

// The most curves a region may hold, all shapes together, counted after arcs become cubics.
inline constexpr std::size_t kMaxRegionCurves = 1000000;

// Exact signed area, (1/2)∮(x dy - y dx) summed over subpaths: positive for paths whose
// interior lies on their left (counter-clockwise with y up, clockwise on screen with y down).
double signed_area(const Geom::PathVector& paths);
double signed_area(const Geom::Path& path);

// Combines the shapes into one region (their union). A single shape keeps its fill rule;
// several shapes give a nonzero region. Throws InputError naming `name` (and the shape) for
// coordinates beyond ±1e9, and when the union has no area.
std::unique_ptr<RegionData> build_region_data(const std::string& name,
                                              std::vector<FilledShape> shapes);

}  // namespace acanthus::detail
