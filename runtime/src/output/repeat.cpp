#include "output/repeat.hpp"

#include <acanthus/error.hpp>
#include <acanthus/int_pair.hpp>
#include <algorithm>
#include <limits>

namespace acanthus::detail {

namespace {

constexpr int max_copies = 100;

Point at(const RepeatTile& t, double u, double v) {
    return {t.origin.x + u * t.a.x + v * t.b.x, t.origin.y + u * t.a.y + v * t.b.y};
}

}  // namespace

std::vector<Point> RepeatLayout::corners() const {
    return {at(tile, 0, 0), at(tile, n, 0), at(tile, n, m), at(tile, 0, m)};
}

Rect RepeatLayout::bounds() const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Rect r{inf, inf, -inf, -inf};
    for (const Point& p : corners()) {
        r.x0 = std::min(r.x0, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x);
        r.y1 = std::max(r.y1, p.y);
    }
    return r;
}

std::vector<Point> RepeatLayout::offsets() const {
    std::vector<Point> out;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i)
            out.push_back({i * tile.a.x + j * tile.b.x, i * tile.a.y + j * tile.b.y});
    return out;
}

std::pair<int, int> parse_int_pair(const std::string& text, int low, int high,
                                   const std::string& usage) {
    const auto pair = read_int_pair(text, low, high);
    if (!pair) throw UsageError(usage);
    return *pair;
}

std::pair<int, int> parse_repeat(const std::string& text) {
    return parse_int_pair(text, 1, max_copies,
                          "--repeat expects NxM, N and M whole numbers from 1 to " +
                              std::to_string(max_copies) + " (e.g. 3x3), not '" + text + "'");
}

bool repeats(const RenderOptions& o) { return o.svg_pattern || o.repeat_x > 1 || o.repeat_y > 1; }

RepeatLayout repeat_layout(const Rect& bounds, const RenderOptions& o) {
    RepeatLayout layout;
    layout.n = o.repeat_x;
    layout.m = o.repeat_y;
    if (o.tile)
        layout.tile = *o.tile;
    else
        layout.tile = {{bounds.x0, bounds.y0}, {bounds.width(), 0}, {0, bounds.height()}};
    return layout;
}

}  // namespace acanthus::detail
