// The pixel grid the engine rasterizes the region on; shared by the engine, its rasterizers and
// the debug frames.
#pragma once

#include <acanthus/point.hpp>

namespace acanthus {

// Pixel (i, j) covers [x0 + i*pixel, x0 + (i+1)*pixel) horizontally, the same vertically from y0.
struct GridFrame {
    double x0 = 0, y0 = 0, pixel = 1;
    int width = 0, height = 0;
    Point center_of(int i, int j) const { return {x0 + (i + 0.5) * pixel, y0 + (j + 0.5) * pixel}; }
};

}  // namespace acanthus
