// What the SVG reader hands its consumers (regions, growth references and guides, facades): each
// drawn shape in the root's user units, with the element that drew it and its ancestors.
#pragma once

#include <2geom/pathvector.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace acanthus::detail {

// An element on the way from the root to a shape. A <use> is the parent of what it draws.
struct SvgElement {
    std::string tag;                          // local name: "g", "path", "use", ...
    std::string id;                           // "" when none
    std::vector<std::string> classes;         // the words of its class attribute
    std::map<std::string, std::string> data;  // data-* attributes, keyed without "data-"
    std::string label;                        // <g id="a"> (line 12), for messages
    std::shared_ptr<const SvgElement> parent;

    bool has_class(const std::string& word) const;
};

struct SvgShape {
    Geom::PathVector paths;  // transforms applied; subpaths as drawn (open ones stay open)
    bool evenodd = false;    // fill-rule in effect
    std::string fill = "black", stroke = "none";  // paint as the cascade gives it (inherited)
    double stroke_width = 1;                      // in root user units (scaled by the transform)
    std::shared_ptr<const SvgElement> element;    // the shape's own element
};

}  // namespace acanthus::detail
