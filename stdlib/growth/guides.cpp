// The tools of section 3 drawn in an SVG: flow, boundary and spray strokes (issue 10).
#include <2geom/bezier-curve.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>

#include "svg/shape_reader.hpp"

namespace acanthus::growth {
namespace {

using acanthus::detail::SvgElement;
using acanthus::detail::SvgShape;

constexpr int kSamplesPerCurve = 16;  // curves become polylines; lines stay two points

// The tool named by the nearest class word flow, boundary or spray, from the shape up.
std::string tool_of(const SvgShape& shape) {
    for (const SvgElement* e = shape.element.get(); e; e = e->parent.get())
        for (const char* tool : {"flow", "boundary", "spray"})
            if (e->has_class(tool)) return tool;
    return "";
}

std::vector<std::vector<Point>> polylines(const Geom::PathVector& paths) {
    std::vector<std::vector<Point>> out;
    for (const Geom::Path& p : paths) {
        std::vector<Point> line{{p.initialPoint()[Geom::X], p.initialPoint()[Geom::Y]}};
        for (const Geom::Curve& c : p) {  // the closing segment only when closed
            const bool straight = c.isLineSegment();
            for (int k = straight ? kSamplesPerCurve : 1; k <= kSamplesPerCurve; ++k) {
                Geom::Point q = c.pointAt(static_cast<double>(k) / kSamplesPerCurve);
                line.push_back({q[Geom::X], q[Geom::Y]});
            }
        }
        if (line.size() >= 2) out.push_back(std::move(line));
    }
    return out;
}

}  // namespace

Guides Guides::from_svg_string(std::string_view text, const std::string& name) {
    Guides g;
    g.name = name;
    for (const SvgShape& s : acanthus::detail::read_svg_shapes(text, name)) {
        std::string tool = tool_of(s);
        if (tool.empty()) continue;
        const std::string where = name + ": " + s.element->label;
        std::vector<std::vector<Point>> lines = polylines(s.paths);
        if (lines.empty()) throw InputError(where + ": a " + tool + " stroke with no length");
        for (auto& line : lines) {
            if (tool == "flow") {
                // The field follows a stroke's direction: one that goes nowhere has none.
                if (line.front() == line.back() &&
                    std::all_of(line.begin(), line.end(),
                                [&](Point p) { return p == line.front(); }))
                    throw InputError(where + ": a flow stroke with no length (no direction)");
                g.flow.push_back(std::move(line));
            } else if (tool == "boundary") {
                g.boundary.push_back(std::move(line));
            } else {
                if (!(s.stroke_width > 0) || s.stroke == "none")
                    throw InputError(where +
                                     ": a spray stroke needs a stroke and a positive "
                                     "stroke-width (the brush diameter)");
                g.spray.push_back({std::move(line), s.stroke_width});
            }
        }
    }
    if (g.flow.empty() && g.boundary.empty() && g.spray.empty())
        throw InputError(name +
                         ": no guide: expected paths, polylines or lines with class flow, "
                         "boundary or spray");
    return g;
}

Guides Guides::from_svg_file(const std::string& path) {
    std::string content =
        read_input_file_or_throw(path, "guides file", acanthus::detail::kMaxSvgFileBytes);
    return from_svg_string(content, path);
}

void Guides::add_to(Options& options) const {
    options.flow_strokes.insert(options.flow_strokes.end(), flow.begin(), flow.end());
    options.boundary_strokes.insert(options.boundary_strokes.end(), boundary.begin(),
                                    boundary.end());
    options.spray_strokes.insert(options.spray_strokes.end(), spray.begin(), spray.end());
    options.guides_name = options.guides_name.empty() ? name : options.guides_name + ", " + name;
}

}  // namespace acanthus::growth
