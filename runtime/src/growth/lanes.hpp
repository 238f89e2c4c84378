// Four int32 lanes in one SSE2-sized vector (GCC vector extensions): the crest prefilter and
// the lazy field's measuring work on 4 pixels of a tile row at a time.
#pragma once

#include <cstdint>
#include <cstring>

namespace acanthus::detail {

using Lanes = std::int32_t __attribute__((vector_size(16)));

inline Lanes load_lanes(const std::int32_t* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

}  // namespace acanthus::detail
