// Lengths and viewports of an SVG file: lengths in user units, percentages of the nearest
// viewport, and the viewport a nested <svg> or a <symbol> drawn by <use> establishes.
#pragma once

#include <2geom/affine.h>
#include <2geom/point.h>

#include <optional>
#include <pugixml.hpp>

#include "svg/source.hpp"

namespace acanthus::detail {

// Which way a percentage length is measured (SVG 1.1, 7.10).
enum class SvgAxis { X, Y, Diagonal };

// The root's viewport in its user units, for percentages: its viewBox size, else its
// absolute width and height; (0, 0) when neither is known. Nothing else of the root's
// size is used (the region keeps the root's user units).
Geom::Point root_viewport(pugi::xml_node root);

// A length attribute in user units, `fallback` when it is not set; a percentage is of the
// width, height or normalized diagonal of `viewport` (user units, 0: not known) as `axis` says.
double svg_length(const SvgSource& source, pugi::xml_node node, const char* attr, double fallback,
                  Geom::Point viewport, SvgAxis axis);
// The same, refusing a negative length.
double non_negative_length(const SvgSource& source, pugi::xml_node node, const char* attr,
                           double fallback, Geom::Point viewport, SvgAxis axis);

// A viewport entered: what maps its user units into the parent's, and its size in its own
// user units.
struct SvgViewport {
    Geom::Affine transform;
    Geom::Point size;
};

// The viewport of a nested <svg>, or of a <symbol> or <svg> drawn by `use` (whose width and
// height, when set, replace the target's): the element's x/y, and its viewBox fitted into
// width x height by preserveAspectRatio. A missing width or height is 100% of `parent`.
// nullopt when a zero width or height disables rendering. The viewport does not clip
// (docs/regions.md).
std::optional<SvgViewport> enter_viewport(const SvgSource& source, pugi::xml_node node,
                                          pugi::xml_node use, Geom::Point parent);

}  // namespace acanthus::detail
