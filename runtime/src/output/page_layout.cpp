// Fitting the region's bounds onto an output page.
#include "output/page_layout.hpp"

#include <cairo.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <string>

namespace acanthus::detail {

namespace {

// Cairo's image surfaces stop at 32767 pixels a side; vector pages share the limit for simplicity.
constexpr double max_page_side = 32767;
constexpr double margin_fraction = 0.02;
constexpr double line_width_per_page_unit = 1.0 / 800.0;

}  // namespace

void PageLayout::apply(cairo_t* cr) const {
    cairo_translate(cr, offset_x, offset_y);
    cairo_scale(cr, scale, scale);
}

PageLayout page_layout(const Rect& bounds, double width) {
    if (!std::isfinite(width) || width < 1 || width > max_page_side)
        throw UsageError("output width " + std::to_string(width) + " is outside 1..32767");
    double bw = std::isfinite(bounds.width()) && bounds.width() > 0 ? bounds.width() : 1;
    double bh = std::isfinite(bounds.height()) && bounds.height() > 0 ? bounds.height() : 1;
    double margin = margin_fraction * std::max(bw, bh);
    double span_x = bw + 2 * margin, span_y = bh + 2 * margin;

    PageLayout page;
    page.width = static_cast<int>(std::lround(width));
    double height = std::max(1.0, std::round(page.width * span_y / span_x));
    if (height > max_page_side)
        throw UsageError("output width " + std::to_string(page.width) + " makes the page " +
                         std::to_string(static_cast<long>(height)) +
                         " high, over 32767; use a smaller width");
    page.height = static_cast<int>(height);
    page.scale = std::min(page.width / span_x, page.height / span_y);
    Point c = bounds.center();
    if (!c.finite()) c = {0, 0};
    page.offset_x = page.width / 2.0 - c.x * page.scale;
    page.offset_y = page.height / 2.0 - c.y * page.scale;
    page.line_width = std::max(1.0, page.width * line_width_per_page_unit) / page.scale;
    return page;
}

}  // namespace acanthus::detail
