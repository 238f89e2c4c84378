// User-defined skeletal strokes from SVG path data or an SVG file: the shapes' joint bounding
// box becomes the stroke frame [0, 1] x [-0.5, 0.5].
#include <2geom/exception.h>
#include <2geom/svg-path-parser.h>
#include <2geom/transforms.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <pugixml.hpp>

#include "draw/skeletal_stroke_data.hpp"
#include "svg/attributes.hpp"

namespace acanthus {

// This file builds public types from private (detail) parts.
using namespace detail;

namespace {

Geom::PathVector parse_path_data(std::string_view data, const std::string& where) {
    try {
        return Geom::parse_svg_path(std::string(data).c_str());
    } catch (const Geom::SVGPathParseError&) {
        throw InputError(where + ": bad path data");
    } catch (const Geom::Exception& e) {
        throw InputError(where + ": bad path data: " + e.what());
    }
}

// Maps the shapes' joint bounding box onto the frame; rejects shapes that cannot be a stroke.
SkeletalStroke make_stroke(std::vector<StrokeShape> shapes, const std::string& name) {
    Geom::PathVector all;
    for (const StrokeShape& s : shapes) all.insert(all.end(), s.paths.begin(), s.paths.end());
    Geom::OptRect box = all.boundsExact();
    if (!box) throw InputError(name + ": no path data");
    for (double c : {box->left(), box->right(), box->top(), box->bottom()})
        if (!std::isfinite(c)) throw InputError(name + ": path has a non-finite coordinate");
    if (!(box->width() > 0) || !(box->height() > 0))
        throw InputError(name + ": the stroke shape has no area (its bounding box is " +
                         std::to_string(box->width()) + " x " + std::to_string(box->height()) +
                         ")");
    Geom::Affine to_frame = Geom::Translate(-box->left(), -box->midpoint()[Geom::Y]) *
                            Geom::Scale(1 / box->width(), 1 / box->height());
    SkeletalStroke::Data d;
    d.name = name;
    for (StrokeShape& s : shapes) {
        s.paths *= to_frame;
        d.shapes.push_back(std::move(s));
    }
    return SkeletalStroke(std::move(d));
}

bool is_evenodd(const pugi::xml_node& node) {
    for (pugi::xml_node n = node; n && n.type() == pugi::node_element; n = n.parent()) {
        std::string rule = n.attribute("fill-rule").as_string();
        if (auto styled = detail::style_property(n.attribute("style").as_string(), "fill-rule"))
            rule = *styled;
        rule.erase(std::remove_if(rule.begin(), rule.end(),
                                  [](unsigned char c) { return std::isspace(c); }),
                   rule.end());
        if (!rule.empty() && rule != "inherit") return rule == "evenodd";
    }
    return false;
}

// Elements whose paths are not drawn where they stand.
bool is_hidden_container(const pugi::xml_node& node) {
    for (const char* name : {"defs", "clipPath", "mask", "symbol", "marker", "pattern"})
        if (std::strcmp(node.name(), name) == 0) return true;
    return false;
}

}  // namespace

SkeletalStroke SkeletalStroke::from_svg_path(std::string_view path_data, const std::string& name) {
    Geom::PathVector paths = parse_path_data(path_data, name);
    return make_stroke({{paths, false}}, name);
}

SkeletalStroke SkeletalStroke::from_svg_file(const std::string& path) {
    const std::string text = read_input_file_or_throw(path, "stroke file");
    auto line_of = [&](std::ptrdiff_t offset) {
        offset = std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(text.size()));
        return 1 + std::count(text.begin(), text.begin() + offset, '\n');
    };
    pugi::xml_document doc;
    pugi::xml_parse_result ok = doc.load_buffer(text.data(), text.size());
    if (!ok)
        throw InputError(path + ":" + std::to_string(line_of(ok.offset)) +
                         ": not an SVG file: " + ok.description());
    pugi::xml_node root = doc.document_element();
    if (std::strcmp(root.name(), "svg") != 0)
        throw InputError(path + ": not an SVG file (the root element is <" +
                         std::string(root.name()) + ">)");

    std::vector<StrokeShape> shapes;
    // Depth-first in document order, carrying each group's transform down.
    struct Pending {
        pugi::xml_node node;
        Geom::Affine parent;
    };
    std::vector<Pending> stack{{root, Geom::identity()}};
    while (!stack.empty()) {
        auto [node, parent] = stack.back();
        stack.pop_back();
        std::string label = std::string("<").append(node.name()) + "> (line " +
                            std::to_string(line_of(node.offset_debug())) + ")";
        Geom::Affine here = parent;
        if (auto t = node.attribute("transform")) {
            try {
                here = detail::parse_transform(t.as_string()) * parent;
            } catch (const detail::SvgSyntaxError& e) {
                throw InputError(path + ": " + label + ": bad transform: " + e.what());
            }
        }
        if (std::strcmp(node.name(), "path") == 0) {
            Geom::PathVector paths =
                parse_path_data(node.attribute("d").as_string(), path + ": " + label);
            shapes.push_back({paths * here, is_evenodd(node)});
        }
        std::vector<Pending> children;
        for (pugi::xml_node child : node.children())
            if (child.type() == pugi::node_element && !is_hidden_container(child))
                children.push_back({child, here});
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }
    if (shapes.empty()) throw InputError(path + ": no path element");
    return make_stroke(std::move(shapes), path);
}

}  // namespace acanthus
