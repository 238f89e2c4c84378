// The output as a repeat of its tile (--repeat NxM, --svg-pattern; docs/symmetry.md): where the
// N x M copies go and which translations of the tile's content cover them.
#pragma once

#include <acanthus/point.hpp>
#include <acanthus/render.hpp>
#include <string>
#include <utility>
#include <vector>

namespace acanthus::detail {

struct RepeatLayout {
    RepeatTile tile;
    int n = 1, m = 1;  // copies along a and along b

    // The N x M parallelogram's corners, from the origin, counter-clockwise in u, v.
    std::vector<Point> corners() const;
    Rect bounds() const;
    // The translations i a + j b of the N x M copies, 0 <= i < N, 0 <= j < M, (0, 0) first.
    std::vector<Point> offsets() const;
};

// "NxM" with 1 <= N, M <= 100. Throws UsageError otherwise.
std::pair<int, int> parse_repeat(const std::string& text);

// "NxM" (or "NXM") with low <= N, M <= high; throws UsageError(usage) otherwise.
std::pair<int, int> parse_int_pair(const std::string& text, int low, int high,
                                   const std::string& usage);

// True when `options` ask for a repeat or a pattern.
bool repeats(const RenderOptions& options);

// The layout for `options`: its tile, or the region's bounding box `bounds` as the tile.
RepeatLayout repeat_layout(const Rect& bounds, const RenderOptions& options);

}  // namespace acanthus::detail
