// The one SVG reader: every shape drawn outside defs/clipPath/mask/symbol (and reached through
// <use>), in the root's user units (its viewBox is not applied), with group and shape transforms,
// <switch>, CSS, entities and namespaces handled; docs/regions.md says what is read.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "svg/svg_shape.hpp"

namespace acanthus::detail {

// The most curves one file may hold, all shapes together, as read (before arcs become cubics).
inline constexpr std::size_t kMaxSvgCurves = 1000000;
inline constexpr std::uintmax_t kMaxSvgFileBytes = 64u << 20;

// Shapes of path, rect, circle, ellipse, polygon, polyline and line elements, in document
// order. Throws InputError "NAME:LINE: <element>: why" on malformed input, and on coordinates
// that are not finite or beyond the coordinate range. May return no shapes.
std::vector<SvgShape> read_svg_shapes(std::string_view text, const std::string& name);

}  // namespace acanthus::detail
