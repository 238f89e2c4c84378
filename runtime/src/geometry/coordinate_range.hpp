// The coordinate range every stage works in: beyond it, distances, rasterization and rendering
// lose their precision or their time bounds, so regions, placed elements and library inputs
// (growth references, guides, facades) beyond it are refused. Documented in docs/cli.md.
#pragma once

#include <cmath>

namespace acanthus::detail {

// |x|, |y| and radii at most this (region user units).
inline constexpr double kMaxCoordinate = 1e9;

inline bool in_coordinate_range(double v) { return std::abs(v) <= kMaxCoordinate; }

}  // namespace acanthus::detail
