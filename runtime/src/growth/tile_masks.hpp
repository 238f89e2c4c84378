// 8 x 8 pixel tiles as 64-bit masks (bit 8 * row + column): the bit tricks of the
// EmptyCircleFinder's incremental refresh, and its crest prefilter on four pixels at a time.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>

#include "growth/distance_field.hpp"

namespace acanthus::detail::tile_masks {

inline constexpr std::uint64_t kColumn0 = 0x0101010101010101ull;
inline constexpr std::uint64_t kColumn7 = 0x8080808080808080ull;
inline constexpr std::uint64_t kRow0 = 0xffull;
inline constexpr std::uint64_t kRow7 = 0xffull << 56;

// A row of 8 bits dilated by one column, with the corner pixels of the diagonal neighbours.
inline std::uint64_t dilate_row(std::uint64_t row, bool left_corner, bool right_corner) {
    return (row | ((row << 1) & 0xfe) | (row >> 1) | (left_corner ? 1u : 0u) |
            (right_corner ? 0x80u : 0u)) &
           0xff;
}

// Bit x set when byte x of the 8 at p is not zero.
inline std::uint32_t nonzero_bytes(const std::uint8_t* p) {
    if constexpr (std::endian::native == std::endian::little) {
        std::uint64_t v;
        std::memcpy(&v, p, sizeof v);
        // States are 0, 1 or 2: fold bit 1 onto bit 0, then gather bit 0 of every byte.
        v = (v | (v >> 1)) & 0x0101010101010101ull;
        return static_cast<std::uint32_t>((v * 0x0102040810204080ull) >> 56);
    } else {
        std::uint32_t out = 0;
        for (int x = 0; x < 8; ++x) out |= static_cast<std::uint32_t>(p[x] != 0) << x;
        return out;
    }
}

// Four lanes of int32: the crest prefilter runs on four pixels at a time.
using Lanes = std::int32_t __attribute__((vector_size(16)));

inline Lanes load(const std::int32_t* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// Bit x (0..3) set when pixel x of `mid` has a line with both neighbours at most as far, and
// a squared distance in [min_d2, infinite).
inline std::uint32_t crest_lanes(const std::int32_t* up, const std::int32_t* mid,
                                 const std::int32_t* down, std::int32_t min_d2) {
    const Lanes d = load(mid);
    const Lanes line = ((load(mid - 1) <= d) & (load(mid + 1) <= d)) |
                       ((load(up) <= d) & (load(down) <= d)) |
                       ((load(up - 1) <= d) & (load(down + 1) <= d)) |
                       ((load(up + 1) <= d) & (load(down - 1) <= d));
    const Lanes lo = {min_d2, min_d2, min_d2, min_d2};
    const Lanes inf = {DistanceField::infinite, DistanceField::infinite, DistanceField::infinite,
                       DistanceField::infinite};
    const Lanes weight = {1, 2, 4, 8};
    const Lanes keep = line & (d >= lo) & (d != inf) & weight;
    return static_cast<std::uint32_t>(keep[0] | keep[1] | keep[2] | keep[3]);
}

}  // namespace acanthus::detail::tile_masks
