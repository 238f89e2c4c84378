// Colours for %draw bodies and the renderer: the hue wheel and CSS-style colour strings.
#include <acanthus/canvas.hpp>
#include <acanthus/error.hpp>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <string_view>

namespace acanthus {

Color hue(double t, double saturation, double value) {
    if (!std::isfinite(t)) t = 0;
    double s = std::clamp(std::isfinite(saturation) ? saturation : 0.0, 0.0, 1.0);
    double v = std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0);
    // The wheel wraps, so %draw bodies may pass an ever-growing order * step.
    double h = (t - std::floor(t)) * 6.0;
    int sector = std::min(static_cast<int>(h), 5);
    double f = h - sector;
    double p = v * (1 - s), q = v * (1 - s * f), u = v * (1 - s * (1 - f));
    switch (sector) {
        case 0:
            return {v, u, p, 1};
        case 1:
            return {q, v, p, 1};
        case 2:
            return {p, v, u, 1};
        case 3:
            return {p, q, v, 1};
        case 4:
            return {u, p, v, 1};
        default:
            return {v, p, q, 1};
    }
}

namespace {

struct NamedColor {
    std::string_view name;
    unsigned rgb;
};

// The 16 basic CSS colours, their common aliases and a few frequently used extended names.
constexpr std::array<NamedColor, 38> named_colors{{
    {"black", 0x000000},     {"silver", 0xc0c0c0},   {"gray", 0x808080},    {"grey", 0x808080},
    {"white", 0xffffff},     {"maroon", 0x800000},   {"red", 0xff0000},     {"purple", 0x800080},
    {"fuchsia", 0xff00ff},   {"magenta", 0xff00ff},  {"green", 0x008000},   {"lime", 0x00ff00},
    {"olive", 0x808000},     {"yellow", 0xffff00},   {"navy", 0x000080},    {"blue", 0x0000ff},
    {"teal", 0x008080},      {"aqua", 0x00ffff},     {"cyan", 0x00ffff},    {"orange", 0xffa500},
    {"brown", 0xa52a2a},     {"pink", 0xffc0cb},     {"gold", 0xffd700},    {"beige", 0xf5f5dc},
    {"ivory", 0xfffff0},     {"linen", 0xfaf0e6},    {"wheat", 0xf5deb3},   {"tan", 0xd2b48c},
    {"khaki", 0xf0e68c},     {"indigo", 0x4b0082},   {"violet", 0xee82ee},  {"crimson", 0xdc143c},
    {"darkgreen", 0x006400}, {"darkblue", 0x00008b}, {"darkred", 0x8b0000}, {"lightgray", 0xd3d3d3},
    {"lightgrey", 0xd3d3d3}, {"darkgray", 0xa9a9a9},
}};

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

Color from_rgb(unsigned rgb) {
    return {((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0, 1};
}

[[noreturn]] void bad_color(const std::string& text) {
    throw InputError("bad colour '" + text +
                     "': expected #rgb, #rgba, #rrggbb, #rrggbbaa, none or a CSS colour name");
}

}  // namespace

Color parse_color(const std::string& text) {
    // Surrounding blanks are forgiven (shell quoting); blanks inside are not.
    std::size_t begin = 0, end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    std::string s = text.substr(begin, end - begin);
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (s == "none" || s == "transparent") return {0, 0, 0, 0};
    if (!s.empty() && s[0] == '#') {
        std::string_view hex = std::string_view(s).substr(1);
        if (hex.size() != 3 && hex.size() != 4 && hex.size() != 6 && hex.size() != 8)
            bad_color(text);
        std::array<double, 4> channel{0, 0, 0, 1};
        bool short_form = hex.size() <= 4;
        std::size_t count = short_form ? hex.size() : hex.size() / 2;
        for (std::size_t i = 0; i < count; ++i) {
            int value;
            if (short_form) {
                int d = hex_digit(hex[i]);
                if (d < 0) bad_color(text);
                value = d * 17;
            } else {
                int hi = hex_digit(hex[2 * i]), lo = hex_digit(hex[2 * i + 1]);
                if (hi < 0 || lo < 0) bad_color(text);
                value = hi * 16 + lo;
            }
            channel[i] = value / 255.0;
        }
        return {channel[0], channel[1], channel[2], channel[3]};
    }
    for (const NamedColor& named : named_colors)
        if (named.name == s) return from_rgb(named.rgb);
    bad_color(text);
}

}  // namespace acanthus
