// Where a Canvas sends its shapes when it does not paint them through Cairo (the structured SVG).
#pragma once

#include <acanthus/point.hpp>
#include <vector>

typedef struct _cairo cairo_t;

namespace acanthus::detail {

// Each call reads the colour, line settings and transformation from `cr`, which the Canvas keeps
// up to date; the sink paints nothing on it.
class CanvasSink {
  public:
    virtual ~CanvasSink() = default;
    // The current path of `cr`, filled or stroked (the Canvas clears it afterwards).
    virtual void path(cairo_t* cr, bool fill) = 0;
    // A whole circle or polygon drawn on an empty path: kept as a shape, not as a path.
    virtual void circle(cairo_t* cr, Point center, double radius, bool fill) = 0;
    virtual void polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) = 0;
    // canvas.cairo() is about to hand `cr` out: whatever the sink holds back must be painted.
    virtual void escape(cairo_t* /*cr*/) {}
};

}  // namespace acanthus::detail
