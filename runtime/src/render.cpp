// render_to_file: the grown ornament on one page, through the same Cairo drawing for every format.
//
// Styles: "outline" and "filled" call a type's %draw when it has one (the author's drawing wins),
// else draw the proxies in that style. "order" ignores %draw and colours every element by its
// placement order, oldest red to newest purple, as Figure 14 of the paper does: it is a diagnostic
// view of the growth, and a %draw would hide exactly what it shows.
// Seeds are not drawn (they are markers, not ornament) unless the seed type has a %draw.
// RenderOptions::stroke (a built-in skeletal stroke name or an .svg stroke file) replaces the
// plain line of every curve proxy drawn by a default style with that stroke, four outline
// widths wide; %draw bodies use SkeletalStroke themselves if they want one.
#include <cairo.h>

#include <acanthus/error.hpp>
#include <acanthus/render.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include "default_style.hpp"
#include "output_document.hpp"
#include "output_file.hpp"
#include "page_layout.hpp"

namespace acanthus {

using detail::RenderStyle;

OutputFormat format_for_path(const std::string& path) {
    if (path == "-") return OutputFormat::svg;
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".svg") return OutputFormat::svg;
    if (ext == ".pdf") return OutputFormat::pdf;
    if (ext == ".ps") return OutputFormat::ps;
    if (ext == ".eps") return OutputFormat::eps;
    if (ext == ".png") return OutputFormat::png;
    throw UsageError("cannot tell the output format of '" + path +
                     "': use a .svg, .pdf, .ps, .eps or .png file name, or - for SVG on stdout");
}

namespace {

constexpr Color region_color{0.6, 0.6, 0.6, 1};
constexpr double skeletal_stroke_widths = 4;  // skeletal stroke width in outline widths

std::optional<SkeletalStroke> resolve_stroke(const std::string& name) {
    if (name.empty()) return std::nullopt;
    std::string ext = std::filesystem::path(name).extension().string();
    if (ext == ".svg" || ext == ".SVG") return SkeletalStroke::from_svg_file(name);
    return SkeletalStroke::builtin(name);
}

void draw_region_outline(cairo_t* cr, const Region& region, const detail::PageLayout& page) {
    // A quarter of a page unit of flattening error is invisible at any output size.
    for (const auto& ring : region.rings(0.25 / page.scale)) {
        if (ring.empty()) continue;
        cairo_move_to(cr, ring[0].x, ring[0].y);
        for (std::size_t i = 1; i < ring.size(); ++i) cairo_line_to(cr, ring[i].x, ring[i].y);
        cairo_close_path(cr);
    }
    cairo_set_source_rgba(cr, region_color.r, region_color.g, region_color.b, region_color.a);
    cairo_set_line_width(cr, 0.75 * page.line_width);
    cairo_stroke(cr);
}

RuleFailure draw_failure(const Pattern& pattern, const ElementType& type, const std::string& why) {
    return RuleFailure(pattern.file, type.line, "%draw " + type.name, why);
}

void draw_elements(cairo_t* cr, const Pattern& pattern, const std::vector<const Element*>& elements,
                   RenderStyle style, const detail::PageLayout& page,
                   const detail::CurveStroke& curves) {
    Canvas canvas(cr);
    long count = static_cast<long>(elements.size());
    for (long index = 0; index < count; ++index) {
        const Element& element = *elements[static_cast<std::size_t>(index)];
        const ElementType& type = element.type();
        bool custom = type.draw != nullptr && style != RenderStyle::order;
        if (!custom && pattern.seed != nullptr && &type == pattern.seed) continue;

        cairo_save(cr);
        cairo_new_path(cr);
        cairo_set_line_width(cr, page.line_width);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_set_source_rgb(cr, 0, 0, 0);
        if (custom) {
            try {
                type.draw(canvas, element);
            } catch (const RuleFailure&) {
                throw;
            } catch (const std::exception& e) {
                throw draw_failure(pattern, type, e.what());
            } catch (...) {
                throw draw_failure(pattern, type, "unknown exception");
            }
        } else {
            long rank = element.id >= 0 ? element.id : index;
            Color color = hue(detail::order_hue(rank, count));
            detail::draw_default(canvas, element, style, color, curves);
        }
        cairo_restore(cr);
        if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
            throw draw_failure(
                pattern, type,
                std::string("drawing failed: ") + cairo_status_to_string(cairo_status(cr)));
    }
}

}  // namespace

void render_to_file(const std::string& path, const Pattern& pattern, const Region& region,
                    const std::vector<const Element*>& elements, const RenderOptions& options) {
    OutputFormat format = format_for_path(path);
    RenderStyle style = detail::parse_render_style(options.style);
    detail::PageLayout page = detail::page_layout(region.bounds(), options.width);
    std::optional<SkeletalStroke> stroke = resolve_stroke(options.stroke);
    detail::CurveStroke curves;
    if (stroke) curves = {&*stroke, skeletal_stroke_widths * page.line_width};

    detail::OutputDocument document(format, page.width, page.height, pattern.name);
    cairo_t* cr = document.context();
    if (options.background) {
        const Color& c = *options.background;
        cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
        cairo_paint(cr);
    }
    page.apply(cr);
    if (options.draw_region) draw_region_outline(cr, region, page);
    draw_elements(cr, pattern, elements, style, page, curves);

    std::string bytes = document.finish();
    if (path == "-")
        detail::write_stdout(bytes);
    else
        detail::write_file_atomically(path, bytes);
}

}  // namespace acanthus
