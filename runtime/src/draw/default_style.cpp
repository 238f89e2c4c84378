// The built-in element styles used when a type has no %draw (and always for the order style).
#include "draw/default_style.hpp"

#include <acanthus/error.hpp>
#include <algorithm>

namespace acanthus::detail {

namespace {

constexpr Color ink{0.10, 0.10, 0.10, 1};
constexpr Color light_fill{0.80, 0.88, 0.76, 1};
constexpr Color faint{0.55, 0.62, 0.78, 0.55};  // overlay: proxies under the author's drawing

// The same hue darkened, so filled order-style areas keep a visible edge.
Color darker(Color c) { return {c.r * 0.55, c.g * 0.55, c.b * 0.55, c.a}; }

}  // namespace

RenderStyle parse_render_style(const std::string& name) {
    if (name == "drawn") return RenderStyle::drawn;
    if (name == "outline") return RenderStyle::outline;
    if (name == "filled") return RenderStyle::filled;
    if (name == "order") return RenderStyle::order;
    if (name == "overlay") return RenderStyle::overlay;
    throw UsageError("unknown style '" + name +
                     "': expected drawn, outline, filled, order or overlay");
}

bool uses_draw_bodies(RenderStyle style) {
    return style == RenderStyle::drawn || style == RenderStyle::overlay;
}

double order_hue(long rank, long count) {
    if (count <= 1) return 0;
    // Stop at 0.8 (purple): the full wheel would bring the newest elements back to red.
    return 0.8 * std::clamp(static_cast<double>(rank) / static_cast<double>(count - 1), 0.0, 1.0);
}

void draw_default(Canvas& canvas, const Element& element, RenderStyle style, Color order_color,
                  const CurveStroke& curves, bool skip_curves) {
    double width = canvas.line_width();
    for (std::size_t k = 0; k < element.proxy_count(); ++k) {
        const Proxy& proxy = element.proxy(k);
        bool area = is_area(proxy.kind());
        if (skip_curves && !area && proxy.kind() != ProxyKind::point) continue;
        if (curves.stroke && !area && proxy.kind() != ProxyKind::point) {
            canvas.set_color(style == RenderStyle::order ? order_color : ink);
            if (proxy.finite()) curves.stroke->draw(canvas, proxy, curves.width);
            continue;
        }
        switch (style) {
            case RenderStyle::drawn:
            case RenderStyle::outline:
                canvas.set_color(ink);
                canvas.stroke(proxy);
                break;
            case RenderStyle::overlay:
                canvas.set_color(faint);
                canvas.set_line_width(width * 0.6);
                canvas.stroke(proxy);
                canvas.set_line_width(width);
                break;
            case RenderStyle::filled:
                if (area) {
                    canvas.set_color(light_fill);
                    canvas.fill(proxy);
                }
                canvas.set_color(ink);
                canvas.stroke(proxy);
                break;
            case RenderStyle::order:
                canvas.set_color(order_color);
                if (area) {
                    canvas.fill(proxy);
                    canvas.set_color(darker(order_color));
                    canvas.set_line_width(width * 0.5);
                    canvas.stroke(proxy);
                    canvas.set_line_width(width);
                } else {
                    canvas.stroke(proxy);
                }
                break;
        }
    }
}

}  // namespace acanthus::detail
