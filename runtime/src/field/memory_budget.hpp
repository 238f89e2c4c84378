// What the growth engine's per-pixel state costs and what the machine can give it: a buffer too
// large for memory is refused before anything is allocated (docs/field.md, "Memory").
#pragma once

#include <acanthus/grid_frame.hpp>
#include <cstdint>
#include <optional>

namespace acanthus::detail {

// Bytes per buffer pixel the incremental engine holds at its peak: the render buffer's
// occupancy (1), squared distance (4), squared distance to the boundary (4), fill stamps (2),
// the finder's tile masks (1: 64 bytes a tile), the lazy field's tile bounds and marks (under
// 1), and room for the ornament and the pixels the first placements change.
inline constexpr double kGrowthBytesPerPixel = 16;

// Bytes this process may still allocate: the smallest of the memory the system reports
// available, the address-space and data limits (setrlimit) left above what it uses now, and
// a container's cgroup memory limit left above its usage. Nothing when none is known.
std::optional<std::uint64_t> available_memory();

// Throws InputError when a buffer of this grid would not fit in available_memory(), with the
// estimate in the message.
void check_growth_memory(const GridFrame& grid, int resolution);

}  // namespace acanthus::detail
