// A second, shallow look at the drawing's elements: only their size attributes, fill and
// display, not the CSS cascade (a zero-size shape left unfilled by a style sheet is still named).
#include "zero_size_shapes.hpp"

#include <acanthus/error.hpp>
#include <cstdlib>
#include <cstring>
#include <pugixml.hpp>
#include <set>
#include <vector>

#include "svg/source.hpp"

namespace acanthus::cells::detail {

namespace {

std::string local_name(const char* name) {
    const char* colon = std::strrchr(name, ':');
    return colon ? colon + 1 : name;
}

// 0 for a missing attribute (SVG's default); a value that does not parse is left to the reader.
bool zero(pugi::xml_node node, const char* attribute) {
    pugi::xml_attribute a = node.attribute(attribute);
    if (!a) return true;
    char* end = nullptr;
    double v = std::strtod(a.value(), &end);
    return end != a.value() && v == 0;
}

bool zero_size(pugi::xml_node node, const std::string& tag) {
    if (tag == "rect") return zero(node, "width") || zero(node, "height");
    if (tag == "circle") return zero(node, "r");
    if (tag == "ellipse") {
        bool has_x = node.attribute("rx"), has_y = node.attribute("ry");
        if (!has_x && !has_y) return true;
        return (has_x && zero(node, "rx")) || (has_y && zero(node, "ry"));
    }
    return false;
}

bool unfilled(pugi::xml_node node) {
    for (pugi::xml_node n = node; n; n = n.parent()) {
        std::string fill = n.attribute("fill").value();
        if (!fill.empty() && fill != "inherit") return fill == "none";
    }
    return false;
}

bool hidden(pugi::xml_node node) {
    static const std::set<std::string> kNotDrawn = {"defs",   "clipPath", "mask",
                                                    "symbol", "pattern",  "marker"};
    for (pugi::xml_node n = node.parent(); n; n = n.parent())
        if (kNotDrawn.count(local_name(n.name()))) return true;
    for (pugi::xml_node n = node; n; n = n.parent())
        if (std::string(n.attribute("display").value()) == "none") return true;
    return false;
}

}  // namespace

void refuse_zero_size_shapes(std::string_view text, const std::string& name) {
    pugi::xml_document doc;
    if (!doc.load_buffer(text.data(), text.size(), pugi::parse_default)) return;
    acanthus::detail::SvgSource source(name, text);
    std::vector<pugi::xml_node> stack{doc.document_element()};
    while (!stack.empty()) {
        pugi::xml_node node = stack.back();
        stack.pop_back();
        for (pugi::xml_node c = node.last_child(); c; c = c.previous_sibling())
            if (c.type() == pugi::node_element) stack.push_back(c);
        std::string tag = local_name(node.name());
        if (!zero_size(node, tag) || unfilled(node) || hidden(node)) continue;
        std::string label = acanthus::detail::SvgSource::label(node);
        if (auto [line, col] = source.position(node.offset_debug()); line > 0)
            label += " (line " + std::to_string(line) + ")";
        throw InputError(name + ": " + label +
                         ": has no area (zero width, height or radius: SVG draws nothing, so it "
                         "is neither wall nor opening; remove it or give it a size)");
    }
}

}  // namespace acanthus::cells::detail
