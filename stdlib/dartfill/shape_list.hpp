// The shapes behind a ShapeSet, for the library's internals and tests.
#pragma once

#include <acanthus/stdlib/dartfill.hpp>
#include <vector>

#include "shape.hpp"

namespace acanthus::dartfill::detail {

struct ShapeList {
    std::vector<Shape> shapes;
};

}  // namespace acanthus::dartfill::detail
