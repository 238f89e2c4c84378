// The CSS cascade for the properties the SVG reader reads (fill-rule, display, fill, stroke,
// stroke-width): the rules of a file's <style> sheets, the style attribute and presentation
// attributes, in CSS order.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "svg/attributes.hpp"

namespace acanthus::detail {

class StyleCascade {
  public:
    // Adds the rules of every <style> element of the SVG namespace (type text/css or none)
    // that set one of those properties; throws InputError naming `file` when there are too many.
    void read(const std::vector<pugi::xml_node>& style_elements, const std::string& file);

    // A property as the cascade gives it: !important style-sheet rules, then the style
    // attribute, then style-sheet rules (by specificity, then order), then the presentation
    // attribute.
    std::optional<std::string> property(pugi::xml_node node, const char* name) const;

  private:
    std::vector<CssRule> rules_;
    // Rules by the last compound of their selector: "#id", ".class", type or "*".
    std::map<std::string, std::vector<std::size_t>> index_;
};

}  // namespace acanthus::detail
