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

// Which pixels the region covers wholly (alpha 255), as a summed-area table: whether a box of
// pixels lies wholly inside is two subtractions.
class WholePixels {
  public:
    explicit WholePixels(cairo_surface_t* mask)
        : width_(cairo_image_surface_get_width(mask)),
          height_(cairo_image_surface_get_height(mask)),
          sums_(static_cast<std::size_t>(width_ + 1) * static_cast<std::size_t>(height_ + 1), 0) {
        cairo_surface_flush(mask);
        const unsigned char* data = cairo_image_surface_get_data(mask);
        const int stride = cairo_image_surface_get_stride(mask);
        for (int j = 0; j < height_; ++j) {
            std::int32_t row = 0;
            for (int i = 0; i < width_; ++i) {
                row += data[static_cast<std::ptrdiff_t>(j) * stride + i] == 255;
                at(i + 1, j + 1) = at(i + 1, j) + row;
            }
        }
    }

    // Whether every pixel meeting [x0, x1] x [y0, y1] (device units) is wholly inside.
    bool whole(double x0, double y0, double x1, double y1) const {
        // (NaN fails every comparison: not whole)
        if (!(x0 >= 0 && y0 >= 0 && x1 < width_ && y1 < height_ && x0 <= x1 && y0 <= y1))
            return false;
        const int i0 = static_cast<int>(x0), j0 = static_cast<int>(y0);
        const int i1 = static_cast<int>(x1) + 1, j1 = static_cast<int>(y1) + 1;
        const std::int64_t count =
            static_cast<std::int64_t>(at(i1, j1)) - at(i0, j1) - at(i1, j0) + at(i0, j0);
        return count == static_cast<std::int64_t>(i1 - i0) * (j1 - j0);
    }

  private:
    std::int32_t& at(int i, int j) {
        return sums_[static_cast<std::size_t>(j) * static_cast<std::size_t>(width_ + 1) +
                     static_cast<std::size_t>(i)];
    }
    std::int32_t at(int i, int j) const {
        return sums_[static_cast<std::size_t>(j) * static_cast<std::size_t>(width_ + 1) +
                     static_cast<std::size_t>(i)];
    }
    int width_, height_;
    std::vector<std::int32_t> sums_;
};

// A proxy's bounds in user units, loose: a Bézier's control points (no path built).
Rect loose_bounds(const Proxy& proxy) {
    if (proxy.kind() != ProxyKind::bezier) return proxy.bounds();
    const auto& b = static_cast<const BezierProxy&>(proxy);
    Rect r{b.c[0].x, b.c[0].y, b.c[0].x, b.c[0].y};
    for (const Point& p : b.c) {
        r.x0 = std::min(r.x0, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x);
        r.y1 = std::max(r.y1, p.y);
    }
    // (a NaN coordinate is dropped by min and max: tell it by finite())
    if (!proxy.finite()) return {NAN, NAN, NAN, NAN};
    return r;
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

    auto context = [&](cairo_surface_t* surface) {
        std::unique_ptr<cairo_t, ContextDeleter> cr(cairo_create(surface));
        cairo_scale(cr.get(), scale, scale);
        cairo_translate(cr.get(), -b.x0, -b.y0);
        return cr;
    };
    auto check = [](cairo_t* cr) {
        if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
            throw InputError(std::string("measuring coverage failed: ") +
                             cairo_status_to_string(cairo_status(cr)));
    };
    auto new_mask = [&] {
        return std::unique_ptr<cairo_surface_t, SurfaceDeleter>(
            cairo_image_surface_create(CAIRO_FORMAT_A8, width, height));
    };

    const auto region_mask = new_mask();
    {
        const auto cr = context(region_mask.get());
        add_region_path(cr.get(), region, 0.25 / scale);
        cairo_fill(cr.get());
        check(cr.get());
    }
    const double region_pixels = covered_pixels(region_mask.get());
    if (region_pixels <= 0) return 0;

    // The elements, clipped to the region. A curve or circle whose pixels the region covers
    // wholly is drawn without the clip (a clip that takes nothing away; the order kept: two
    // contexts on one surface): the clip was a third of the measure's time. Cairo rounds a
    // few of the shape's edge pixels otherwise without it: the figure moves by about 1e-6 of
    // itself, far inside its one-pixel accuracy. Polygons keep the clip: Cairo fills an
    // unclipped rectilinear one as boxes, whose edge pixels differ more from its clipped fill's
    // (facade's coverage 0.81829 -> 0.81848).
    const WholePixels whole(region_mask.get());
    const auto mask = new_mask();
    const auto clipped = context(mask.get()), unclipped = context(mask.get());
    add_region_path(clipped.get(), region, 0.25 / scale);
    cairo_clip(clipped.get());
    for (cairo_t* cr : {clipped.get(), unclipped.get()}) {
        cairo_set_line_width(cr, std::max(0.0, stroke_width));
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    }
    Canvas clipped_canvas(clipped.get()), unclipped_canvas(unclipped.get());
    // Beyond a shape's bounds: half the stroke and two pixels of antialiasing.
    const double reach = 0.5 * std::max(0.0, stroke_width) * scale + 2;
    for (const Element* e : elements)
        for (std::size_t k = 0; k < e->proxy_count(); ++k) {
            const Proxy& proxy = e->proxy(k);
            if (proxy.kind() == ProxyKind::point) continue;
            const bool area = is_area(proxy.kind());
            if (!area && !(stroke_width > 0)) continue;
            const Rect r = loose_bounds(proxy);
            Canvas& canvas =
                proxy.kind() != ProxyKind::polygon &&
                        whole.whole((r.x0 - b.x0) * scale - reach, (r.y0 - b.y0) * scale - reach,
                                    (r.x1 - b.x0) * scale + reach, (r.y1 - b.y0) * scale + reach)
                    ? unclipped_canvas
                    : clipped_canvas;
            if (area)
                canvas.fill(proxy);
            else
                canvas.stroke(proxy);
        }
    check(clipped.get());
    check(unclipped.get());
    return std::min(1.0, covered_pixels(mask.get()) / region_pixels);
}

double rendered_line_width(const Region& region, double output_width) {
    return detail::page_layout(region.bounds(), output_width).line_width;
}

}  // namespace acanthus::detail
