// 8 x 8 grids as 64-bit masks (bit 8 * row + column): the EmptyCircleFinder's pixel masks
// per tile, with its crest prefilter on four pixels at a time, and the lazy field's tile masks
// per block (dilate(): the tiles next to one not exact).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>

#include "field/distance_field.hpp"
#include "field/lanes.hpp"

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

// The centre of a 3 x 3 neighbourhood of tile masks (at[dj + 1][di + 1]) dilated by one bit in
// the 8-neighbourhood, with the bits its neighbours' edges lend it.
inline std::uint64_t dilate(const std::uint64_t (&at)[3][3]) {
    const std::uint64_t m = at[1][1];
    // Within the rows: left and right neighbours, then up and down.
    std::uint64_t near = m | ((m << 1) & ~kColumn0) | ((m >> 1) & ~kColumn7) |
                         ((at[1][0] & kColumn7) >> 7) | ((at[1][2] & kColumn0) << 7);
    near |= (near << 8) | (near >> 8);
    // The last row of the mask above and the first row of the mask below, with the corners.
    near |= dilate_row(at[0][1] >> 56, (at[0][0] >> 63) & 1, (at[0][2] >> 56) & 1);
    near |= dilate_row(at[2][1] & kRow0, (at[2][0] >> 7) & 1, at[2][2] & 1) << 56;
    return near;
}

// dilate() of the mask at (i, j) in a w x h grid of masks; mask_at(a, b) gives each.
template <class MaskAt>
std::uint64_t dilate_in_grid(int i, int j, int w, int h, MaskAt mask_at) {
    std::uint64_t at[3][3];
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            const int a = i + di, b = j + dj;
            at[dj + 1][di + 1] = a < 0 || b < 0 || a >= w || b >= h ? 0 : mask_at(a, b);
        }
    return dilate(at);
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

// Bit x (0..3) set when pixel x of `mid` has a line with both neighbours at most as far, and
// a squared distance in [min_d2, infinite).
inline std::uint32_t crest_lanes(const std::int32_t* up, const std::int32_t* mid,
                                 const std::int32_t* down, std::int32_t min_d2) {
    const Lanes d = load_lanes(mid);
    const Lanes line = ((load_lanes(mid - 1) <= d) & (load_lanes(mid + 1) <= d)) |
                       ((load_lanes(up) <= d) & (load_lanes(down) <= d)) |
                       ((load_lanes(up - 1) <= d) & (load_lanes(down + 1) <= d)) |
                       ((load_lanes(up + 1) <= d) & (load_lanes(down - 1) <= d));
    const Lanes lo = {min_d2, min_d2, min_d2, min_d2};
    const Lanes inf = {DistanceField::infinite, DistanceField::infinite, DistanceField::infinite,
                       DistanceField::infinite};
    const Lanes weight = {1, 2, 4, 8};
    const Lanes keep = line & (d >= lo) & (d != inf) & weight;
    return static_cast<std::uint32_t>(keep[0] | keep[1] | keep[2] | keep[3]);
}

}  // namespace acanthus::detail::tile_masks
