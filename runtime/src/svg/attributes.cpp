#include "svg/attributes.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

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
    Length l = parse_length_or_percent(text);
    if (l.percent)
        throw SvgSyntaxError("unsupported length " + quoted(text) +
                             " (use user units or px, pt, pc, mm, cm, in)");
    return l.value;
}

Length parse_length_or_percent(std::string_view text) {
    std::string_view s = trim(text);
    std::size_t pos = 0;
    double v = 0;
    if (!read_number(s, pos, v)) throw SvgSyntaxError("not a length: " + quoted(text));
    std::string_view unit = trim(s.substr(pos));
    double scale = 1;
    if (unit == "%") return {finite_or_throw(v, text), true};
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
                             " (use user units or px, pt, pc, mm, cm, in, %)");
    }
    return {finite_or_throw(v * scale, text), false};
}

AspectRatio parse_aspect_ratio(std::string_view text) {
    AspectRatio r;
    std::vector<std::string_view> words;
    std::string_view s = trim(text);
    while (!s.empty()) {
        std::size_t end = 0;
        while (end < s.size() && !is_space(s[end])) ++end;
        words.push_back(s.substr(0, end));
        s = trim(s.substr(end));
    }
    std::size_t i = 0;
    if (i < words.size() && words[i] == "defer") ++i;
    if (i < words.size()) {
        std::string_view align = words[i++];
        if (align == "none") {
            r.none = true;
        } else if (align.size() == 8 && align[0] == 'x' && align[4] == 'Y') {
            auto place = [](std::string_view w) {
                return w == "Min" ? 0.0 : w == "Mid" ? 0.5 : w == "Max" ? 1.0 : -1.0;
            };
            r.align_x = place(align.substr(1, 3));
            r.align_y = place(align.substr(5, 3));
            if (r.align_x < 0 || r.align_y < 0)
                throw SvgSyntaxError("malformed preserveAspectRatio " + quoted(text));
        } else {
            throw SvgSyntaxError("malformed preserveAspectRatio " + quoted(text));
        }
    }
    if (i < words.size()) {
        if (words[i] == "slice") {
            r.slice = true;
        } else if (words[i] != "meet") {
            throw SvgSyntaxError("malformed preserveAspectRatio " + quoted(text));
        }
        ++i;
    }
    if (i != words.size()) throw SvgSyntaxError("malformed preserveAspectRatio " + quoted(text));
    return r;
}

Geom::Affine viewbox_transform(const std::vector<double>& view_box, const AspectRatio& aspect,
                               double x, double y, double width, double height) {
    double sx = width / view_box[2], sy = height / view_box[3];
    if (!aspect.none) sx = sy = aspect.slice ? std::max(sx, sy) : std::min(sx, sy);
    double tx = x - view_box[0] * sx, ty = y - view_box[1] * sy;
    if (!aspect.none) {
        tx += (width - view_box[2] * sx) * aspect.align_x;
        ty += (height - view_box[3] * sy) * aspect.align_y;
    }
    return Geom::Affine(sx, 0, 0, sy, tx, ty);
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

namespace {

// A compound selector ("g.layer#a"); false when it has parts a region does not match on.
bool parse_compound(std::string_view text, CssCompound& out, int& specificity) {
    std::size_t p = 0;
    auto name_end = [&](std::size_t from) {
        while (from < text.size() &&
               (std::isalnum(static_cast<unsigned char>(text[from])) || text[from] == '-' ||
                text[from] == '_' || static_cast<unsigned char>(text[from]) >= 0x80))
            ++from;
        return from;
    };
    if (p < text.size() && text[p] == '*') {
        ++p;
    } else {
        std::size_t e = name_end(p);
        out.type = std::string(text.substr(p, e - p));
        if (!out.type.empty()) ++specificity;
        p = e;
    }
    while (p < text.size()) {
        char c = text[p];
        if (c != '.' && c != '#') return false;
        std::size_t e = name_end(p + 1);
        if (e == p + 1) return false;
        std::string name(text.substr(p + 1, e - p - 1));
        if (c == '.') {
            out.classes.push_back(name);
            specificity += 100;
        } else {
            out.id = name;
            specificity += 10000;
        }
        p = e;
    }
    return p > 0;
}

// "g.a > path" into compounds and combinators; false for selectors a region does not match.
bool parse_selector(std::string_view text, CssRule& rule) {
    std::string spaced;
    for (char c : text) {
        if (c == '>') {
            spaced += " > ";
        } else {
            spaced += is_space(c) ? ' ' : c;
        }
    }
    std::istringstream words(spaced);
    std::string word;
    char pending = 0;
    while (words >> word) {
        if (word == ">") {
            if (rule.compounds.empty() || pending) return false;
            pending = '>';
            continue;
        }
        CssCompound compound;
        if (!parse_compound(word, compound, rule.specificity)) return false;
        if (!rule.compounds.empty()) rule.combinators.push_back(pending ? pending : ' ');
        pending = 0;
        rule.compounds.push_back(std::move(compound));
    }
    return !rule.compounds.empty() && !pending;
}

// Index of the '}' closing the block opened at `open`, or npos.
std::size_t block_end(std::string_view s, std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < s.size(); ++i) {
        if (s[i] == '{') ++depth;
        if (s[i] == '}' && --depth == 0) return i;
    }
    return std::string_view::npos;
}

}  // namespace

