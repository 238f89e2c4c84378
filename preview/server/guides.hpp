// Strokes drawn on the page with a library's stroke tools (server/stroke_tools.hpp), written as
// the SVG such a library reads (docs/stdlib/growth.md#guides): a polyline per stroke, its class
// the stroke's kind, the stroke-width of a width kind its brush diameter, in region coordinates.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "server/stroke_tools.hpp"

namespace acanthus {

// `body` is {"strokes": [{"kind": "flow", "width": 20, "points": [[x, y], ...]}, ...]}, each
// kind one of `tool`'s. False with `error` set on anything else; `svg` empty when there is no
// stroke. `kinds_drawn` receives each stroke's kind, in order.
bool guides_svg(const nlohmann::json& body, const StrokeTool& tool, std::string& svg,
                std::vector<std::string>& kinds_drawn, std::string& error);

}  // namespace acanthus
