// %param values from the command line, checked against the declared type.
#include <acanthus/pattern.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace acanthus {
namespace {
template <class Int>
bool parse_integer(std::string_view text, Int& out, std::string& error, const char* type) {
    Int v{};
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
        error = "'" + std::string(text) + "' is not " + type;
        return false;
    }
    out = v;
    return true;
}
bool parse_real(std::string_view text, double& out, std::string& error) {
    std::string s(text);
    char* end = nullptr;
    double v = s.empty() ? 0.0 : std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) {
        error = "'" + s + "' is not a finite number";
        return false;
    }
    out = v;
    return true;
}
}  // namespace

bool parse_param(std::string_view text, int& out, std::string& error) {
    return parse_integer(text, out, error, "an int");
}
bool parse_param(std::string_view text, long& out, std::string& error) {
    return parse_integer(text, out, error, "a long");
}
bool parse_param(std::string_view text, double& out, std::string& error) {
    return parse_real(text, out, error);
}
bool parse_param(std::string_view text, float& out, std::string& error) {
    double v;
    if (!parse_real(text, v, error)) return false;
    out = static_cast<float>(v);
    return true;
}
bool parse_param(std::string_view text, bool& out, std::string& error) {
    if (text == "true" || text == "1" || text == "yes" || text == "on") {
        out = true;
    } else if (text == "false" || text == "0" || text == "no" || text == "off") {
        out = false;
    } else {
        error = "'" + std::string(text) + "' is not a bool (true/false, 1/0, yes/no, on/off)";
        return false;
    }
    return true;
}
bool parse_param(std::string_view text, std::string& out, std::string&) {
    out = std::string(text);
    return true;
}

std::string format_param(int v) { return std::to_string(v); }
std::string format_param(long v) { return std::to_string(v); }
std::string format_param(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    // Shortest form that reads back the same value.
    for (int prec = 1; prec <= 17; ++prec) {
        char t[64];
        std::snprintf(t, sizeof t, "%.*g", prec, v);
        if (std::strtod(t, nullptr) == v) return t;
    }
    return buf;
}
std::string format_param(float v) { return format_param(static_cast<double>(v)); }
std::string format_param(bool v) { return v ? "true" : "false"; }
std::string format_param(const std::string& v) { return v; }

}  // namespace acanthus
