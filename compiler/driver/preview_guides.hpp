// Strokes drawn with the growth library's tools in the page, written as the guides SVG the
// library reads (docs/stdlib/growth.md): polylines of class flow, boundary or spray, a spray
// stroke's width its brush diameter, in region coordinates.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace acanthus {

// `body` is {"strokes": [{"kind": "flow", "width": 20, "points": [[x, y], ...]}, ...]}.
// False with `error` set on anything else; `svg` empty when there is no stroke.
bool guides_svg(const nlohmann::json& body, std::string& svg, std::string& error);

}  // namespace acanthus
