// The shapes behind a ShapeSet, for the library's internals and tests.
#pragma once

#include "shape.hpp"

#include <acanthus/dartfill.hpp>

#include <vector>

namespace acanthus::dartfill::detail {

struct ShapeList {
    std::vector<Shape> shapes;
};

}  // namespace acanthus::dartfill::detail
