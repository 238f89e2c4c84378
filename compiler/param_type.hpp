// %param types: which are allowed, how they appear in C++ and in the runtime's ParamInfo, and
// whether a default parses.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace acanthus {

struct ParamType {
    std::string_view cpp;   // type of the generated global: "std::string"
    std::string_view info;  // ParamInfo::type: "std::string"
};

// `written` is the type as written, words joined by one space.
std::optional<ParamType> find_param_type(std::string_view written);
std::string_view param_type_list();  // "int, long, float, double, bool, string, std::string"

// Whether `text` is a valid default for `type`; when not, `why` says what is expected.
bool default_parses(const ParamType& type, std::string_view text, std::string& why);

// int, long, float, double: the types that can declare a range `in [LO, HI]`.
bool is_numeric(const ParamType& type);

// The value of a numeric literal that default_parses accepted, for comparing bounds.
long double numeric_value(std::string_view text);

}  // namespace acanthus
