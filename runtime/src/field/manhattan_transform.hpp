// The Manhattan (city-block) distance field of Wong et al.'s MAT (section 4.1): computed in full
// and updated by a brushfire. Values are squares of city-block distances, so that they compare
// like the Euclidean field's squared distances (docs/field.md, "The Manhattan metric").
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace acanthus::detail {

// Over a w x h grid whose sites are the pixels with occ != 0 (occ == boundary_kind when
// `boundary_only`): d2 = squared city-block distance to the nearest site (INT32_MAX without
// sites), site = that site's index when not null (-1 without sites).
void manhattan_transform(int w, int h, const std::uint8_t* occ, bool boundary_only,
                         std::uint8_t boundary_kind, std::int32_t* d2, std::int32_t* site);

// Adds new sites (free pixels) to such a field: a breadth-first brushfire over the
// 4-neighbours it improves. Exact: along a shortest 4-path from the nearest new site to any
// pixel it improves, every pixel is improved too, and breadth-first order reaches each at its
// new distance first. Changed pixels are appended to `out` when it is not null.
void manhattan_brushfire(int w, int h, const std::vector<int>& sites, std::int32_t* d2,
                         std::int32_t* site, std::vector<int>* out,
                         std::vector<std::pair<int, std::int32_t>>& queue);

}  // namespace acanthus::detail
