// Filled <rect>, <circle> and <ellipse> elements of zero size: SVG does not draw them, so the
// shared reader hands nothing back, but in a facade they are a wall or opening the author meant.
#pragma once

#include <string>
#include <string_view>

namespace acanthus::cells::detail {

// Throws InputError "NAME: <rect id="a"> (line N): has no area (...)" for the first one.
void refuse_zero_size_shapes(std::string_view text, const std::string& name);

}  // namespace acanthus::cells::detail
