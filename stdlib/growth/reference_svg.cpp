// The reference arrangement as an SVG drawing (issue 10): each shape or group carrying
// data-symbol is one element at the centre of its bounding box; its shapes are its outline.
#include <2geom/bezier-curve.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "empty_symbols.hpp"
#include "reference.hpp"
#include "region/curves.hpp"
#include "svg/shape_reader.hpp"

namespace acanthus::growth {
namespace {

using acanthus::detail::SvgElement;
using acanthus::detail::SvgShape;

// The nearest element from the shape up that carries data-symbol, or null.
const SvgElement* owner(const SvgShape& shape) {
    for (const SvgElement* e = shape.element.get(); e; e = e->parent.get())
        if (e->data.count("symbol")) return e;
    return nullptr;
}

double number(const SvgElement& e, const char* key, const std::string& where) {
    const std::string& text = e.data.at(key);
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    while (end && *end == ' ') ++end;
    if (text.empty() || !end || *end != '\0' || !std::isfinite(v))
        throw InputError(where + ": data-" + key + " '" + text + "' is not a finite number");
    return v;
}

Color paint(const std::string& text, Color fallback) {
    if (text == "none") return {0, 0, 0, 0};
    try {
        return parse_color(text);
    } catch (const InputError&) {
        return fallback;  // gradients, currentColor, rgb(): drawn in the fallback
    }
}

Point point(Geom::Point p, Geom::Point centre) {
    return {p[Geom::X] - centre[Geom::X], p[Geom::Y] - centre[Geom::Y]};
}

// Every curve as a cubic (arcs were made cubics before).
void append_cubic(const Geom::Curve& c, Geom::Point centre, std::vector<Point>& out) {
    Geom::Point a = c.initialPoint(), b = c.finalPoint();
    if (auto bez = dynamic_cast<const Geom::BezierCurve*>(&c); bez && bez->order() == 3) {
        for (unsigned k = 1; k <= 3; ++k) out.push_back(point((*bez)[k], centre));
    } else if (bez && bez->order() == 2) {
        Geom::Point q = (*bez)[1];
        out.push_back(point(a + (q - a) * (2.0 / 3), centre));
        out.push_back(point(b + (q - b) * (2.0 / 3), centre));
        out.push_back(point(b, centre));
    } else {
        out.push_back(point(a + (b - a) / 3, centre));
        out.push_back(point(a + (b - a) * (2.0 / 3), centre));
        out.push_back(point(b, centre));
    }
}

Outline outline_of(const SvgShape& shape, Geom::Point centre) {
    Outline o;
    o.fill = paint(shape.fill, {0.5, 0.5, 0.5, 1});
    o.stroke = paint(shape.stroke, {0, 0, 0, 0});
    o.stroke_width = shape.stroke_width;
    for (const Geom::Path& p : acanthus::detail::arcs_to_cubics(shape.paths)) {
        OutlinePath op;
        op.closed = p.closed();
        op.points.push_back(point(p.initialPoint(), centre));
        for (const Geom::Curve& c : p) append_cubic(c, centre, op.points);
        o.paths.push_back(std::move(op));
    }
    return o;
}

// data-flips="0 4; 2 7" on the root element: pairs of element indices.
std::vector<std::pair<int, int>> flips_of(const SvgElement* root, const std::string& name) {
    std::vector<std::pair<int, int>> flips;
    if (!root || !root->data.count("flips")) return flips;
    std::istringstream pairs(root->data.at("flips"));
    for (std::string pair; std::getline(pairs, pair, ';');) {
        if (pair.find_first_not_of(" \t\n") == std::string::npos) continue;
        std::istringstream in(pair);
        long long i = -1, j = -1;
        std::string rest;
        if (!(in >> i >> j) || (in >> rest) || i < 0 || j < 0 || i > 1 << 30 || j > 1 << 30)
            throw InputError(name + ": data-flips: '" + pair +
                             "' is not a pair of element indices (\"i j; k l\")");
        flips.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
    return flips;
}

}  // namespace

Reference Reference::from_svg_string(std::string_view text, const std::string& name) {
    std::vector<SvgShape> shapes = acanthus::detail::read_svg_shapes(text, name);
    // The reader hands over only shapes: an element with none would vanish without a word.
    detail::check_symbols_own_shapes(text, name);
    // Elements in document order of their first shape; shapes grouped by their owner.
    std::vector<const SvgElement*> owners;
    std::map<const SvgElement*, std::vector<const SvgShape*>> grouped;
    const SvgElement* root = nullptr;
    for (const SvgShape& s : shapes) {
        for (const SvgElement* e = s.element.get(); e; e = e->parent.get()) root = e;
        const SvgElement* o = owner(s);
        if (!o) continue;
        auto [it, fresh] = grouped.try_emplace(o);
        if (fresh) owners.push_back(o);
        it->second.push_back(&s);
    }
    if (owners.empty())
        throw InputError(name + ": no element carries data-symbol (see docs/stdlib/growth.md)");
    std::vector<ReferenceElement> elements;
    std::vector<std::vector<Outline>> outlines;
    for (std::size_t i = 0; i < owners.size(); ++i) {
        const SvgElement& e = *owners[i];
        const std::string where = name + ": element " + std::to_string(i) + " " + e.label;
        // The bounding box of all its shapes (kept as numbers: GCC misreads OptRect unions).
        double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
        for (const SvgShape* s : grouped[&e])
            if (Geom::OptRect b = s->paths.boundsExact()) {
                x0 = std::min(x0, b->left());
                y0 = std::min(y0, b->top());
                x1 = std::max(x1, b->right());
                y1 = std::max(y1, b->bottom());
            }
        if (!(x1 >= x0 && y1 >= y0)) throw InputError(where + ": has no geometry");
        ReferenceElement r;
        r.symbol = e.data.at("symbol");
        if (r.symbol.empty()) throw InputError(where + ": empty data-symbol");
        if (e.data.count("label") && e.data.count("sub"))
            throw InputError(where + ": data-label and its old name data-sub both given");
        for (const char* key : {"label", "sub"})
            if (e.data.count(key)) r.label = e.data.at(key);
        if (e.data.count("angle")) r.angle = number(e, "angle", where) * M_PI / 180;
        if (e.data.count("size")) {
            r.size = number(e, "size", where);
            if (!(r.size > 0)) throw InputError(where + ": data-size must be positive");
        }
        Geom::Point c((x0 + x1) / 2, (y0 + y1) / 2);
        r.position = {c[Geom::X], c[Geom::Y]};
        elements.push_back(std::move(r));
        std::vector<Outline> own;
        for (const SvgShape* s : grouped[&e]) own.push_back(outline_of(*s, c));
        outlines.push_back(std::move(own));
    }
    return Reference(detail::analyse_reference(name, std::move(elements), flips_of(root, name),
                                               std::move(outlines)));
}

Reference Reference::from_svg_file(const std::string& path) {
    std::string content =
        read_input_file_or_throw(path, "reference arrangement", acanthus::detail::kMaxSvgFileBytes);
    return from_svg_string(content, path);
}

Reference Reference::from_file(const std::string& path) {
    std::string content =
        read_input_file_or_throw(path, "reference arrangement", acanthus::detail::kMaxSvgFileBytes);
    std::size_t first = content.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (first != std::string::npos && content[first] == '<') return from_svg_string(content, path);
    return from_json_string(content, path);
}

}  // namespace acanthus::growth
