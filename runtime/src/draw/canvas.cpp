// Canvas: the drawing surface of %draw bodies and of the default styles, a thin layer over Cairo.
#include <cairo.h>

#include <acanthus/canvas.hpp>
#include <algorithm>
#include <cmath>

#include "draw/canvas_sink.hpp"

namespace acanthus {

namespace {

// A point proxy has no extent; it is shown as a dot this many line widths in radius.
constexpr double point_dot_radius = 1.5;

}  // namespace

Canvas::Canvas(cairo_t* cr) : cr_(cr) {}

Canvas::Canvas(cairo_t* cr, detail::CanvasSink* sink) : cr_(cr), sink_(sink) {}

void Canvas::set_color(double r, double g, double b, double a) {
    cairo_set_source_rgba(cr_, r, g, b, a);
}

void Canvas::set_color(Color c) { cairo_set_source_rgba(cr_, c.r, c.g, c.b, c.a); }

void Canvas::set_line_width(double w) { cairo_set_line_width(cr_, w); }

double Canvas::line_width() const { return cairo_get_line_width(cr_); }

double Canvas::pixel() const {
    // The longer image of a device pixel's sides: under a non-uniform scale, the safe one.
    double ux = 1, uy = 0, vx = 0, vy = 1;
    cairo_device_to_user_distance(cr_, &ux, &uy);
    cairo_device_to_user_distance(cr_, &vx, &vy);
    return std::max(std::hypot(ux, uy), std::hypot(vx, vy));
}

void Canvas::move_to(Point p) { cairo_move_to(cr_, p.x, p.y); }

void Canvas::line_to(Point p) { cairo_line_to(cr_, p.x, p.y); }

void Canvas::curve_to(Point c1, Point c2, Point p) {
    cairo_curve_to(cr_, c1.x, c1.y, c2.x, c2.y, p.x, p.y);
}

// Angles grow from +x towards +y, the same sense as Direction and ArcProxy (y points down).
void Canvas::arc(Point center, double radius, double start, double end) {
    cairo_arc(cr_, center.x, center.y, radius, start, end);
}

void Canvas::close_path() { cairo_close_path(cr_); }

void Canvas::fill() {
    if (sink_) {
        sink_->path(cr_, true);
        cairo_new_path(cr_);
        return;
    }
    cairo_fill(cr_);
}

void Canvas::stroke() {
    if (sink_) {
        sink_->path(cr_, false);
        cairo_new_path(cr_);
        return;
    }
    cairo_stroke(cr_);
}

// A sink keeps a lone circle or polygon as that shape; on a path already begun it is just more
// path.
bool Canvas::send_shape(const Proxy& proxy, bool fill) {
    if (!sink_ || cairo_has_current_point(cr_) || !proxy.finite()) return false;
    switch (proxy.kind()) {
        case ProxyKind::point: {
            const auto& p = static_cast<const PointProxy&>(proxy);
            sink_->circle(cr_, Point{p.x, p.y}, point_dot_radius * line_width(), true);
            return true;
        }
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            sink_->circle(cr_, c.center, std::abs(c.radius), fill);
            return true;
        }
        case ProxyKind::polygon: {
            const auto& poly = static_cast<const PolygonProxy&>(proxy);
            if (poly.points.empty()) return false;
            sink_->polygon(cr_, poly.points, fill);
            return true;
        }
        default:
            return false;
    }
}

void Canvas::fill(const Proxy& proxy) {
    if (send_shape(proxy, true)) return;
    add_proxy(proxy);
    fill();
}

void Canvas::stroke(const Proxy& proxy) {
    if (send_shape(proxy, false)) return;
    add_proxy(proxy);
    // A point has no outline to stroke: its dot is filled instead.
    if (proxy.kind() == ProxyKind::point)
        fill();
    else
        stroke();
}

void Canvas::fill_circle(Point center, double radius) {
    if (sink_ && !cairo_has_current_point(cr_) && std::isfinite(center.x) &&
        std::isfinite(center.y) && std::isfinite(radius)) {
        if (radius > 0) sink_->circle(cr_, center, radius, true);  // Cairo draws nothing else
        return;
    }
    cairo_new_sub_path(cr_);
    cairo_arc(cr_, center.x, center.y, radius, 0, 2 * M_PI);
    cairo_close_path(cr_);
    fill();
}

void Canvas::fill_circle(Point center, double radius, Color color) {
    cairo_save(cr_);
    set_color(color);
    fill_circle(center, radius);
    cairo_restore(cr_);
}

// Unset or non-finite proxies add nothing: NaN coordinates would corrupt Cairo's fixed-point path.
void Canvas::add_proxy(const Proxy& proxy) {
    if (!proxy.finite()) return;
    switch (proxy.kind()) {
        case ProxyKind::point: {
            const auto& p = static_cast<const PointProxy&>(proxy);
            cairo_new_sub_path(cr_);
            cairo_arc(cr_, p.x, p.y, point_dot_radius * line_width(), 0, 2 * M_PI);
            cairo_close_path(cr_);
            break;
        }
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            cairo_new_sub_path(cr_);
            cairo_arc(cr_, c.center.x, c.center.y, std::abs(c.radius), 0, 2 * M_PI);
            cairo_close_path(cr_);
            break;
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(proxy);
            cairo_new_sub_path(cr_);
            cairo_arc(cr_, a.center.x, a.center.y, std::abs(a.radius), a.start, a.end);
            break;
        }
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(proxy);
            cairo_move_to(cr_, l.p0.x, l.p0.y);
            cairo_line_to(cr_, l.p1.x, l.p1.y);
            break;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(proxy);
            cairo_move_to(cr_, b.c[0].x, b.c[0].y);
            cairo_curve_to(cr_, b.c[1].x, b.c[1].y, b.c[2].x, b.c[2].y, b.c[3].x, b.c[3].y);
            break;
        }
        case ProxyKind::polygon: {
            const auto& poly = static_cast<const PolygonProxy&>(proxy);
            if (poly.points.empty()) break;
            cairo_move_to(cr_, poly.points[0].x, poly.points[0].y);
            for (std::size_t i = 1; i < poly.points.size(); ++i)
                cairo_line_to(cr_, poly.points[i].x, poly.points[i].y);
            cairo_close_path(cr_);
            break;
        }
    }
}

cairo_t* Canvas::cairo() {
    used_cairo_ = true;
    if (sink_) sink_->escape(cr_);
    return cr_;
}

void Canvas::save() { cairo_save(cr_); }

void Canvas::restore() { cairo_restore(cr_); }

}  // namespace acanthus
