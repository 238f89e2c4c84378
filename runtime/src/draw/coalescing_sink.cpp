// CoalescingSink: fewer Cairo operations for the same picture (coalescing_sink.hpp).
#include "draw/coalescing_sink.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace acanthus::detail {

namespace {

// At most 2^22 cells (two bytes each): cells of two device units on a 4096-unit square page.
constexpr double max_cells = 4194304.0;

// Shapes in one run at most.
constexpr long max_members = 1024;

// How often another style must come back, against the run's own, to become the run's style.
constexpr long switch_after = 16;

}  // namespace

SlotGrid::SlotGrid(double width, double height, int window) : window_(window) {
    width = std::max(width, 1.0);
    height = std::max(height, 1.0);
    cell_ = std::max(1.0, std::sqrt(width * height / max_cells));
    nx_ = static_cast<long>(std::ceil(width / cell_));
    ny_ = static_cast<long>(std::ceil(height / cell_));
    // Marking or testing a box costs its cells; past an eighth of the page, don't count them.
    large_ = std::max(64L, nx_ * ny_ / 8);
    run_.assign(static_cast<std::size_t>(nx_ * ny_), 0);
    other_.assign(static_cast<std::size_t>(nx_ * ny_), 0);
    marked_run_.resize(static_cast<std::size_t>(window));
    marked_other_.resize(static_cast<std::size_t>(window));
    everything_run_.assign(static_cast<std::size_t>(window), -1);
    everything_other_.assign(static_cast<std::size_t>(window), -1);
}

bool SlotGrid::cells(const Box& box, long& cx0, long& cy0, long& cx1, long& cy1) const {
    if (!(box.x0 <= box.x1 && box.y0 <= box.y1)) return false;  // NaN or empty: everything
    auto index = [&](double v, long n) {
        double c = std::floor(v / cell_);
        return static_cast<long>(std::clamp(c, 0.0, static_cast<double>(n - 1)));
    };
    cx0 = index(box.x0, nx_);
    cx1 = index(box.x1, nx_);
    cy0 = index(box.y0, ny_);
    cy1 = index(box.y1, ny_);
    return (cx1 - cx0 + 1) * (cy1 - cy0 + 1) <= large_;
}

// Codes 1..255 name slots modulo 255; the open ones are fewer than that, so one matches.
long SlotGrid::decode(std::uint8_t c, long first) const {
    if (c == 0) return -1;
    long offset = ((static_cast<long>(c) - 1 - first % 255) % 255 + 255) % 255;
    return first + offset;
}

void SlotGrid::newest(const Box& box, long first, long& run, long& other) const {
    run = other = -1;
    for (int k = 0; k < window_; ++k) {
        run = std::max(run, everything_run_[static_cast<std::size_t>(k)]);
        other = std::max(other, everything_other_[static_cast<std::size_t>(k)]);
    }
    long cx0, cy0, cx1, cy1;
    if (!cells(box, cx0, cy0, cx1, cy1)) {
        // Touches everything: after every open slot.
        run = other = first + window_ - 1;
        return;
    }
    for (long y = cy0; y <= cy1; ++y)
        for (long x = cx0; x <= cx1; ++x) {
            auto i = static_cast<std::size_t>(y * nx_ + x);
            run = std::max(run, decode(run_[i], first));
            other = std::max(other, decode(other_[i], first));
        }
}

void SlotGrid::mark(const Box& box, long slot, long first, bool run) {
    auto k = static_cast<std::size_t>(slot % window_);
    long cx0, cy0, cx1, cy1;
    if (!cells(box, cx0, cy0, cx1, cy1)) {
        (run ? everything_run_ : everything_other_)[k] = slot;
        return;
    }
    std::vector<std::uint8_t>& grid = run ? run_ : other_;
    std::vector<std::uint32_t>& marked = run ? marked_run_[k] : marked_other_[k];
    std::uint8_t c = code(slot);
    for (long y = cy0; y <= cy1; ++y)
        for (long x = cx0; x <= cx1; ++x) {
            auto i = static_cast<std::size_t>(y * nx_ + x);
            // Each cell keeps the newest slot: slots close oldest first.
            if (grid[i] == c || decode(grid[i], first) > slot) continue;
            grid[i] = c;
            marked.push_back(static_cast<std::uint32_t>(i));
        }
}

void SlotGrid::close(long slot) {
    auto k = static_cast<std::size_t>(slot % window_);
    std::uint8_t c = code(slot);
    for (std::uint32_t i : marked_run_[k])
        if (run_[i] == c) run_[i] = 0;
    for (std::uint32_t i : marked_other_[k])
        if (other_[i] == c) other_[i] = 0;
    marked_run_[k].clear();
    marked_other_[k].clear();
    if (everything_run_[k] == slot) everything_run_[k] = -1;
    if (everything_other_[k] == slot) everything_other_[k] = -1;
}

