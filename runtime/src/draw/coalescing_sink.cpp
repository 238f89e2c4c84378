// CoalescingSink: fewer Cairo operations for the same picture (coalescing_sink.hpp).
#include "draw/coalescing_sink.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace acanthus::detail {

namespace {

// At most 2^24 cells (2 MB of bits): a cell of one device unit up to a 4096-unit square page.
constexpr double max_cells = 16777216.0;

}  // namespace

InkGrid::InkGrid(double width, double height) {
    width = std::max(width, 1.0);
    height = std::max(height, 1.0);
    cell_ = std::max(1.0, std::sqrt(width * height / max_cells));
    nx_ = static_cast<long>(std::ceil(width / cell_));
    ny_ = static_cast<long>(std::ceil(height / cell_));
    // Marking or testing a box costs its cells; past an eighth of the page, don't count them.
    large_ = std::max(64L, nx_ * ny_ / 8);
    bits_.assign(static_cast<std::size_t>((nx_ * ny_ + 63) / 64), 0);
}

bool InkGrid::cells(const Box& box, long& cx0, long& cy0, long& cx1, long& cy1) const {
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

bool InkGrid::hits(const Box& box) const {
    if (everything_) return true;
    long cx0, cy0, cx1, cy1;
    if (!cells(box, cx0, cy0, cx1, cy1)) return true;
    for (long y = cy0; y <= cy1; ++y)
        for (long x = cx0; x <= cx1; ++x) {
            auto i = static_cast<std::size_t>(y * nx_ + x);
            if (bits_[i / 64] >> (i % 64) & 1) return true;
        }
    return false;
}

void InkGrid::mark(const Box& box) {
    long cx0, cy0, cx1, cy1;
    if (!cells(box, cx0, cy0, cx1, cy1)) {
        everything_ = true;
        return;
    }
    for (long y = cy0; y <= cy1; ++y)
        for (long x = cx0; x <= cx1; ++x) {
            auto i = static_cast<std::size_t>(y * nx_ + x);
            std::uint64_t bit = std::uint64_t{1} << (i % 64);
            if (bits_[i / 64] & bit) continue;
            bits_[i / 64] |= bit;
            marked_.push_back(static_cast<std::uint32_t>(i));
        }
}

void InkGrid::clear() {
    for (std::uint32_t i : marked_) bits_[i / 64] = 0;
    marked_.clear();
    everything_ = false;
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
    : run_(cairo_create(cairo_get_target(cr))), grid_(width, height) {}

CoalescingSink::~CoalescingSink() { cairo_destroy(run_); }

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

InkGrid::Box CoalescingSink::ink_box(cairo_t* cr, bool fill) {
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
    InkGrid::Box box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
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

void CoalescingSink::paint(cairo_t* cr, bool fill) {
    ++painted_;
    if (fill)
        cairo_fill(cr);
    else
        cairo_stroke(cr);
}

// The path is copied in device coordinates (the run's context keeps the identity until it
// paints), so the shapes keep Cairo's exact fixed-point positions.
void CoalescingSink::gather(cairo_t* cr, const InkGrid::Box& box) {
    cairo_save(cr);
    cairo_identity_matrix(cr);
    cairo_path_t* path = cairo_copy_path(cr);
    cairo_restore(cr);
    cairo_append_path(run_, path);
    cairo_path_destroy(path);
    grid_.mark(box);
}

void CoalescingSink::path(cairo_t* cr, bool fill) {
    ++received_;
    if (direct_) {
        paint(cr, fill);
        return;
    }
    Style style;
    bool gather_it = gatherable(cr, fill, style);
    InkGrid::Box box = ink_box(cr, fill);
    if (pending_) {
        // Same style: a union, exact for one opaque colour's strokes, else only where disjoint.
        if (gather_it && style == style_ && ((!fill && style.a >= 1) || !grid_.hits(box))) {
            gather(cr, box);
            return;
        }
        // Apart from everything gathered: painting it now, under the run, changes no pixel.
        if (cairo_get_operator(cr) == CAIRO_OPERATOR_OVER && !grid_.hits(box)) {
            paint(cr, fill);
            return;
        }
        flush();
    }
    if (!gather_it) {
        paint(cr, fill);
        return;
    }
    style_ = style;
    pending_ = true;
    gather(cr, box);
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
    if (!pending_) return;
    pending_ = false;
    grid_.clear();
    const Style& s = style_;
    cairo_set_matrix(run_, &s.matrix);
    cairo_set_source_rgba(run_, s.r, s.g, s.b, s.a);
    cairo_set_tolerance(run_, s.tolerance);
    cairo_set_antialias(run_, s.antialias);
    ++painted_;
    if (s.fill) {
        cairo_set_fill_rule(run_, s.rule);
        cairo_fill(run_);
    } else {
        cairo_set_line_width(run_, s.width);
        cairo_set_miter_limit(run_, s.miter);
        cairo_set_line_cap(run_, s.cap);
        cairo_set_line_join(run_, s.join);
        cairo_stroke(run_);
    }
    cairo_identity_matrix(run_);
    if (cairo_status(run_) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("drawing failed: ") +
                                 cairo_status_to_string(cairo_status(run_)));
}

}  // namespace acanthus::detail
