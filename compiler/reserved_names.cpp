#include "reserved_names.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace acanthus {

namespace {

constexpr std::string_view kCppKeywords[] = {
    "alignas",       "alignof",     "and",
    "and_eq",        "asm",         "auto",
    "bitand",        "bitor",       "bool",
    "break",         "case",        "catch",
    "char",          "char8_t",     "char16_t",
    "char32_t",      "class",       "compl",
    "concept",       "const",       "consteval",
    "constexpr",     "constinit",   "const_cast",
    "continue",      "co_await",    "co_return",
    "co_yield",      "decltype",    "default",
    "delete",        "do",          "double",
    "dynamic_cast",  "else",        "enum",
    "explicit",      "export",      "extern",
    "false",         "float",       "for",
    "friend",        "goto",        "if",
    "inline",        "int",         "long",
    "mutable",       "namespace",   "new",
    "noexcept",      "not",         "not_eq",
    "nullptr",       "operator",    "or",
    "or_eq",         "private",     "protected",
    "public",        "register",    "reinterpret_cast",
    "requires",      "return",      "short",
    "signed",        "sizeof",      "static",
    "static_assert", "static_cast", "struct",
    "switch",        "template",    "this",
    "thread_local",  "throw",       "true",
    "try",           "typedef",     "typeid",
    "typename",      "union",       "unsigned",
    "using",         "virtual",     "void",
    "volatile",      "wchar_t",     "while",
    "xor",           "xor_eq",      "final",
    "override",      "import",      "module",
    "main",
};

// Names the support library puts in scope of every body (acanthus::body), and the generated
// code's own names.
constexpr std::string_view kSupportNames[] = {
    "acanthus",
    "std",
    "Point",
    "Vector",
    "Direction",
    "Circle",
    "Corner",
    "Rect",
    "Element",
    "Proxy",
    "Canvas",
    "Color",
    "SkeletalStroke",
    "parse_color",
    "PointProxy",
    "CircleProxy",
    "ArcProxy",
    "LineSegmentProxy",
    "BezierProxy",
    "PolygonProxy",
    "Result",
    "Flow",
    "SUCCESS",
    "FAILURE",
    "CONTINUE",
    "STOP",
    "min",
    "max",
    "rng",
    "distance",
    "hue",
    "lerp",
    "midpoint",
    "intersection",
    "inside",
    "distance_to_boundary",
    "nearest_element",
    "clear_exclude_list",
    "corners",
    "new_child",
    "report_progress",
    "goal",
    "RandomSource",
    "canvas",
    "M_PI",
};

}  // namespace

std::optional<std::string> reserved_name_problem(std::string_view name) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict, bug 105329) on "lit" + string&&.
    std::string quoted("'");
    quoted.append(name).append("'");
    for (std::string_view k : kCppKeywords) {
        if (k == name) return quoted + " is a C++ keyword";
    }
    for (std::string_view k : kSupportNames) {
        if (k == name) {
            return quoted + " is already a name of the rule support library";
        }
    }
    if (name.substr(0, 4) == "acr_" || (!name.empty() && name.back() == '_') ||
        name.find("__") != std::string_view::npos ||
        (name.size() > 1 && name[0] == '_' && name[1] >= 'A' && name[1] <= 'Z')) {
        return quoted +
               " is reserved (names starting with 'acr_' or ending in '_' belong to the "
               "generated code; '__' and '_X' belong to C++)";
    }
    return std::nullopt;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

}  // namespace acanthus