bool CoalescingSink::Style::operator==(const Style& o) const {
    if (fill != o.fill || r != o.r || g != o.g || b != o.b || a != o.a ||
        tolerance != o.tolerance || antialias != o.antialias)
        return false;
    if (std::memcmp(&matrix, &o.matrix, sizeof matrix) != 0) return false;
    if (fill) return rule == o.rule;
    return width == o.width && miter == o.miter && cap == o.cap && join == o.join;
}

CoalescingSink::CoalescingSink(cairo_t* cr, double width, double height)
    : held_(cairo_create(cairo_get_target(cr))),
      grid_(width, height, window),
      slots_(static_cast<std::size_t>(window)) {
    for (Slot& s : slots_) s.run = cairo_create(cairo_get_target(cr));
}

CoalescingSink::~CoalescingSink() {
    for (Slot& s : slots_) {
        for (Held& h : s.held) cairo_path_destroy(h.path);
        cairo_destroy(s.run);
    }
    cairo_destroy(held_);
}

bool CoalescingSink::gatherable(cairo_t* cr, bool fill, Style& s) {
    cairo_pattern_t* source = cairo_get_source(cr);
    if (cairo_get_operator(cr) != CAIRO_OPERATOR_OVER ||
        cairo_pattern_get_type(source) != CAIRO_PATTERN_TYPE_SOLID)
        return false;
    if (!fill && cairo_get_dash_count(cr) != 0) return false;
    s.fill = fill;
    cairo_pattern_get_rgba(source, &s.r, &s.g, &s.b, &s.a);
    s.rule = cairo_get_fill_rule(cr);
    s.width = cairo_get_line_width(cr);
    s.miter = cairo_get_miter_limit(cr);
    s.cap = cairo_get_line_cap(cr);
    s.join = cairo_get_line_join(cr);
    cairo_get_matrix(cr, &s.matrix);
    s.tolerance = cairo_get_tolerance(cr);
    s.antialias = cairo_get_antialias(cr);
    return true;
}

SlotGrid::Box CoalescingSink::ink_box(cairo_t* cr, bool fill) {
    double x0, y0, x1, y1;
    cairo_path_extents(cr, &x0, &y0, &x1, &y1);
    if (!fill) {
        // How far a stroke reaches past its path, in user units: half its width, times the
        // miter length at a mitred join, times sqrt 2 at a square cap's corners.
        double reach = 0.5 * cairo_get_line_width(cr);
        double factor = 1;
        if (cairo_get_line_join(cr) == CAIRO_LINE_JOIN_MITER)
            factor = std::max(factor, cairo_get_miter_limit(cr));
        if (cairo_get_line_cap(cr) == CAIRO_LINE_CAP_SQUARE) factor = std::max(factor, M_SQRT2);
        reach *= factor;
        x0 -= reach;
        y0 -= reach;
        x1 += reach;
        y1 += reach;
    }
    double xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
    SlotGrid::Box box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int k = 0; k < 4; ++k) {
        cairo_user_to_device(cr, &xs[k], &ys[k]);
        box.x0 = std::min(box.x0, xs[k]);
        box.y0 = std::min(box.y0, ys[k]);
        box.x1 = std::max(box.x1, xs[k]);
        box.y1 = std::max(box.y1, ys[k]);
    }
    // Antialiasing spreads an edge over the pixel it crosses.
    const double margin = 1;
    box.x0 -= margin;
    box.y0 -= margin;
    box.x1 += margin;
    box.y1 += margin;
    return box;
}

// In device coordinates (read under the identity), so the shapes keep Cairo's exact fixed-point
// positions when appended to a context that keeps the identity until it paints.
cairo_path_t* CoalescingSink::device_path(cairo_t* cr) {
    cairo_save(cr);
    cairo_identity_matrix(cr);
    cairo_path_t* path = cairo_copy_path(cr);
    cairo_restore(cr);
    return path;
}

void CoalescingSink::paint_as(cairo_t* cr, const Style& s) {
    ++painted_;
    cairo_set_matrix(cr, &s.matrix);
    cairo_set_source_rgba(cr, s.r, s.g, s.b, s.a);
    cairo_set_tolerance(cr, s.tolerance);
    cairo_set_antialias(cr, s.antialias);
    if (s.fill) {
        cairo_set_fill_rule(cr, s.rule);
        cairo_fill(cr);
    } else {
        cairo_set_line_width(cr, s.width);
        cairo_set_miter_limit(cr, s.miter);
        cairo_set_line_cap(cr, s.cap);
        cairo_set_line_join(cr, s.join);
        cairo_stroke(cr);
    }
    cairo_identity_matrix(cr);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("drawing failed: ") +
                                 cairo_status_to_string(cairo_status(cr)));
}

