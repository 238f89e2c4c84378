// The coordinate range a placed element must stay in: beyond it, distances, rasterization and
// rendering lose their precision or their time bounds. A body that goes there has failed.
#pragma once

#include <acanthus/proxy.hpp>
#include <string>

#include "geometry/coordinate_range.hpp"

namespace acanthus::detail {

// Empty when the (finite) proxy is in range; otherwise what is wrong, e.g.
// "a negative radius (-3)" or "a coordinate beyond +-1e9 (x = 1e+300)".
std::string proxy_range_problem(const Proxy& proxy);

}  // namespace acanthus::detail
