// XML namespaces of an SVG file, resolved by URI (pugixml does not resolve them): which
// elements are SVG elements, and which attribute of a <use> is its XLink href.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "svg/source.hpp"

namespace acanthus::detail {

inline constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";
inline constexpr std::string_view kXlinkNamespace = "http://www.w3.org/1999/xlink";

// XML namespace declarations in scope: the xmlns and xmlns:PREFIX attributes of one element,
// linked to those of its ancestors. Names point into the document, which outlives every scope.
struct Namespaces {
    const Namespaces* parent = nullptr;
    // (prefix, URI); the prefix "" is the default namespace.
    std::vector<std::pair<std::string_view, std::string_view>> bindings;

    // Adds the declarations `node` makes itself.
    void declare(pugi::xml_node node);

    // Every declaration in scope at `node`, its own included, innermost first: the scope of an
    // element reached out of document order (the root, a <use> target).
    static Namespaces at(pugi::xml_node node);

    // The URI `prefix` is bound to; nullopt when it is not declared (an unprefixed name with
    // no default namespace, or a prefix nobody declared).
    static std::optional<std::string_view> uri(const Namespaces* scope, std::string_view prefix);
};

// Local name of an element in the SVG namespace, "" for elements of other namespaces
// (sodipodi:namedview, inkscape:*, metadata vocabularies) and for undeclared prefixes.
// `scope` includes the element's own declarations. The namespace is found by URI, so
// <svg:path> counts when xmlns:svg is bound to the SVG namespace. An unprefixed name with
// no default namespace in scope (a file without xmlns, or xmlns="") is read as SVG, as
// rsvg reads it.
std::string svg_name(pugi::xml_node node, const Namespaces* scope);

// The name without its prefix, whatever namespace that prefix is bound to.
std::string_view local_name(pugi::xml_node node);

// The reference of a <use>: SVG 2's plain href, else an href attribute in the XLink
// namespace under whatever prefix is bound to it (xlink:href, a0:href, ...). href under
// a prefix of another namespace is not a reference; under an undeclared prefix it is
// refused, as XML namespaces require (rsvg refuses the file too).
std::string use_href(const SvgSource& source, pugi::xml_node node, const Namespaces* scope);

}  // namespace acanthus::detail
