// Drawing bent onto a band's centre line (docs/symmetry.md): the Canvas draws in the straight
// band's coordinates on a context that paints nothing; each shape's path is flattened, every
// point (s, t) mapped to C(s) + t N(s), and the bent path painted on the target context with
// the same paint and line settings, or handed to a further sink (the structured SVG).
#pragma once

#include "draw/canvas_sink.hpp"
#include "region/band.hpp"

namespace acanthus::detail {

class BandSink : public CanvasSink {
  public:
    // `target` has the page's transformation (user units of the band's page); `next`, when
    // given, receives the bent shapes on `target` instead of Cairo painting them.
    // `tolerance` is the flattening error allowed, in user units.
    BandSink(const Band& band, cairo_t* target, double tolerance, CanvasSink* next = nullptr);

    void path(cairo_t* cr, bool fill) override;
    void circle(cairo_t* cr, Point center, double radius, bool fill) override;
    void polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) override;

  private:
    const Band& band_;
    cairo_t* target_;
    double tolerance_, step_;
    CanvasSink* next_;
};

}  // namespace acanthus::detail
