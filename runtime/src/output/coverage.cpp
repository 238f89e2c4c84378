// Coverage of the region by the grown elements, measured on a Cairo A8 raster.
#include "output/coverage.hpp"

#include <cairo.h>

#include <acanthus/canvas.hpp>
#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "output/page_layout.hpp"

namespace acanthus::detail {

namespace {

constexpr int coverage_resolution = 1024;  // pixels on the region's longer side

struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
    void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};

void add_region_path(cairo_t* cr, const Region& region, double tolerance) {
    for (const auto& ring : region.rings(tolerance)) {
        if (ring.empty()) continue;
        cairo_move_to(cr, ring[0].x, ring[0].y);
        for (std::size_t i = 1; i < ring.size(); ++i) cairo_line_to(cr, ring[i].x, ring[i].y);
        cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, region.evenodd() ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
}

// Sum of the mask's alpha, in pixels.
double covered_pixels(cairo_surface_t* mask) {
    cairo_surface_flush(mask);
    const unsigned char* data = cairo_image_surface_get_data(mask);
    int stride = cairo_image_surface_get_stride(mask);
    int width = cairo_image_surface_get_width(mask), height = cairo_image_surface_get_height(mask);
    std::uint64_t sum = 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) sum += data[static_cast<std::ptrdiff_t>(j) * stride + i];
    return static_cast<double>(sum) / 255.0;
}

}  // namespace

double coverage(const Region& region, const std::vector<const Element*>& elements,
                double stroke_width) {
    Rect b = region.bounds();
    double span = std::max(b.width(), b.height());
    if (!(span > 0) || !std::isfinite(span)) return 0;
    double scale = coverage_resolution / span;
    int width = std::max(1, static_cast<int>(std::ceil(b.width() * scale)));
    int height = std::max(1, static_cast<int>(std::ceil(b.height() * scale)));

    auto draw = [&](bool with_elements) {
        std::unique_ptr<cairo_surface_t, SurfaceDeleter> mask(
            cairo_image_surface_create(CAIRO_FORMAT_A8, width, height));
        std::unique_ptr<cairo_t, ContextDeleter> owner(cairo_create(mask.get()));
        cairo_t* cr = owner.get();
        cairo_scale(cr, scale, scale);
        cairo_translate(cr, -b.x0, -b.y0);
        add_region_path(cr, region, 0.25 / scale);
        if (!with_elements) {
            cairo_fill(cr);
        } else {
            cairo_clip(cr);
            cairo_set_line_width(cr, std::max(0.0, stroke_width));
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
            Canvas canvas(cr);
            for (const Element* e : elements)
                for (std::size_t k = 0; k < e->proxy_count(); ++k) {
                    const Proxy& proxy = e->proxy(k);
                    if (proxy.kind() == ProxyKind::point) continue;
                    if (is_area(proxy.kind()))
                        canvas.fill(proxy);
                    else if (stroke_width > 0)
                        canvas.stroke(proxy);
                }
        }
        if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
            throw InputError(std::string("measuring coverage failed: ") +
                             cairo_status_to_string(cairo_status(cr)));
        return covered_pixels(mask.get());
    };

    double region_pixels = draw(false);
    if (region_pixels <= 0) return 0;
    return std::min(1.0, draw(true) / region_pixels);
}

double rendered_line_width(const Region& region, double output_width) {
    return detail::page_layout(region.bounds(), output_width).line_width;
}

}  // namespace acanthus::detail
