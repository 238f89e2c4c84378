#include "driver/preview_guides.hpp"

#include <cmath>
#include <sstream>

namespace acanthus {

bool guides_svg(const nlohmann::json& body, std::string& svg, std::string& error) {
    svg.clear();
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
        if (kind != "flow" && kind != "boundary" && kind != "spray")
            return error = "a stroke's kind is flow, boundary or spray", false;
        const auto& points = stroke.contains("points") ? stroke["points"] : nlohmann::json();
        if (!points.is_array() || points.size() < 2 || points.size() > 10000)
            return error = "a stroke has 2 to 10000 points", false;
        double width = 1;
        if (kind == "spray") {
            if (!stroke.contains("width") || !stroke["width"].is_number() ||
                !(stroke["width"].get<double>() > 0) || stroke["width"].get<double>() > 1e9)
                return error = "a spray stroke needs a width (its brush diameter) above 0", false;
            width = stroke["width"].get<double>();
        }
        out << "  <polyline class=\"" << kind << "\" fill=\"none\" stroke=\""
            << (kind == "flow"       ? "#36c"
                : kind == "boundary" ? "#c33"
                                     : "#c63")
            << "\" stroke-width=\"" << width << "\" stroke-linecap=\"round\" points=\"";
        for (const auto& p : points) {
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                return error = "each point is [x, y]", false;
            const double x = p[0].get<double>(), y = p[1].get<double>();
            if (!std::isfinite(x) || !std::isfinite(y) || std::fabs(x) > 1e9 || std::fabs(y) > 1e9)
                return error = "a point's coordinates are finite and within 1e9", false;
            out << x << "," << y << " ";
        }
        out << "\"/>\n";
        ++count;
    }
    if (count == 0) return true;
    svg =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- Guides drawn in acanthus preview: flow, boundary and spray strokes. -->\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\">\n" +
        out.str() + "</svg>\n";
    return true;
}

}  // namespace acanthus
