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
// Percentages and font-relative units are refused: they need a viewport a region lacks.
double parse_length(std::string_view text);
// The numbers of a list separated by whitespace and/or commas ("points", "viewBox").
std::vector<double> parse_number_list(std::string_view text);
// "points" of polygon/polyline: an even count of numbers.
std::vector<Geom::Point> parse_points(std::string_view text);
// A transform list: matrix, translate, scale, rotate (with optional centre), skewX, skewY,
// applied right to left as SVG says; the result maps element coordinates to the parent's.
Geom::Affine parse_transform(std::string_view text);
// The value of `property` in a style attribute ("fill-rule:evenodd;display:none"), if set.
std::optional<std::string> style_property(std::string_view style, std::string_view property);

}  // namespace acanthus::detail
