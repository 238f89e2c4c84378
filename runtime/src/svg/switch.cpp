#include "svg/switch.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <string_view>

namespace acanthus::detail {
namespace {

// Feature strings rsvg implements (requiredFeatures in a <switch>), sorted.
constexpr std::array<std::string_view, 21> kFeatures = {
    "http://www.w3.org/TR/SVG11/feature#BasicFilter",
    "http://www.w3.org/TR/SVG11/feature#BasicGraphicsAttribute",
    "http://www.w3.org/TR/SVG11/feature#BasicPaintAttribute",
    "http://www.w3.org/TR/SVG11/feature#BasicStructure",
    "http://www.w3.org/TR/SVG11/feature#BasicText",
    "http://www.w3.org/TR/SVG11/feature#ConditionalProcessing",
    "http://www.w3.org/TR/SVG11/feature#ContainerAttribute",
    "http://www.w3.org/TR/SVG11/feature#Filter",
    "http://www.w3.org/TR/SVG11/feature#Gradient",
    "http://www.w3.org/TR/SVG11/feature#Image",
    "http://www.w3.org/TR/SVG11/feature#Marker",
    "http://www.w3.org/TR/SVG11/feature#Mask",
    "http://www.w3.org/TR/SVG11/feature#OpacityAttribute",
    "http://www.w3.org/TR/SVG11/feature#Pattern",
    "http://www.w3.org/TR/SVG11/feature#SVG",
    "http://www.w3.org/TR/SVG11/feature#SVG-static",
    "http://www.w3.org/TR/SVG11/feature#Shape",
    "http://www.w3.org/TR/SVG11/feature#Structure",
    "http://www.w3.org/TR/SVG11/feature#Style",
    "http://www.w3.org/TR/SVG11/feature#View",
    "org.w3c.svg.static"};

// Whether every whitespace-separated word of `text` is `known`.
template <class Known>
bool words_all(std::string_view text, Known&& known) {
    std::istringstream in{std::string(text)};
    std::string word;
    while (in >> word)
        if (!known(word)) return false;
    return true;
}

}  // namespace

bool passes_conditions(pugi::xml_node node) {
    if (pugi::xml_attribute a = node.attribute("requiredExtensions"))
        if (!words_all(a.value(), [](const std::string&) { return false; })) return false;
    if (pugi::xml_attribute a = node.attribute("requiredFeatures"))
        if (!words_all(a.value(), [](const std::string& w) {
                return std::binary_search(kFeatures.begin(), kFeatures.end(), w);
            }))
            return false;
    return !node.attribute("systemLanguage");
}

}  // namespace acanthus::detail
