#include "svg/namespaces.hpp"

namespace acanthus::detail {
namespace {

constexpr std::string_view kXmlNamespace = "http://www.w3.org/XML/1998/namespace";

}  // namespace

void Namespaces::declare(pugi::xml_node node) {
    for (pugi::xml_attribute a : node.attributes()) {
        std::string_view name = a.name();
        if (name == "xmlns") {
            bindings.emplace_back(std::string_view(), a.value());
        } else if (name.substr(0, 6) == "xmlns:") {
            bindings.emplace_back(name.substr(6), a.value());
        }
    }
}

Namespaces Namespaces::at(pugi::xml_node node) {
    Namespaces ns;
    for (pugi::xml_node n = node; n; n = n.parent())
        if (n.type() == pugi::node_element) ns.declare(n);
    return ns;
}

std::optional<std::string_view> Namespaces::uri(const Namespaces* scope, std::string_view prefix) {
    for (const Namespaces* s = scope; s; s = s->parent)
        for (const auto& [p, u] : s->bindings)
            if (p == prefix) return u;
    if (prefix == "xml") return kXmlNamespace;
    return std::nullopt;
}

std::string svg_name(pugi::xml_node node, const Namespaces* scope) {
    std::string_view name = node.name();
    std::size_t colon = name.find(':');
    std::string_view prefix = colon == std::string_view::npos ? "" : name.substr(0, colon);
    std::string_view local = colon == std::string_view::npos ? name : name.substr(colon + 1);
    std::optional<std::string_view> uri = Namespaces::uri(scope, prefix);
    if (!uri) return prefix.empty() ? std::string(local) : std::string();
    if (uri->empty() && prefix.empty()) return std::string(local);  // xmlns=""
    return *uri == kSvgNamespace ? std::string(local) : std::string();
}

std::string_view local_name(pugi::xml_node node) {
    std::string_view name = node.name();
    std::size_t colon = name.find(':');
    return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

std::string use_href(const SvgSource& source, pugi::xml_node node, const Namespaces* scope) {
    if (pugi::xml_attribute a = node.attribute("href")) return a.value();
    for (pugi::xml_attribute a : node.attributes()) {
        std::string_view name = a.name();
        std::size_t colon = name.find(':');
        if (colon == std::string_view::npos || name.substr(colon + 1) != "href") continue;
        std::string_view prefix = name.substr(0, colon);
        if (prefix == "xmlns") continue;  // xmlns:href declares a prefix
        std::optional<std::string_view> uri = Namespaces::uri(scope, prefix);
        if (!uri)
            source.fail(node, "attribute " + std::string(name) + ": namespace prefix '" +
                                  std::string(prefix) +
                                  "' is not declared (xmlns:" + std::string(prefix) + "=\"" +
                                  std::string(kXlinkNamespace) + "\" would make it XLink)");
        if (*uri == kXlinkNamespace) return a.value();
    }
    return std::string();
}

}  // namespace acanthus::detail
