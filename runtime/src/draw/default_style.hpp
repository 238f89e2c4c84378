// How an element looks when its type has no %draw: the outline, filled and order styles.
#pragma once

#include <acanthus/canvas.hpp>
#include <acanthus/element.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <string>

namespace acanthus::detail {

enum class RenderStyle {
    drawn,    // each type's %draw; types without one in outline (the default)
    outline,  // every proxy in outline, %draw ignored (the paper's Figure 15(d))
    filled,   // areas filled with a light colour and outlined, curves stroked, %draw ignored
    order,    // coloured by placement order, oldest red to newest purple (Figure 14)
    overlay,  // %draw over faint proxies: what an author drew and what the engine placed
};

// Throws UsageError on anything but "drawn", "outline", "filled", "order" or "overlay".
RenderStyle parse_render_style(const std::string& name);

// The hue wheel position of placement rank `rank` among `count` elements: red 0 to purple 0.8.
double order_hue(long rank, long count);

// How curves (arc, linesegment, bezier) are drawn: plain lines, or a skeletal stroke this wide.
struct CurveStroke {
    const SkeletalStroke* stroke = nullptr;
    double width = 0;  // user units
};

// Draws `element`'s proxies with the canvas's current line width. `order_color` is used by the
// order style only.
// With `skip_curves`, curve proxies are left out (a skeletal stroke draws them afterwards).
void draw_default(Canvas& canvas, const Element& element, RenderStyle style, Color order_color,
                  const CurveStroke& curves = {}, bool skip_curves = false);

// True when `style` calls a type's %draw.
bool uses_draw_bodies(RenderStyle style);

}  // namespace acanthus::detail
