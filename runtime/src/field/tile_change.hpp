// The pixels of one 8 x 8 tile whose distance changed (bit 8 * row + column): what the lazy
// field's measuring hands the EmptyCircleFinder, a tile at a time.
#pragma once

#include <cstdint>

namespace acanthus::detail {

struct TileChange {
    int tile = -1;
    std::uint64_t pixels = 0;
};

}  // namespace acanthus::detail
