// The checks every reader of paths makes before any geometry runs on them.
#pragma once

#include <2geom/pathvector.h>

#include <string>

namespace acanthus::detail {

// Throws InputError "<where>: coordinates are not finite numbers" when a point or a curve's
// bounds are NaN or infinite.
void require_finite(const Geom::PathVector& paths, const std::string& where);

// Throws InputError "<where>: coordinates out of range (the limit is ±1e9 user units)" when an
// end point, control point or arc radius lies beyond the coordinate range.
void require_in_range(const Geom::PathVector& paths, const std::string& where);

}  // namespace acanthus::detail
