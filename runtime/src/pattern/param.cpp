// %param values from the command line, checked against the declared type.
#include <acanthus/param.hpp>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace acanthus {
namespace {
template <class Int>
bool parse_integer(std::string_view text, Int& out, std::string& error, const char* type) {
    Int v{};
    std::string_view digits = text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (!digits.empty() && ec == std::errc::result_out_of_range &&
        ptr == digits.data() + digits.size()) {
        // Built by appending: GCC 12 warns falsely (-Wrestrict, bug 105329) on "lit" + string&&.
        error = std::string("'").append(text) + "' is out of range for " + type + " (" +
                std::to_string(std::numeric_limits<Int>::min()) + " to " +
                std::to_string(std::numeric_limits<Int>::max()) + ")";
        return false;
    }
    if (digits.empty() || ec != std::errc() || ptr != digits.data() + digits.size()) {
        error =
            std::string("'").append(text) + "' is not " + (type[0] == 'i' ? "an " : "a ") + type;
        return false;
    }
    out = v;
    return true;
}

// A nonzero value that rounds to zero (or to a denormal) has lost its meaning as surely as one
// that overflows: both are out of range.
template <class Real>
bool parse_real(std::string_view text, Real& out, std::string& error, const char* type) {
    std::string s(text);
    char* end = nullptr;
    errno = 0;
    const double v = s.empty() ? 0.0 : std::strtod(s.c_str(), &end);
    const bool overflow = errno == ERANGE && std::abs(v) > 1;
    if (s.empty() || end != s.c_str() + s.size() || (!std::isfinite(v) && !overflow)) {
        error = "'" + s + "' is not a finite number";
        return false;
    }
    const Real r = static_cast<Real>(v);
    const bool underflow =
        (v == 0 && errno == ERANGE) || (v != 0 && std::abs(r) < std::numeric_limits<Real>::min());
    if (overflow || !std::isfinite(r) || underflow) {
        std::ostringstream range;
        range << std::numeric_limits<Real>::min() << " to " << std::numeric_limits<Real>::max();
        error =
            "'" + s + "' is out of range for " + type + " (magnitudes " + range.str() + ", or 0)";
        return false;
    }
    out = r;
    return true;
}
}  // namespace

bool parse_param(std::string_view text, int& out, std::string& error) {
    return parse_integer(text, out, error, "int");
}
bool parse_param(std::string_view text, long& out, std::string& error) {
    return parse_integer(text, out, error, "long");
}
bool parse_param(std::string_view text, double& out, std::string& error) {
    return parse_real(text, out, error, "double");
}
bool parse_param(std::string_view text, float& out, std::string& error) {
    return parse_real(text, out, error, "float");
}
bool parse_param(std::string_view text, bool& out, std::string& error) {
    if (text == "true" || text == "1" || text == "yes" || text == "on") {
        out = true;
    } else if (text == "false" || text == "0" || text == "no" || text == "off") {
        out = false;
    } else {
        error = std::string("'").append(text) + "' is not a bool (true/false, 1/0, yes/no, on/off)";
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

namespace {
// Filled during static initialisation of the program (register_param_flag): a function-local
// static, so that it exists whichever translation unit registers first.
std::vector<ParamFlag>& flags() {
    static std::vector<ParamFlag> all;
    return all;
}
}  // namespace

bool register_param_flag(ParamFlag flag) {
    for (const ParamFlag& f : flags())
        if (f.flag == flag.flag) return true;
    flags().push_back(std::move(flag));
    return true;
}

const std::vector<ParamFlag>& param_flags() { return flags(); }

}  // namespace acanthus