void CoalescingSink::paint(cairo_t* cr, bool fill) {
    ++painted_;
    if (fill)
        cairo_fill(cr);
    else
        cairo_stroke(cr);
}

void CoalescingSink::close_first() {
    Slot& s = slot(first_);
    for (Held& h : s.held) {  // none unless it was never first before (kept for safety)
        cairo_append_path(held_, h.path);
        cairo_path_destroy(h.path);
        paint_as(held_, h.style);
    }
    s.held.clear();
    if (s.has_run) paint_as(s.run, style_);
    s.has_run = false;
    s.members = 0;
    grid_.close(first_);
    ++first_;
    if (first_ < end_) {
        // The next slot comes first now: its held shapes precede its run and follow all else.
        Slot& next = slot(first_);
        for (Held& h : next.held) {
            cairo_append_path(held_, h.path);
            cairo_path_destroy(h.path);
            h.path = nullptr;
            paint_as(held_, h.style);
        }
        next.held.clear();
    } else {
        end_ = first_;
    }
}

void CoalescingSink::note_other_style(const Style& style) {
    // Two candidates, so that a style coming back between shapes of ever new colours (a dot's
    // rim between dots coloured by order) is counted; a new style replaces the rarer one.
    Candidate* hit = nullptr;
    for (Candidate& c : candidates_)
        if (c.count > 0 && c.style == style) hit = &c;
    if (!hit) {
        hit = candidates_[0].count <= candidates_[1].count ? &candidates_[0] : &candidates_[1];
        *hit = {style, 0};
    }
    ++hit->count;
    // It keeps coming back, more than the run's own style: it becomes the run's.
    if (hit->count >= switch_after && hit->count > 2 * gathered_) {
        flush();
        style_ = hit->style;
        gathered_ = 0;
        candidates_[0].count = candidates_[1].count = 0;
    }
}

void CoalescingSink::path(cairo_t* cr, bool fill) {
    ++received_;
    Style style;
    if (direct_ || !gatherable(cr, fill, style)) {
        flush();
        paint(cr, fill);
        return;
    }
    if (!has_style_) {
        style_ = style;
        has_style_ = true;
    }
    bool run = style == style_;
    if (!run) {
        note_other_style(style);
        run = style == style_;  // it may have just become the run's
    }
    SlotGrid::Box box = ink_box(cr, fill);
    long newest_run, newest_other;
    grid_.newest(box, first_, newest_run, newest_other);
    long at = std::max(first_, newest_other);  // with or after the other shapes it touches
    if (run) {
        // A union is exact for one opaque colour's strokes; anything else must not overlap.
        if ((fill || style.a < 1) && newest_run >= at) at = newest_run + 1;
    } else {
        at = std::max(at, newest_run + 1);  // after the runs it touches
    }
    while (at - first_ >= window) close_first();
    end_ = std::max(end_, at + 1);
    if (run) {
        Slot& s = slot(at);
        cairo_path_t* path = device_path(cr);
        cairo_append_path(s.run, path);
        cairo_path_destroy(path);
        s.has_run = true;
        ++gathered_;
        // Cairo works out a stroke's exact extents from its whole outline when it writes it: a
        // run of a few hundred thousand rims would need hundreds of MB for that moment.
        if (++s.members >= max_members) {
            grid_.mark(box, at, first_, run);
            while (first_ <= at) close_first();
            return;
        }
    } else if (at == first_) {
        paint(cr, fill);  // everything before it is painted; its slot's run comes after it
    } else {
        slot(at).held.push_back({device_path(cr), style});
    }
    grid_.mark(box, at, first_, run);
}

void CoalescingSink::circle(cairo_t* cr, Point center, double radius, bool fill) {
    // The path Canvas::fill_circle and Canvas::add_proxy draw.
    cairo_new_sub_path(cr);
    cairo_arc(cr, center.x, center.y, radius, 0, 2 * M_PI);
    cairo_close_path(cr);
    path(cr, fill);
    cairo_new_path(cr);
}

void CoalescingSink::polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) {
    cairo_move_to(cr, points[0].x, points[0].y);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr, points[i].x, points[i].y);
    cairo_close_path(cr);
    path(cr, fill);
    cairo_new_path(cr);
}

void CoalescingSink::escape(cairo_t*) {
    flush();
    direct_ = true;
}

void CoalescingSink::flush() {
    while (first_ < end_) close_first();
}

}  // namespace acanthus::detail
