#include "output/band_sink.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace acanthus::detail {

BandSink::BandSink(const Band& band, cairo_t* target, double tolerance, CanvasSink* next)
    : band_(band),
      target_(target),
      tolerance_(tolerance),
      step_(band.step(tolerance)),
      next_(next) {}

void BandSink::path(cairo_t* cr, bool fill) {
    // The path in the straight band's coordinates: the source context's device space.
    cairo_save(cr);
    cairo_set_tolerance(cr, tolerance_);
    cairo_matrix_t ctm;
    cairo_get_matrix(cr, &ctm);
    cairo_path_t* flat = cairo_copy_path_flat(cr);
    cairo_restore(cr);

    cairo_new_path(target_);
    Point last{0, 0}, start{0, 0};
    bool open = false;
    auto to_band = [&](double x, double y) {
        cairo_matrix_transform_point(&ctm, &x, &y);
        return Point{x, y};
    };
    auto line_to = [&](Point p) {  // subdivided so that the bent segment follows the bend
        const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(p.x - last.x) / step_)));
        for (int k = 1; k <= pieces; ++k) {
            const double f = double(k) / pieces;
            const Point q = band_.map({last.x + f * (p.x - last.x), last.y + f * (p.y - last.y)});
            cairo_line_to(target_, q.x, q.y);
        }
        last = p;
    };
    for (int i = 0; i < flat->num_data; i += flat->data[i].header.length) {
        const cairo_path_data_t* d = &flat->data[i];
        switch (d->header.type) {
            case CAIRO_PATH_MOVE_TO: {
                start = last = to_band(d[1].point.x, d[1].point.y);
                const Point q = band_.map(last);
                cairo_move_to(target_, q.x, q.y);
                open = true;
                break;
            }
            case CAIRO_PATH_LINE_TO:
                if (open) line_to(to_band(d[1].point.x, d[1].point.y));
                break;
            case CAIRO_PATH_CLOSE_PATH:
                if (open) {
                    line_to(start);
                    cairo_close_path(target_);
                }
                break;
            case CAIRO_PATH_CURVE_TO:  // not in a flat path
                break;
        }
    }
    cairo_path_destroy(flat);

    // The paint and line settings, widths carried from the source's user units to the band's.
    const double scale = std::sqrt(std::abs(ctm.xx * ctm.yy - ctm.xy * ctm.yx));
    cairo_save(target_);
    cairo_set_source(target_, cairo_get_source(cr));
    cairo_set_fill_rule(target_, cairo_get_fill_rule(cr));
    cairo_set_line_width(target_, cairo_get_line_width(cr) * scale);
    cairo_set_line_cap(target_, cairo_get_line_cap(cr));
    cairo_set_line_join(target_, cairo_get_line_join(cr));
    cairo_set_miter_limit(target_, cairo_get_miter_limit(cr));
    const int dashes = cairo_get_dash_count(cr);
    if (dashes > 0) {
        std::vector<double> dash(static_cast<std::size_t>(dashes));
        double offset = 0;
        cairo_get_dash(cr, dash.data(), &offset);
        for (double& d : dash) d *= scale;
        cairo_set_dash(target_, dash.data(), dashes, offset * scale);
    }
    if (next_)
        next_->path(target_, fill);
    else if (fill)
        cairo_fill(target_);
    else
        cairo_stroke(target_);
    cairo_new_path(target_);
    cairo_restore(target_);
}

void BandSink::circle(cairo_t* cr, Point center, double radius, bool fill) {
    cairo_new_path(cr);
    cairo_arc(cr, center.x, center.y, radius, 0, 2 * M_PI);
    cairo_close_path(cr);
    path(cr, fill);
    cairo_new_path(cr);
}

void BandSink::polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) {
    cairo_new_path(cr);
    for (const Point& p : points) cairo_line_to(cr, p.x, p.y);
    cairo_close_path(cr);
    path(cr, fill);
    cairo_new_path(cr);
}

}  // namespace acanthus::detail
