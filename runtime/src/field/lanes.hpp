// Four int32 lanes in one SSE2-sized vector (GCC vector extensions): the crest prefilter and
// the lazy field's measuring work on 4 pixels of a tile row at a time.
#pragma once

#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace acanthus::detail {

using Lanes = std::int32_t __attribute__((vector_size(16)));

inline Lanes load_lanes(const std::int32_t* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

inline void store_lanes(std::int32_t* p, Lanes v) { std::memcpy(p, &v, sizeof v); }

// Bit l set when lane l of a comparison's result is true (all ones).
inline unsigned lane_mask(Lanes m) {
#if defined(__SSE2__)
    return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps((__m128i)m)));
#else
    const Lanes bits = m & Lanes{1, 2, 4, 8};
    return static_cast<unsigned>(bits[0] | bits[1] | bits[2] | bits[3]);
#endif
}

}  // namespace acanthus::detail
