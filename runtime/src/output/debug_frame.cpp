// render_debug_frame: one iteration of the growth loop drawn as Figure 8 of the paper shows it.
//
// The render buffer fills the picture (free white, boundary red, elements dark grey), scaled so
// the grid spans the output width. Over it: the elements in place before the iteration in thin
// black outline, eligible candidate circles in yellow, excluded ones in green, the candidate
// parents in thick purple, the chosen circle C dashed blue and the newly added children in orange.
// Under symmetry, images of elements are outlined in light blue and the fundamental domain's
// edges drawn in dashed teal.
// The format follows the file name like render_to_file; the paper's picture is a PNG.
#include <cairo.h>

#include <acanthus/error.hpp>
#include <acanthus/render.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include "output/document.hpp"
#include "output/output_stream.hpp"
#include "symmetry/image_element.hpp"

namespace acanthus {

namespace {

constexpr std::uint32_t free_pixel = 0xffffff;
constexpr std::uint32_t boundary_pixel = 0xe02020;
constexpr std::uint32_t element_pixel = 0x505050;

constexpr Color placed_color{0, 0, 0, 1};
constexpr Color eligible_color{0.95, 0.8, 0.0, 1};
constexpr Color excluded_color{0.0, 0.65, 0.1, 1};
constexpr Color candidate_color{0.55, 0.1, 0.75, 1};
constexpr Color chosen_color{0.1, 0.3, 0.95, 1};
constexpr Color added_color{1.0, 0.5, 0.0, 1};
constexpr Color image_color{0.35, 0.6, 0.95, 1};
constexpr Color domain_color{0.0, 0.55, 0.55, 1};

struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};

// The occupancy grid as an image, one pixel per grid cell.
std::unique_ptr<cairo_surface_t, SurfaceDeleter> occupancy_image(const DebugFrame& frame) {
    const GridFrame& grid = frame.grid;
    std::unique_ptr<cairo_surface_t, SurfaceDeleter> image(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, grid.width, grid.height));
    if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS)
        throw InputError("debug frame: cannot make a " + std::to_string(grid.width) + "x" +
                         std::to_string(grid.height) + " image of the render buffer");
    cairo_surface_flush(image.get());
    unsigned char* data = cairo_image_surface_get_data(image.get());
    int stride = cairo_image_surface_get_stride(image.get());
    for (int j = 0; j < grid.height; ++j) {
        auto* row =
            reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(j) * stride);
        for (int i = 0; i < grid.width; ++i) {
            std::uint8_t cell = frame.occupancy[static_cast<std::size_t>(j) * grid.width + i];
            row[i] = cell == 0 ? free_pixel : cell == 1 ? boundary_pixel : element_pixel;
        }
    }
    cairo_surface_mark_dirty(image.get());
    return image;
}

void stroke_circle(Canvas& canvas, const Circle& c) {
    canvas.move_to(c.center + Vector{c.radius, 0});
    canvas.arc(c.center, c.radius, 0, 2 * M_PI);
    canvas.close_path();
    canvas.stroke();
}

void stroke_elements(Canvas& canvas, const std::vector<const Element*>& elements) {
    for (const Element* e : elements)
        for (std::size_t k = 0; k < e->proxy_count(); ++k) canvas.stroke(e->proxy(k));
}

}  // namespace

void render_debug_frame(const std::string& path, const Region& region, const DebugFrame& frame,
                        const RenderOptions& options) {
    (void)region;  // the buffer already shows the boundary, rasterized as growth saw it
    OutputFormat format = format_for_path(path);
    const GridFrame& grid = frame.grid;
    if (grid.width <= 0 || grid.height <= 0 || !(grid.pixel > 0) ||
        frame.occupancy.size() != static_cast<std::size_t>(grid.width) * grid.height)
        throw InputError("debug frame of iteration " + std::to_string(frame.iteration) +
                         ": the render buffer is empty or does not match its grid");
    if (!std::isfinite(options.width) || options.width < 1 || options.width > 32767)
        throw UsageError("output width " + std::to_string(options.width) + " is outside 1..32767");
    int width = static_cast<int>(std::lround(options.width));
    double zoom = static_cast<double>(width) / grid.width;  // output pixels per grid pixel
    double height = std::max(1.0, std::round(grid.height * zoom));
    if (height > 32767) throw UsageError("debug frame too high; use a smaller width");

    auto image = occupancy_image(frame);
    detail::OutputStream out(path);
    detail::OutputDocument document(format, width, static_cast<int>(height),
                                    "iteration " + std::to_string(frame.iteration), out);
    cairo_t* cr = document.context();
    cairo_save(cr);
    cairo_scale(cr, zoom, zoom);
    cairo_set_source_surface(cr, image.get(), 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);

    // From here on, user units: grid pixel (i, j) starts at x0 + i * pixel.
    double scale = zoom / grid.pixel;
    cairo_scale(cr, scale, scale);
    cairo_translate(cr, -grid.x0, -grid.y0);
    double px = 1.0 / scale;  // one output pixel in user units
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    Canvas canvas(cr);

    canvas.set_line_width(px);
    std::vector<const Element*> fundamental, images;
    for (const Element* e : frame.placed)
        (detail::as_image(*e) ? images : fundamental).push_back(e);
    canvas.set_color(image_color);
    stroke_elements(canvas, images);
    canvas.set_color(placed_color);
    stroke_elements(canvas, fundamental);
    if (!frame.domain.empty()) {
        double dash[] = {8 * px, 4 * px};
        cairo_save(cr);
        cairo_set_dash(cr, dash, 2, 0);
        canvas.set_line_width(2 * px);
        canvas.set_color(domain_color);
        for (const auto& [a, b] : frame.domain) {
            canvas.move_to(a);
            canvas.line_to(b);
        }
        canvas.stroke();
        cairo_restore(cr);
    }

    canvas.set_line_width(1.5 * px);
    canvas.set_color(eligible_color);
    for (const Circle& c : frame.eligible) stroke_circle(canvas, c);
    canvas.set_color(excluded_color);
    for (const Circle& c : frame.excluded) stroke_circle(canvas, c);

    canvas.set_line_width(4 * px);
    canvas.set_color(candidate_color);
    stroke_elements(canvas, frame.candidates);

    if (frame.chosen) {
        double dash[] = {6 * px, 4 * px};
        cairo_save(cr);
        cairo_set_dash(cr, dash, 2, 0);
        canvas.set_line_width(2 * px);
        canvas.set_color(chosen_color);
        stroke_circle(canvas, *frame.chosen);
        cairo_restore(cr);
    }

    canvas.set_line_width(2 * px);
    for (const Element* e : frame.added)
        for (std::size_t k = 0; k < e->proxy_count(); ++k) {
            const Proxy& proxy = e->proxy(k);
            if (is_area(proxy.kind())) {
                canvas.set_color(added_color.r, added_color.g, added_color.b, 0.45);
                canvas.fill(proxy);
            }
            canvas.set_color(added_color);
            canvas.stroke(proxy);
        }

    document.finish();
    out.commit();
}

}  // namespace acanthus