std::vector<CssRule> parse_style_sheet(std::string_view sheet,
                                       const std::vector<std::string_view>& properties,
                                       std::size_t& order) {
    // Comments out first ("<!--" and "-->" may wrap a sheet too).
    std::string text;
    for (std::size_t i = 0; i < sheet.size();) {
        if (sheet.compare(i, 2, "/*") == 0) {
            std::size_t end = sheet.find("*/", i + 2);
            i = end == std::string_view::npos ? sheet.size() : end + 2;
        } else if (sheet.compare(i, 4, "<!--") == 0 || sheet.compare(i, 3, "-->") == 0) {
            i += sheet[i] == '<' ? 4 : 3;
        } else {
            text += sheet[i++];
        }
    }
    std::vector<CssRule> rules;
    std::string_view s = text;
    std::size_t p = 0;
    while (p < s.size()) {
        while (p < s.size() && (is_space(s[p]) || s[p] == ';')) ++p;
        if (p >= s.size()) break;
        std::size_t open = s.find('{', p);
        std::size_t semi = s.find(';', p);
        if (s[p] == '@' && semi < open) {  // @import ...; @charset ...;
            p = semi + 1;
            continue;
        }
        if (open == std::string_view::npos) break;
        std::size_t close = block_end(s, open);
        if (close == std::string_view::npos) close = s.size();
        std::string_view prelude = trim(s.substr(p, open - p));
        std::string_view body = s.substr(open + 1, close - open - 1);
        p = close + 1;
        if (prelude.empty() || prelude[0] == '@') continue;  // @media, @font-face, ...
        std::vector<CssRule> declared;
        std::size_t start = 0;
        while (start <= body.size()) {
            std::size_t end = body.find(';', start);
            std::string_view decl = body.substr(start, end - start);
            std::size_t colon = decl.find(':');
            if (colon != std::string_view::npos) {
                std::string_view name = trim(decl.substr(0, colon));
                if (std::find(properties.begin(), properties.end(), name) != properties.end()) {
                    CssRule r;
                    r.property = std::string(name);
                    std::string_view value = trim(decl.substr(colon + 1));
                    if (std::size_t bang = value.find('!'); bang != std::string_view::npos) {
                        r.important = trim(value.substr(bang + 1)) == "important";
                        value = trim(value.substr(0, bang));
                    }
                    r.value = std::string(value);
                    declared.push_back(std::move(r));
                }
            }
            if (end == std::string_view::npos) break;
            start = end + 1;
        }
        std::size_t from = 0;
        while (from <= prelude.size()) {
            std::size_t comma = prelude.find(',', from);
            CssRule selector;
            if (parse_selector(prelude.substr(from, comma - from), selector)) {
                for (const CssRule& d : declared) {
                    CssRule r = selector;
                    r.property = d.property;
                    r.value = d.value;
                    r.important = d.important;
                    r.order = order++;
                    rules.push_back(std::move(r));
                }
            }
            if (comma == std::string_view::npos) break;
            from = comma + 1;
        }
    }
    return rules;
}

}  // namespace acanthus::detail
