// The structured SVG: written element by element to an OutputStream, in Inkscape layers, with
// shared styles as CSS classes. It is the CanvasSink of the Canvas that draws each element.
#pragma once

#include <acanthus/canvas.hpp>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "draw/canvas_sink.hpp"
#include "output/output_stream.hpp"

namespace acanthus::detail {

// Decimal digits for coordinates on a page `width` x `height`: a step of at most 1/20000 of its
// longer side (0.01 under 2000 units, 0.1 under 20000), so rounding moves a point by at most
// 1/40000 of the page, below a twentieth of a pixel at the page's own size.
int svg_digits(int width, int height);
// `value` to `digits` decimals, without trailing zeros.
std::string svg_number(double value, int digits = 2);
// Escapes text for an XML attribute value or element content.
std::string xml_escape(std::string_view text);

class SvgWriter : public CanvasSink {
  public:
    // Writes the document's start: a page `width` x `height` points.
    SvgWriter(OutputStream& out, int width, int height, const std::string& title);

    void background(Color color);
    // A layer `label`d for Inkscape with id `id`; layers do not nest.
    void begin_layer(const std::string& label, const std::string& id);
    void end_layer();
    // One element's group, id TYPE-ID and data-parent (the rest of the tree is in --json); its
    // shapes are kept until end_element() writes the group out.
    void begin_element(const std::string& type, long id, long parent);
    // True when a shape could not be written as SVG (a gradient, a dash, a skew): the element
    // must be drawn by Cairo.
    bool needs_fallback() const { return fallback_; }
    // Drops the element's shapes and puts `fragment` (Cairo's SVG of it) in their place.
    void replace_shapes(std::string fragment);
    // Raw SVG inside the current layer (outside any element).
    void raw(std::string_view fragment);
    void end_element();
    // Writes the shared styles and closes the document.
    void finish();

    void path(cairo_t* cr, bool fill) override;
    void circle(cairo_t* cr, Point center, double radius, bool fill) override;
    void polygon(cairo_t* cr, const std::vector<Point>& points, bool fill) override;

  private:
    struct Shape {
        std::string tag, geometry;  // "circle", " cx=.. cy=.. r=.."
        std::string fill, stroke;   // CSS declarations of each part, empty when absent
    };
    // The paint part of the style for a fill or a stroke by `cr`, or fallback_ set.
    std::string paint(cairo_t* cr, bool fill);
    void add(Shape shape);
    void flush_shape();
    std::string class_of(const std::string& style);
    std::string number(double value) const { return svg_number(value, digits_); }
    std::string point_text(Point p) const { return number(p.x) + " " + number(p.y); }

    OutputStream& out_;
    int digits_;                   // decimals of coordinates and widths (svg_digits)
    std::string element_;          // the current element's group, written at its end
    std::size_t group_start_ = 0;  // where its shapes begin in element_
    Shape pending_;                // the last shape, which a stroke of the same geometry may join
    bool has_pending_ = false, fallback_ = false;
    std::map<std::string, std::size_t> classes_;  // CSS declarations -> class number
    std::vector<const std::string*> class_order_;
};

}  // namespace acanthus::detail
