#include "server/guides.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace acanthus {

namespace {

// A colour per kind, in the order the tool declares them: the file reads well in an editor.
const char* const kPalette[] = {"#36c", "#c33", "#c63", "#393", "#939", "#399"};

}  // namespace

bool guides_svg(const nlohmann::json& body, const StrokeTool& tool, std::string& svg,
                std::vector<std::string>& kinds_drawn, std::string& error) {
    svg.clear();
    kinds_drawn.clear();
    if (!body.contains("strokes") || !body["strokes"].is_array() || body["strokes"].size() > 1000) {
        error = "strokes must be a list of at most 1000 strokes";
        return false;
    }
    std::ostringstream out;
    out.precision(10);
    int count = 0;
    for (const auto& stroke : body["strokes"]) {
        if (!stroke.is_object()) return error = "each stroke is an object", false;
        const std::string kind = stroke.value("kind", "");
        if (!tool.has_kind(kind)) {
            error = "a stroke's kind is one of";
            for (const std::string& k : tool.kinds) error += " " + k;
            return false;
        }
        const auto& points = stroke.contains("points") ? stroke["points"] : nlohmann::json();
        if (!points.is_array() || points.size() < 2 || points.size() > 10000)
            return error = "a stroke has 2 to 10000 points", false;
        double width = 1;
        if (tool.has_width(kind)) {
            if (!stroke.contains("width") || !stroke["width"].is_number() ||
                !(stroke["width"].get<double>() > 0) || stroke["width"].get<double>() > 1e9)
                return error = "a " + kind + " stroke needs a width (its brush diameter) above 0",
                       false;
            width = stroke["width"].get<double>();
        }
        const auto index = static_cast<std::size_t>(
            std::find(tool.kinds.begin(), tool.kinds.end(), kind) - tool.kinds.begin());
        out << "  <polyline class=\"" << kind << "\" fill=\"none\" stroke=\""
            << kPalette[index % std::size(kPalette)] << "\" stroke-width=\"" << width
            << "\" stroke-linecap=\"round\" points=\"";
        for (const auto& p : points) {
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                return error = "each point is [x, y]", false;
            const double x = p[0].get<double>(), y = p[1].get<double>();
            if (!std::isfinite(x) || !std::isfinite(y) || std::fabs(x) > 1e9 || std::fabs(y) > 1e9)
                return error = "a point's coordinates are finite and within 1e9", false;
            out << x << "," << y << " ";
        }
        out << "\"/>\n";
        kinds_drawn.push_back(kind);
        ++count;
    }
    if (count == 0) return true;
    svg =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- Guides drawn in acanthus preview with the " +
        tool.library +
        " library's strokes. -->\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\">\n" +
        out.str() + "</svg>\n";
    return true;
}

}  // namespace acanthus
