#include "region_svg_attributes.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

namespace acanthus::detail {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

std::string quoted(std::string_view s) {
    constexpr std::size_t kShown = 60;
    std::string out(s.substr(0, kShown));
    if (s.size() > kShown) out += "...";
    return "'" + out + "'";
}

// Reads one number at `pos` (after optional whitespace and at most one comma when `comma`).
// std::from_chars does not take a leading '+', SVG does.
bool read_number(std::string_view s, std::size_t& pos, double& value) {
    std::size_t p = pos;
    while (p < s.size() && is_space(s[p])) ++p;
    if (p < s.size() && s[p] == '+') ++p;
    if (p >= s.size()) return false;
    // from_chars would accept "inf"/"nan"; SVG numbers start with a digit, '.' or '-'.
    char c = s[p];
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-')) return false;
    auto [end, ec] = std::from_chars(s.data() + p, s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) {
        value = HUGE_VAL;  // reported by the caller's finiteness check
    } else if (ec != std::errc()) {
        return false;
    }
    pos = static_cast<std::size_t>(end - s.data());
    return true;
}

// Skips whitespace and at most one comma between list items.
void skip_separator(std::string_view s, std::size_t& pos) {
    while (pos < s.size() && is_space(s[pos])) ++pos;
    if (pos < s.size() && s[pos] == ',') ++pos;
    while (pos < s.size() && is_space(s[pos])) ++pos;
}

double finite_or_throw(double v, std::string_view text) {
    if (!std::isfinite(v)) throw SvgSyntaxError("number out of range in " + quoted(text));
    return v;
}

}  // namespace

double parse_length(std::string_view text) {
    std::string_view s = trim(text);
    std::size_t pos = 0;
    double v = 0;
    if (!read_number(s, pos, v)) throw SvgSyntaxError("not a length: " + quoted(text));
    std::string_view unit = trim(s.substr(pos));
    double scale = 1;
    if (unit.empty() || unit == "px") {
        scale = 1;
    } else if (unit == "pt") {
        scale = 96.0 / 72.0;
    } else if (unit == "pc") {
        scale = 16;
    } else if (unit == "mm") {
        scale = 96.0 / 25.4;
    } else if (unit == "cm") {
        scale = 96.0 / 2.54;
    } else if (unit == "in") {
        scale = 96;
    } else {
        throw SvgSyntaxError("unsupported length " + quoted(text) +
                             " (use user units or px, pt, pc, mm, cm, in)");
    }
    return finite_or_throw(v * scale, text);
}

std::vector<double> parse_number_list(std::string_view text) {
    std::vector<double> out;
    std::size_t pos = 0;
    while (pos < text.size() && is_space(text[pos])) ++pos;
    while (pos < text.size()) {
        double v = 0;
        if (!read_number(text, pos, v)) throw SvgSyntaxError("not a number list: " + quoted(text));
        out.push_back(finite_or_throw(v, text));
        skip_separator(text, pos);
    }
    return out;
}

std::vector<Geom::Point> parse_points(std::string_view text) {
    std::vector<double> v = parse_number_list(text);
    if (v.size() % 2 != 0)
        throw SvgSyntaxError("odd number of coordinates in points " + quoted(text));
    std::vector<Geom::Point> out;
    for (std::size_t i = 0; i + 1 < v.size(); i += 2) out.emplace_back(v[i], v[i + 1]);
    return out;
}

Geom::Affine parse_transform(std::string_view text) {
    Geom::Affine total = Geom::identity();
    std::size_t pos = 0;
    auto skip_space = [&] {
        while (pos < text.size() && is_space(text[pos])) ++pos;
    };
    skip_space();
    while (pos < text.size()) {
        std::size_t name_start = pos;
        while (pos < text.size() && std::isalpha(static_cast<unsigned char>(text[pos]))) ++pos;
        std::string_view name = text.substr(name_start, pos - name_start);
        skip_space();
        if (name.empty() || pos >= text.size() || text[pos] != '(')
            throw SvgSyntaxError("malformed transform " + quoted(text));
        ++pos;
        std::vector<double> a;
        skip_space();
        while (pos < text.size() && text[pos] != ')') {
            double v = 0;
            if (!read_number(text, pos, v))
                throw SvgSyntaxError("malformed transform " + quoted(text));
            a.push_back(finite_or_throw(v, text));
            skip_separator(text, pos);
        }
        if (pos >= text.size()) throw SvgSyntaxError("unclosed '(' in transform " + quoted(text));
        ++pos;  // ')'
        auto bad_count = [&] {
            return SvgSyntaxError("wrong number of arguments to " + std::string(name) +
                                  " in transform " + quoted(text));
        };
        constexpr double kDeg = M_PI / 180;
        Geom::Affine m;
        if (name == "matrix") {
            if (a.size() != 6) throw bad_count();
            m = Geom::Affine(a[0], a[1], a[2], a[3], a[4], a[5]);
        } else if (name == "translate") {
            if (a.empty() || a.size() > 2) throw bad_count();
            m = Geom::Affine(1, 0, 0, 1, a[0], a.size() == 2 ? a[1] : 0);
        } else if (name == "scale") {
            if (a.empty() || a.size() > 2) throw bad_count();
            m = Geom::Affine(a[0], 0, 0, a.size() == 2 ? a[1] : a[0], 0, 0);
        } else if (name == "rotate") {
            if (a.size() != 1 && a.size() != 3) throw bad_count();
            double c = std::cos(a[0] * kDeg), s = std::sin(a[0] * kDeg);
            m = Geom::Affine(c, s, -s, c, 0, 0);
            if (a.size() == 3) {
                // translate(cx, cy) rotate(a) translate(-cx, -cy)
                m = Geom::Affine(1, 0, 0, 1, -a[1], -a[2]) * m *
                    Geom::Affine(1, 0, 0, 1, a[1], a[2]);
            }
        } else if (name == "skewX") {
            if (a.size() != 1) throw bad_count();
            m = Geom::Affine(1, 0, std::tan(a[0] * kDeg), 1, 0, 0);
        } else if (name == "skewY") {
            if (a.size() != 1) throw bad_count();
            m = Geom::Affine(1, std::tan(a[0] * kDeg), 0, 1, 0, 0);
        } else {
            throw SvgSyntaxError("unknown transform '" + std::string(name) + "' in " +
                                 quoted(text));
        }
        // lib2geom composes left to right (p * A * B applies A first); SVG's list applies
        // its rightmost item first, so each new item goes in front.
        total = m * total;
        skip_separator(text, pos);
    }
    for (int i = 0; i < 6; ++i)
        if (!std::isfinite(total[i])) throw SvgSyntaxError("transform overflows " + quoted(text));
    return total;
}

std::optional<std::string> style_property(std::string_view style, std::string_view property) {
    std::optional<std::string> found;
    std::size_t start = 0;
    while (start <= style.size()) {
        std::size_t semi = style.find(';', start);
        std::string_view decl = style.substr(start, semi - start);
        std::size_t colon = decl.find(':');
        if (colon != std::string_view::npos && trim(decl.substr(0, colon)) == property) {
            std::string_view value = trim(decl.substr(colon + 1));
            // "!important" does not change anything between one element's own declarations.
            if (std::size_t bang = value.find('!'); bang != std::string_view::npos)
                value = trim(value.substr(0, bang));
            found = std::string(value);  // the last declaration wins
        }
        if (semi == std::string_view::npos) break;
        start = semi + 1;
    }
    return found;
}

}  // namespace acanthus::detail
