// Facades from SVG drawings and from panels, on top of the shared SVG reader (runtime/src/svg).
// Which shape is wall, which an opening, and which labels each carries (docs/stdlib/cells.md).
#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/facade_shape.hpp>
#include <algorithm>
#include <filesystem>

#include "region/region_data.hpp"
#include "svg/shape_reader.hpp"
#include "zero_size_shapes.hpp"

namespace acanthus::cells {

namespace {

using acanthus::detail::SvgElement;
using acanthus::detail::SvgShape;

// Twice the signed area of a closed path, from points along its curves (the sign is all we need).
double orientation(const Geom::Path& path) {
    double sum = 0;
    Geom::Point prev = path.initialPoint();
    for (const Geom::Curve& c : path)
        for (int i = 1; i <= 16; ++i) {
            Geom::Point q = c.pointAt(i / 16.0);
            sum += prev[Geom::X] * q[Geom::Y] - q[Geom::X] * prev[Geom::Y];
            prev = q;
        }
    return sum;
}

// Closed subpaths whose nonzero fill is the shape's fill: an even-odd shape's subpaths are
// turned so that those nested an odd number of times wind against the others (holes).
Geom::PathVector closed_nonzero(const Geom::PathVector& paths, bool evenodd) {
    Geom::PathVector out;
    for (const Geom::Path& p : paths) {
        if (p.empty()) continue;
        Geom::Path closed = p;
        closed.close(true);
        out.push_back(closed);
    }
    if (!evenodd || out.size() < 2) return out;
    Geom::PathVector turned;
    for (std::size_t i = 0; i < out.size(); ++i) {
        int depth = 0;
        // A point just along the subpath, not its start: shared starts are common in drawings.
        Geom::Point probe = out[i].pointAt(0.5);
        for (std::size_t j = 0; j < out.size(); ++j)
            if (j != i && out[j].winding(probe) != 0) ++depth;
        bool positive = orientation(out[i]) > 0;
        turned.push_back(positive == (depth % 2 == 0) ? out[i] : out[i].reversed());
    }
    return turned;
}

// The chain of elements from the shape's own up to (not including) the root <svg>.
std::vector<const SvgElement*> chain_of(const SvgShape& s) {
    std::vector<const SvgElement*> chain;
    for (const SvgElement* e = s.element.get(); e; e = e->parent.get())
        if (e->tag != "svg") chain.push_back(e);
    return chain;
}

// A shape is wall when the nearest element with any class words (itself, else its closest
// ancestor) has the class `wall`: a <g class="wall"> can hold <rect class="window">.
bool wall_role(const std::vector<const SvgElement*>& chain) {
    for (const SvgElement* e : chain)
        if (!e->classes.empty()) return e->has_class("wall");
    return false;
}

// `panel`: a drawing without `wall` read as one: every filled shape is wall.
FacadeShape facade_shape(const SvgShape& s, bool panel) {
    FacadeShape f;
    f.paths = closed_nonzero(s.paths, s.evenodd);
    std::vector<const SvgElement*> chain = chain_of(s);
    const bool wall = panel || wall_role(chain);
    if (panel) f.classes = {"wall", "panel"};
    // Labels: the class words of the shape, then of its ancestors outwards, each once; an
    // opening does not inherit `wall` from a group around it.
    for (const SvgElement* e : chain)
        for (const std::string& c : e->classes)
            if ((wall || c != "wall") &&
                std::find(f.classes.begin(), f.classes.end(), c) == f.classes.end())
                f.classes.push_back(c);
    // The id: its own, else the nearest ancestor's (a <g id="door"> around unnamed paths).
    const SvgElement* named = nullptr;
    for (const SvgElement* e : chain)
        if (!e->id.empty()) {
            named = e;
            break;
        }
    if (named) f.id = named->id;
    f.label = s.element ? s.element->label : std::string("a shape");
    if (named && named != s.element.get()) f.label += " in " + named->label;
    return f;
}

bool is_spec(const std::string& name) {
    for (std::string_view kind : {"rect:", "circle:", "ellipse:"})
        if (name.compare(0, kind.size(), kind) == 0) return true;
    return false;
}

Facade from_svg_shapes(const std::vector<SvgShape>& svg, const std::string& name, bool panel) {
    std::vector<FacadeShape> shapes;
    std::string unfilled_wall;
    for (const SvgShape& s : svg) {
        // Lines and unfilled shapes are drawing, not masonry: glazing bars, outlines, notes.
        bool line = s.element && s.element->tag == "line";
        if (line || s.fill == "none") {
            if (unfilled_wall.empty() && wall_role(chain_of(s)) && s.element)
                unfilled_wall = s.element->label;
            continue;
        }
        shapes.push_back(facade_shape(s, panel));
    }
    bool any_wall = std::any_of(shapes.begin(), shapes.end(), [](const FacadeShape& s) {
        return std::find(s.classes.begin(), s.classes.end(), "wall") != s.classes.end();
    });
    if (!any_wall && !unfilled_wall.empty())
        throw InputError(name + ": " + unfilled_wall +
                         ": has class \"wall\" but no fill (unfilled shapes are ignored); no "
                         "filled shape with class \"wall\"");
    return Facade::from_shapes(std::move(shapes), name);
}

}  // namespace

Facade Facade::from_svg_string(std::string_view text, const std::string& name) {
    std::vector<SvgShape> svg = acanthus::detail::read_svg_shapes(text, name);
    detail::refuse_zero_size_shapes(text, name);
    return from_svg_shapes(svg, name, false);
}

Facade Facade::from_svg_file(const std::string& path) {
    std::string text = read_input_file_or_throw(path, "facade", acanthus::detail::kMaxSvgFileBytes);
    return from_svg_string(text, path);
}

Facade Facade::from_region(const Region& region) {
    const acanthus::detail::RegionData& r = region.data();
    FacadeShape wall;
    wall.paths = closed_nonzero(r.paths, r.evenodd);
    wall.classes = {"wall", "panel"};
    wall.label = "the panel";
    std::vector<FacadeShape> shapes;
    shapes.push_back(std::move(wall));
    return from_shapes(std::move(shapes), r.name);
}

Facade Facade::for_panel(const Region& region, bool whole_panel) {
    const std::string& name = region.name();
    std::error_code ec;
    if (is_spec(name) || !std::filesystem::is_regular_file(name, ec)) return from_region(region);
    std::string text = read_input_file_or_throw(name, "facade", acanthus::detail::kMaxSvgFileBytes);
    std::vector<SvgShape> svg = acanthus::detail::read_svg_shapes(text, name);
    detail::refuse_zero_size_shapes(text, name);
    // Read again rather than taken from the region: the drawing's circular arcs stay exact.
    bool wall = std::any_of(svg.begin(), svg.end(),
                            [](const SvgShape& s) { return wall_role(chain_of(s)); });
    if (!wall && !whole_panel)
        throw InputError(name +
                         ": no filled shape with class \"wall\": not a facade (its wall is the "
                         "union of the shapes with class wall; docs/stdlib/cells.md)");
    return from_svg_shapes(svg, name, !wall);
}

}  // namespace acanthus::cells
