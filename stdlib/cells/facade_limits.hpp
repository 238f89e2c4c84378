// What texture() refuses before laying a cell: walls no course fits in, and facades too large to
// lay in memory and time.
#pragma once

#include <acanthus/stdlib/cells.hpp>

namespace acanthus::cells::detail {

// About how many cells fill the wall: its area over the mean cell's.
long expected_cells(const Facade& facade, const Options& options);

// Throws InputError naming the facade (and the wall shapes of a thin face).
void check_limits(const Facade& facade, const Options& options);

}  // namespace acanthus::cells::detail
