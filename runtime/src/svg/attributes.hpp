// Parsers for the SVG attribute values a region needs besides path data (which lib2geom
// parses): numbers, lengths, point lists, transform lists and style declarations.
#pragma once

#include <2geom/affine.h>
#include <2geom/point.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus::detail {

// A malformed attribute value; the SVG loader adds file and element to the message.
class SvgSyntaxError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// A length in user units: a number with an optional absolute unit (px, pt, pc, mm, cm, in).
// Percentages (see parse_length_or_percent) and font-relative units are refused.
double parse_length(std::string_view text);
// A length that may be a percentage of the viewport: `value` is in user units, or in percent
// when `percent` is set (the caller knows the viewport).
struct Length {
    double value = 0;
    bool percent = false;
};
Length parse_length_or_percent(std::string_view text);
// preserveAspectRatio: how a viewBox is fitted into a viewport.
struct AspectRatio {
    bool none = false;     // stretch to fill, ignoring the aspect ratio
    double align_x = 0.5;  // 0 = xMin, 0.5 = xMid, 1 = xMax
    double align_y = 0.5;  // 0 = YMin, 0.5 = YMid, 1 = YMax
    bool slice = false;    // cover the viewport (else meet: fit inside it)
};
// "[defer] <align> [meet|slice]"; an empty value is the default xMidYMid meet.
AspectRatio parse_aspect_ratio(std::string_view text);
// The transform that maps a viewBox (x, y, w, h, w and h > 0) into the viewport (x, y, w, h).
Geom::Affine viewbox_transform(const std::vector<double>& view_box, const AspectRatio& aspect,
                               double x, double y, double width, double height);
// The numbers of a list separated by whitespace and/or commas ("points", "viewBox").
std::vector<double> parse_number_list(std::string_view text);
// "points" of polygon/polyline: an even count of numbers.
std::vector<Geom::Point> parse_points(std::string_view text);
// A transform list: matrix, translate, scale, rotate (with optional centre), skewX, skewY,
// applied right to left as SVG says; the result maps element coordinates to the parent's.
Geom::Affine parse_transform(std::string_view text);
// The value of `property` in a style attribute ("fill-rule:evenodd;display:none"), if set.
std::optional<std::string> style_property(std::string_view style, std::string_view property);

// One rule of a CSS style sheet, reduced to what a region reads: a selector of type, class
// and id selectors (`path`, `.st0`, `#a`, `g.layer`, `*`) joined by descendant (` `) or child
// (`>`) combinators, with one declaration.
struct CssCompound {
    std::string type;  // "" or "*": any element
    std::string id;
    std::vector<std::string> classes;
};
struct CssRule {
    std::vector<CssCompound> compounds;  // left to right
    std::vector<char> combinators;       // between compounds: ' ' or '>'
    int specificity = 0;                 // ids * 10000 + classes * 100 + types
    bool important = false;
    std::size_t order = 0;  // position in the document's sheets
    std::string property, value;
};
// The rules of a style sheet that set one of `properties`, numbered from `order`. Selectors
// with other parts (attributes, pseudo-classes, sibling combinators) and at-rules (@media,
// @import, ...) are left out.
std::vector<CssRule> parse_style_sheet(std::string_view sheet,
                                       const std::vector<std::string_view>& properties,
                                       std::size_t& order);

}  // namespace acanthus::detail
