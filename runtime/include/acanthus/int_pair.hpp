// "WxH" pairs of whole numbers, as `--view-size`, `--repeat` and the preview's `?view=` take
// them: one rule for the program and the preview's server (header-only, so both may include it).
#pragma once

#include <charconv>
#include <optional>
#include <string_view>
#include <utility>

namespace acanthus {

// The picture's size in pixels, each side (`--view-size`, the preview's `?view=`).
inline constexpr int view_size_min = 16;
inline constexpr int view_size_max = 8192;

// "NxM" (or "NXM"), N and M decimal whole numbers from `low` to `high`; nullopt otherwise.
inline std::optional<std::pair<int, int>> read_int_pair(std::string_view text, int low, int high) {
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string_view::npos) return std::nullopt;
    const auto number = [&](std::string_view digits) -> std::optional<int> {
        int v = 0;
        const char* last = digits.data() + digits.size();
        auto [ptr, ec] = std::from_chars(digits.data(), last, v);
        if (digits.empty() || ec != std::errc() || ptr != last || v < low || v > high)
            return std::nullopt;
        return v;
    };
    const auto n = number(text.substr(0, x));
    const auto m = number(text.substr(x + 1));
    if (!n || !m) return std::nullopt;
    return std::pair{*n, *m};
}

inline std::optional<std::pair<int, int>> read_view_size(std::string_view text) {
    return read_int_pair(text, view_size_min, view_size_max);
}

}  // namespace acanthus
