// A CanvasSink for Cairo's vector surfaces (PDF, PostScript, EPS) that paints fewer, larger
// operations: Cairo records every fill and stroke of a page, with its own copy of path, source and
// style (about 1 KB each), until the page ends.
#pragma once

#include <cairo.h>

#include <cstdint>
#include <vector>

#include "draw/canvas_sink.hpp"

namespace acanthus::detail {

// For each cell of the page (device units, a cell of a unit or more), the newest open slot whose
// run, and whose other shapes, cover it. Slots are numbered from 0 up; at most `window` are open,
// and a slot's marks are cleared when it closes.
class SlotGrid {
  public:
    struct Box {
        double x0, y0, x1, y1;
    };
    SlotGrid(double width, double height, int window);
    // The newest open slot covering any cell of `box` (-1: none), for runs and for others.
    void newest(const Box& box, long first, long& run, long& other) const;
    void mark(const Box& box, long slot, long first, bool run);
    // Slot `slot` closes (the oldest open one).
    void close(long slot);

  private:
    bool cells(const Box& box, long& cx0, long& cy0, long& cx1, long& cy1) const;
    std::uint8_t code(long slot) const { return static_cast<std::uint8_t>(slot % 255 + 1); }
    long decode(std::uint8_t c, long first) const;

    int window_;
    double cell_;
    long nx_, ny_;
    long large_;  // a box of more cells counts as covering the whole page
    std::vector<std::uint8_t> run_, other_;
    // Per open slot (by slot % window): the cells it marked, and whether it covers everything.
    std::vector<std::vector<std::uint32_t>> marked_run_, marked_other_;
    std::vector<long> everything_run_, everything_other_;  // the slot, or -1
};

// Shapes are painted in an order with the same picture but fewer operations. One style (a solid
// opaque-enough colour with its fill rule or stroke width, cap and join, the transformation) is
// the run's: its shapes are gathered into paths, one per slot. Every other shape goes into the
// oldest slot that keeps the order wherever shapes touch (boxes a device unit apart): after the
// runs it touches, with or after the other shapes it touches; a slot paints its other shapes in
// the order they came, then its run. Shapes that touch nothing in between commute; a union of
// strokes of one opaque colour paints what they did one by one; fills of the run are gathered only
// where they do not overlap (under the even-odd rule, or with opposite windings, overlaps would be
// holes). The run's style is the first one gathered, and later the one that keeps coming back.
// Anything else (another operator, a gradient, a dash, a canvas.cairo() call) first paints all.
class CoalescingSink : public CanvasSink {
  public:
    // `cr` draws on the page; runs are built and held shapes painted on contexts of their own on
    // the same surface. `width` x `height` is the page in device units.
    CoalescingSink(cairo_t* cr, double width, double height);
    ~CoalescingSink() override;
    CoalescingSink(const CoalescingSink&) = delete;
    CoalescingSink& operator=(const CoalescingSink&) = delete;

    void path(cairo_t* cr, bool fill) override;
    void circle(cairo_t* cr, Point center, double radius, bool fill) override;
    void polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) override;
    // canvas.cairo(): everything is painted, and the rest of the element is drawn as it comes
    // (its clip and state are no longer the Canvas's to know).
    void escape(cairo_t* cr) override;
    // The element is over (its state restored): gathering may start again.
    void end_element() { direct_ = false; }

    // Paints everything held. Throws std::runtime_error if Cairo reports an error.
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
    // A shape of another style waiting for its slot to come first: its path in device units.
    struct Held {
        cairo_path_t* path;
        Style style;
    };
    struct Slot {
        cairo_t* run = nullptr;  // the run's path, in device units
        bool has_run = false;
        long members = 0;
        std::vector<Held> held;
    };

    // The style of the current operation; false when it cannot be gathered.
    static bool gatherable(cairo_t* cr, bool fill, Style& style);
    // The device-space box of what the operation may paint, a device unit wider all round.
    static SlotGrid::Box ink_box(cairo_t* cr, bool fill);
    static cairo_path_t* device_path(cairo_t* cr);
    // Paints `style` on `cr`, whose path is in device units, and checks Cairo's status.
    void paint_as(cairo_t* cr, const Style& style);
    void paint(cairo_t* cr, bool fill);
    Slot& slot(long id) { return slots_[static_cast<std::size_t>(id % window)]; }
    // Paints the oldest open slot and closes it; the next one's held shapes are painted too.
    void close_first();
    void note_other_style(const Style& style);

    static constexpr int window = 6;
    cairo_t* held_;  // paints held shapes
    SlotGrid grid_;
    std::vector<Slot> slots_;
    long first_ = 0, end_ = 0;  // open slots: [first_, end_)
    bool has_style_ = false;
    Style style_;
    long gathered_ = 0;  // shapes gathered since the run's style was chosen
    // Other styles seen lately (candidates for the run's), and how often.
    struct Candidate {
        Style style;
        long count = 0;
    };
    Candidate candidates_[2];
    bool direct_ = false;
    long painted_ = 0, received_ = 0;
};

}  // namespace acanthus::detail
