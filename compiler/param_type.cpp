#include "param_type.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace acanthus {

std::optional<ParamType> find_param_type(std::string_view written) {
    if (written == "int") return ParamType{"int", "int"};
    if (written == "long") return ParamType{"long", "long"};
    if (written == "float") return ParamType{"float", "float"};
    if (written == "double") return ParamType{"double", "double"};
    if (written == "bool") return ParamType{"bool", "bool"};
    if (written == "string" || written == "std::string") {
        return ParamType{"std::string", "std::string"};
    }
    return std::nullopt;
}

std::string_view param_type_list() { return "int, long, float, double, bool, string, std::string"; }

namespace {

bool all_digits(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
    }
    return true;
}

// A decimal floating literal as C++ and the runtime both read it: digits, optional fraction,
// optional exponent; at least one digit.
bool is_decimal_number(std::string_view s) {
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        if (!all_digits(s.substr(i))) return false;
        i = s.size();
    }
    return i == s.size();
}

template <class T>
bool integer_fits(std::string_view s) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    T value{};
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

bool default_parses(const ParamType& type, std::string_view text, std::string& why) {
    std::string_view body = text;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
    if (type.cpp == "int" || type.cpp == "long") {
        bool ok = all_digits(body) &&
                  (type.cpp == "int" ? integer_fits<int>(text) : integer_fits<long>(text));
        if (!ok) why = "an integer that fits in '" + std::string(type.cpp) + "'";
        return ok;
    }
    if (type.cpp == "float" || type.cpp == "double") {
        bool ok = is_decimal_number(text);
        if (ok) {
            std::string_view s = text[0] == '+' ? text.substr(1) : text;
            double value = 0;
            auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
            ok = ec == std::errc() && end == s.data() + s.size() && std::isfinite(value) &&
                 (type.cpp == "double" || std::fabs(value) <= std::numeric_limits<float>::max());
        }
        if (!ok) why = "a finite decimal number such as 2.5 or -1e-3";
        return ok;
    }
    if (type.cpp == "bool") {
        bool ok = text == "true" || text == "false";
        if (!ok) why = "'true' or 'false'";
        return ok;
    }
    // std::string: one string literal with simple escapes.
    bool ok = text.size() >= 2 && text.front() == '"' && text.back() == '"';
    for (std::size_t i = 1; ok && i + 1 < text.size(); ++i) {
        if (text[i] == '\\') {
            ++i;
            ok = i + 1 < text.size() &&
                 std::string_view("\\\"'nrt0").find(text[i]) != std::string_view::npos;
        } else if (text[i] == '"' || static_cast<unsigned char>(text[i]) < 0x20) {
            ok = false;
        }
    }
    if (!ok) why = "a string literal in double quotes, such as \"red\"";
    return ok;
}

bool is_numeric(const ParamType& type) {
    return type.cpp == "int" || type.cpp == "long" || type.cpp == "float" || type.cpp == "double";
}

long double numeric_value(std::string_view text) {
    std::string s(text);
    return std::strtold(s.c_str(), nullptr);
}

}  // namespace acanthus
