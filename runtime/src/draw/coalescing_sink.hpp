// A CanvasSink for Cairo's vector surfaces (PDF, PostScript, EPS) that paints fewer, larger
// operations: Cairo records every fill and stroke of a page, with its own copy of path, source and
// style (about 1 KB each), until the page ends.
#pragma once

#include <cairo.h>

#include <cstdint>
#include <vector>

#include "draw/canvas_sink.hpp"

namespace acanthus::detail {

// Which cells of the page the pending run covers (device units, a cell of a unit or more).
class InkGrid {
  public:
    InkGrid(double width, double height);
    struct Box {
        double x0, y0, x1, y1;
    };
    bool hits(const Box& box) const;
    void mark(const Box& box);
    void clear();

  private:
    // Cell range of a box, clamped to the grid (what lies off the page lands on its border).
    bool cells(const Box& box, long& cx0, long& cy0, long& cx1, long& cy1) const;

    double cell_;
    long nx_, ny_;
    long large_;  // a box of more cells counts as covering everything
    bool everything_ = false;
    std::vector<std::uint64_t> bits_;
    std::vector<std::uint32_t> marked_;  // the cells set, to clear them in their number's time
};

// Shapes of one opaque-enough solid colour and one style are gathered into one path while what
// is painted between them does not touch them, and painted as one operation when that stops
// being true. The picture is the same: a painted shape that touches none of the gathered ones
// (boxes a device unit apart) gives the same pixels before or after them; a union of strokes of
// one opaque colour paints what the strokes did one by one; fills are gathered only where they do
// not overlap (under the even-odd rule, or with opposite windings, overlaps would be holes).
// Anything else (another operator, a gradient, a dash, a canvas.cairo() call) first paints the run.
class CoalescingSink : public CanvasSink {
  public:
    // `cr` draws on the page; the run is built and painted on a context of its own on the same
    // surface. `width` x `height` is the page in device units.
    CoalescingSink(cairo_t* cr, double width, double height);
    ~CoalescingSink() override;
    CoalescingSink(const CoalescingSink&) = delete;
    CoalescingSink& operator=(const CoalescingSink&) = delete;

    void path(cairo_t* cr, bool fill) override;
    void circle(cairo_t* cr, Point center, double radius, bool fill) override;
    void polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) override;
    // canvas.cairo(): the run is painted, and the rest of the element is drawn as it comes (its
    // clip and state are no longer the Canvas's to know).
    void escape(cairo_t* cr) override;
    // The element is over (its state restored): gathering may start again.
    void end_element() { direct_ = false; }

    // Paints the run. Throws std::runtime_error if Cairo reports an error.
    void flush();

    // Operations sent to Cairo, and shapes received (for tests and measurements).
    long painted() const { return painted_; }
    long received() const { return received_; }

  private:
    struct Style {
        bool fill = true;
        double r = 0, g = 0, b = 0, a = 1;
        cairo_fill_rule_t rule = CAIRO_FILL_RULE_WINDING;
        double width = 0, miter = 0;
        cairo_line_cap_t cap = CAIRO_LINE_CAP_BUTT;
        cairo_line_join_t join = CAIRO_LINE_JOIN_MITER;
        cairo_matrix_t matrix{};
        double tolerance = 0;
        cairo_antialias_t antialias = CAIRO_ANTIALIAS_DEFAULT;
        bool operator==(const Style& o) const;
    };
    // The style of the current operation; false when it cannot be gathered.
    static bool gatherable(cairo_t* cr, bool fill, Style& style);
    // The device-space box of what the operation may paint, a device unit wider all round.
    static InkGrid::Box ink_box(cairo_t* cr, bool fill);
    void paint(cairo_t* cr, bool fill);
    void gather(cairo_t* cr, const InkGrid::Box& box);

    cairo_t* run_;
    InkGrid grid_;
    Style style_;
    bool pending_ = false;
    bool direct_ = false;
    long painted_ = 0, received_ = 0;
};

}  // namespace acanthus::detail
