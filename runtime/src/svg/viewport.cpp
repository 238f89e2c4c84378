#include "svg/viewport.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "svg/attributes.hpp"

namespace acanthus::detail {

Geom::Point root_viewport(pugi::xml_node root) {
    try {
        std::vector<double> v = parse_number_list(root.attribute("viewBox").value());
        if (v.size() == 4 && v[2] > 0 && v[3] > 0) return {v[2], v[3]};
        if (root.attribute("width") && root.attribute("height"))
            return {parse_length(root.attribute("width").value()),
                    parse_length(root.attribute("height").value())};
    } catch (const SvgSyntaxError&) {
    }
    return {0, 0};
}

double svg_length(const SvgSource& source, pugi::xml_node node, const char* attr, double fallback,
                  Geom::Point viewport, SvgAxis axis) {
    pugi::xml_attribute a = node.attribute(attr);
    if (!a) return fallback;
    Length l;
    try {
        l = parse_length_or_percent(a.value());
    } catch (const SvgSyntaxError& e) {
        source.fail(node, std::string("attribute ") + attr + ": " + e.what());
    }
    if (!l.percent) return l.value;
    double base = axis == SvgAxis::X   ? viewport.x()
                  : axis == SvgAxis::Y ? viewport.y()
                                       : std::hypot(viewport.x(), viewport.y()) / std::sqrt(2.0);
    if (!(base > 0))
        source.fail(node, std::string("attribute ") + attr + ": '" + a.value() +
                              "' is a percentage of a viewport of unknown size (give the root "
                              "<svg> a viewBox, or use absolute lengths)");
    return l.value / 100 * base;
}

double non_negative_length(const SvgSource& source, pugi::xml_node node, const char* attr,
                           double fallback, Geom::Point viewport, SvgAxis axis) {
    double v = svg_length(source, node, attr, fallback, viewport, axis);
    if (v < 0) source.fail(node, std::string("attribute ") + attr + " is negative");
    return v;
}

std::optional<SvgViewport> enter_viewport(const SvgSource& source, pugi::xml_node node,
                                          pugi::xml_node use, Geom::Point parent) {
    // Percentages refer to the parent's viewport.
    double x = svg_length(source, node, "x", 0, parent, SvgAxis::X);
    double y = svg_length(source, node, "y", 0, parent, SvgAxis::Y);
    bool disabled = false;
    auto size = [&](const char* attr, SvgAxis axis) {
        pugi::xml_node from = use && use.attribute(attr) ? use : node;
        if (!from.attribute(attr)) return axis == SvgAxis::X ? parent.x() : parent.y();
        double v = non_negative_length(source, from, attr, 0, parent, axis);
        if (v == 0) disabled = true;
        return v;
    };
    double w = size("width", SvgAxis::X), h = size("height", SvgAxis::Y);
    if (disabled) return std::nullopt;
    SvgViewport out{Geom::Affine(1, 0, 0, 1, x, y), Geom::Point(w, h)};
    if (pugi::xml_attribute vb = node.attribute("viewBox")) {
        std::vector<double> v;
        AspectRatio aspect;
        try {
            v = parse_number_list(vb.value());
            aspect = parse_aspect_ratio(node.attribute("preserveAspectRatio").value());
        } catch (const SvgSyntaxError& e) {
            source.fail(node, e.what());
        }
        if (v.size() != 4 || !(v[2] > 0) || !(v[3] > 0))
            source.fail(node, "viewBox must be four numbers: min-x min-y width height > 0");
        if (!(w > 0) || !(h > 0))
            source.fail(node,
                        "a viewBox needs the viewport's width and height: set them, or give the "
                        "root <svg> a viewBox");
        out.transform = viewbox_transform(v, aspect, x, y, w, h);
        out.size = Geom::Point(v[2], v[3]);
    }
    return out;
}

}  // namespace acanthus::detail
