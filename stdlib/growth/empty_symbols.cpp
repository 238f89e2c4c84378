#include "empty_symbols.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <pugixml.hpp>
#include <set>
#include <vector>

namespace acanthus::growth::detail {
namespace {

std::string local_name(pugi::xml_node node) {
    std::string name = node.name();
    std::size_t colon = name.find(':');
    return colon == std::string::npos ? name : name.substr(colon + 1);
}

// Hidden as the reader sees it (display none, as an attribute or in the style): not drawn, and
// not an error (a hidden Inkscape layer).
bool hidden(pugi::xml_node node) {
    if (std::string(node.attribute("display").value()) == "none") return true;
    std::string style = node.attribute("style").value();
    style.erase(std::remove(style.begin(), style.end(), ' '), style.end());
    return style.find("display:none") != std::string::npos;
}

struct Owner {
    pugi::xml_node node;
    bool drawn = false;
};

// `owner`: index of the nearest data-symbol ancestor (-1: none), which owns the shapes below it.
void walk(pugi::xml_node node, int owner, std::vector<Owner>& owners) {
    // What the reader never draws from directly: templates (a <use> draws them) and non-graphics.
    static const std::set<std::string> kTemplates = {
        "defs",   "clipPath", "mask",          "symbol",         "metadata",
        "title",  "desc",     "style",         "script",         "pattern",
        "marker", "filter",   "foreignObject", "linearGradient", "radialGradient"};
    static const std::set<std::string> kShapes = {"path", "rect",     "circle",  "ellipse",
                                                  "line", "polyline", "polygon", "use"};
    const std::string tag = local_name(node);
    if (kTemplates.count(tag) || hidden(node)) return;
    if (node.attribute("data-symbol")) {
        owner = static_cast<int>(owners.size());
        owners.push_back({node, false});
    }
    if (owner >= 0 && kShapes.count(tag)) owners[static_cast<std::size_t>(owner)].drawn = true;
    for (pugi::xml_node child : node.children())
        if (child.type() == pugi::node_element) walk(child, owner, owners);
}

}  // namespace

void check_symbols_own_shapes(std::string_view text, const std::string& name) {
    pugi::xml_document doc;
    if (!doc.load_buffer(text.data(), text.size(), pugi::parse_default)) return;
    std::vector<Owner> owners;
    for (pugi::xml_node child : doc.children())
        if (child.type() == pugi::node_element) walk(child, -1, owners);
    for (const Owner& o : owners) {
        if (o.drawn) continue;
        const auto offset =
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, o.node.offset_debug()));
        const long line =
            1 + std::count(text.begin(),
                           text.begin() + static_cast<long>(std::min(offset, text.size())), '\n');
        std::string label = "<" + std::string(o.node.name());
        if (const char* id = o.node.attribute("id").value(); *id)
            label.append(" id=\"").append(id).append("\"");
        label += ">";
        throw InputError(name + ": " + label + " (line " + std::to_string(line) +
                         "): carries data-symbol=\"" + o.node.attribute("data-symbol").value() +
                         "\" but owns no shape (an empty group, or only text or images): draw "
                         "its shapes in it, or remove data-symbol");
    }
}

}  // namespace acanthus::growth::detail
