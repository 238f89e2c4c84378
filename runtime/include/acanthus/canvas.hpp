// Drawing for %draw bodies and the default renderer. Cairo underneath; one path for all formats.
#pragma once

#include <acanthus/proxy.hpp>

typedef struct _cairo cairo_t;

namespace acanthus {

namespace detail {
class CanvasSink;
}

struct Color {
    double r = 0, g = 0, b = 0, a = 1;
};

// Colour wheel: t in [0, 1) goes red, yellow, green, cyan, blue, magenta (wraps).
Color hue(double t, double saturation = 0.85, double value = 0.9);
// Parses "#rgb", "#rrggbb", "#rrggbbaa", "none" / "transparent", or a CSS colour name.
// Throws InputError on a bad string.
Color parse_color(const std::string& text);

class Canvas {
  public:
    // Draws into `cr` (not owned). Coordinates are the region's user units.
    explicit Canvas(cairo_t* cr);
    // For the renderer: fills and strokes go to `sink` (the structured SVG writer) while `cr`
    // keeps the state (colour, line width, path, transformation).
    Canvas(cairo_t* cr, detail::CanvasSink* sink);

    void set_color(double r, double g, double b, double a = 1.0);
    void set_color(Color c);
    void set_line_width(double w);
    double line_width() const;
    // One output pixel in user units, at the current transformation: what a width or a size
    // must stay above to be seen (e.g. std::max(w, 0.75 * canvas.pixel())).
    double pixel() const;

    void move_to(Point p);
    void line_to(Point p);
    void curve_to(Point c1, Point c2, Point p);
    void arc(Point center, double radius, double start, double end);
    void close_path();
    void fill();
    void stroke();
    // Adds the proxy's outline to the path and fills or strokes it.
    void fill(const Proxy& proxy);
    void stroke(const Proxy& proxy);
    void fill_circle(Point center, double radius);
    void fill_circle(Point center, double radius, Color color);
    // Appends the proxy's geometry to the current path.
    void add_proxy(const Proxy& proxy);

    void save();
    void restore();

    // The escape hatch: the underlying Cairo context.
    cairo_t* cairo();
    // For the renderer: whether cairo() was called since the last reset (a sink cannot see what
    // was drawn through it, so the element is drawn by Cairo instead).
    bool used_cairo() const { return used_cairo_; }
    void reset_used_cairo() { used_cairo_ = false; }

  private:
    bool send_shape(const Proxy& proxy, bool fill);

    cairo_t* cr_;
    detail::CanvasSink* sink_ = nullptr;
    bool used_cairo_ = false;
};

}  // namespace acanthus
