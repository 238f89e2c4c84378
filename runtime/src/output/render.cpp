// render_to_file: the grown ornament on one page, through the same Cairo drawing for every format.
//
// Styles: "drawn" (the default) calls a type's %draw when it has one (the author's drawing wins),
// else outlines the proxies. "outline" and "filled" draw the proxies themselves and ignore %draw,
// as the paper's Figure 15(d) shows an ornament's proxies. "order" colours every element by its
// placement order, oldest red to newest purple, as Figure 14 does: a diagnostic view of the
// growth, which a %draw would hide. "overlay" draws every element's proxies faintly, then the
// %draw pictures over them, for authors checking their drawing against the geometry.
// Seeds are not drawn (they are markers, not ornament) unless the seed type has a %draw.
// RenderOptions::stroke (a built-in skeletal stroke name or an .svg stroke file) applies to every
// curve of the pattern: %draw bodies are set aside, area proxies are drawn in the chosen style,
// and curve proxies that join end to start in placement order (a spiral's segments, a vine's
// pieces) are warped along as one skeleton, as wide as a twelfth of its length (between one and
// eight outline widths), so larger curves get bolder strokes (Figure 17).
#include <cairo.h>

#include <acanthus/error.hpp>
#include <acanthus/render.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "draw/coalescing_sink.hpp"
#include "draw/default_style.hpp"
#include "output/band_sink.hpp"
#include "output/document.hpp"
#include "output/layer_order.hpp"
#include "output/output_stream.hpp"
#include "output/page_layout.hpp"
#include "output/repeat.hpp"
#include "output/svg_fallback.hpp"
#include "output/svg_writer.hpp"
#include "pattern/running_body.hpp"
#include "region/band.hpp"
#include "symmetry/image_element.hpp"

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

// The region's outline as drawn: flattened to a quarter of a page unit (invisible at any output
// size), bent with the band when there is one.
struct Outline {
    std::vector<std::vector<Point>> rings;
    bool evenodd = false;
};

Outline outline_of(const Region& region, const RenderOptions& options,
                   const detail::PageLayout& page) {
    if (options.band) return {options.band->outline(0.25 / page.scale), true};
    return {region.rings(0.25 / page.scale), region.evenodd()};
}

// Through the Canvas, so that the structured SVG gets it as a path of its own layer.
void draw_region_outline(Canvas& canvas, const Outline& outline, const detail::PageLayout& page) {
    for (const auto& ring : outline.rings) {
        if (ring.empty()) continue;
        canvas.move_to(ring[0]);
        for (std::size_t i = 1; i < ring.size(); ++i) canvas.line_to(ring[i]);
        canvas.close_path();
    }
    canvas.set_color(region_color);
    canvas.set_line_width(0.75 * page.line_width);
    canvas.stroke();
}

RuleFailure draw_failure(const Pattern& pattern, const ElementType& type, const std::string& why) {
    return RuleFailure(pattern.file, type.line, "%draw " + type.name, why);
}

bool is_curve(const Proxy& p) {
    return p.kind() == ProxyKind::arc || p.kind() == ProxyKind::linesegment ||
           p.kind() == ProxyKind::bezier;
}

std::pair<Point, Point> curve_ends(const Proxy& p) {
    switch (p.kind()) {
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(p);
            return {a.start_point(), a.end_point()};
        }
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(p);
            return {l.p0, l.p1};
        }
        default: {
            const auto& b = static_cast<const BezierProxy&>(p);
            return {b.c[0], b.c[3]};
        }
    }
}

double chain_length(const std::vector<const Proxy*>& chain) {
    double length = 0;
    for (const Proxy* p : chain) {
        Rect b = p->bounds();
        length += std::max(distance(curve_ends(*p).first, curve_ends(*p).second),
                           0.5 * std::hypot(b.width(), b.height()));
    }
    return length;
}

// Curve proxies in placement order, joined into chains where one ends where the next starts.
void draw_stroke_chains(Canvas& canvas, const std::vector<const Element*>& elements,
                        const SkeletalStroke& stroke, double line_width, double join_tolerance) {
    std::vector<std::vector<const Proxy*>> chains;
    for (const Element* e : elements) {
        for (std::size_t k = 0; k < e->proxy_count(); ++k) {
            const Proxy& p = e->proxy(k);
            if (!is_curve(p) || !p.finite()) continue;
            if (!chains.empty() && distance(curve_ends(*chains.back().back()).second,
                                            curve_ends(p).first) <= join_tolerance)
                chains.back().push_back(&p);
            else
                chains.push_back({&p});
        }
    }
    canvas.set_color(Color{0.10, 0.10, 0.10, 1});
    for (const auto& chain : chains) {
        double width = std::clamp(chain_length(chain) / 12, line_width, 8 * line_width);
        stroke.draw(canvas, chain, width);
    }
}

// Whether an element is drawn at all: seeds are markers, unless their type has a %draw.
bool is_drawn(const Pattern& pattern, const Element& element, RenderStyle style,
              const detail::CurveStroke& curves) {
    const ElementType& type = element.type();
    bool custom = type.draw != nullptr && detail::uses_draw_bodies(style) && !curves.stroke;
    return custom || pattern.seed == nullptr || &type != pattern.seed;
}

// One element, its %draw or the style's default; `index` of `count` ranks it for the order style.
void draw_element(Canvas& canvas, cairo_t* cr, const Pattern& pattern, const Element& element,
                  long index, long count, RenderStyle style, const detail::PageLayout& page,
                  const detail::CurveStroke& curves) {
    const ElementType& type = element.type();
    bool custom = type.draw != nullptr && detail::uses_draw_bodies(style) && !curves.stroke;
    if (custom && style == RenderStyle::overlay) {
        cairo_save(cr);
        cairo_new_path(cr);
        cairo_set_line_width(cr, page.line_width);
        detail::draw_default(canvas, element, style, {}, {}, false);
        cairo_restore(cr);
    }

    cairo_save(cr);
    cairo_new_path(cr);
    cairo_set_line_width(cr, page.line_width);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_source_rgb(cr, 0, 0, 0);
    if (custom) {
        // An image (symmetry) is its original drawn under its transformation.
        const detail::ImageElement* image = detail::as_image(element);
        if (image) {
            const auto m = image->transform().matrix();
            cairo_matrix_t matrix{m[0], m[1], m[2], m[3], m[4], m[5]};
            cairo_transform(cr, &matrix);
        }
        try {
            const detail::RunningBody running(
                detail::body_label(&type, pattern.file, type.line, "%draw " + type.name));
            type.draw(canvas, image ? image->original() : element);
        } catch (const RuleFailure&) {
            throw;
        } catch (const std::exception& e) {
            throw draw_failure(pattern, type, e.what());
        } catch (...) {
            throw draw_failure(pattern, type, "unknown exception");
        }
    } else {
        const Element& ranked = detail::original_of(element);  // images share their colour
        long rank = ranked.id >= 0 ? ranked.id : index;
        Color color = hue(detail::order_hue(rank, count));
        detail::draw_default(canvas, element, style, color, {}, curves.stroke != nullptr);
    }
    cairo_restore(cr);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
        throw draw_failure(
            pattern, type,
            std::string("drawing failed: ") + cairo_status_to_string(cairo_status(cr)));
}

void draw_all_stroke_chains(Canvas& canvas, cairo_t* cr,
                            const std::vector<const Element*>& elements,
                            const detail::PageLayout& page, const detail::CurveStroke& curves) {
    cairo_save(cr);
    draw_stroke_chains(canvas, elements, *curves.stroke, page.line_width,
                       1e-6 * std::max(page.width, page.height) / page.scale);
    cairo_restore(cr);
}

// `sink` (may be null) gathers shapes for Cairo's vector surfaces; each element's state is
// restored after it, so what a canvas.cairo() call set is gone for the next one.
void draw_elements(cairo_t* cr, const Pattern& pattern, const std::vector<const Element*>& elements,
                   RenderStyle style, const detail::PageLayout& page,
                   const detail::CurveStroke& curves, detail::CoalescingSink* sink) {
    Canvas canvas(cr, sink);
    long count = static_cast<long>(elements.size());
    for (long index = 0; index < count; ++index) {
        const Element& element = *elements[static_cast<std::size_t>(index)];
        if (!is_drawn(pattern, element, style, curves)) continue;
        draw_element(canvas, cr, pattern, element, index, count, style, page, curves);
        if (sink) sink->end_element();
    }
    if (curves.stroke) draw_all_stroke_chains(canvas, cr, elements, page, curves);
}

std::string page_point(Point p, const detail::PageLayout& page) {
    return detail::svg_number(page.offset_x + page.scale * p.x, 4) + " " +
           detail::svg_number(page.offset_y + page.scale * p.y, 4);
}

std::string svg_path_of(const std::vector<std::vector<Point>>& rings,
                        const detail::PageLayout& page) {
    std::string d;
    for (const auto& ring : rings) {
        for (std::size_t k = 0; k < ring.size(); ++k)
            d += (d.empty() ? "M" : k == 0 ? " M" : " L") + page_point(ring[k], page);
        if (!ring.empty()) d += " Z";
    }
    return d;
}

// The region as a clip path of id `id`, in page units.
std::string region_clip_path(const Outline& outline, const detail::PageLayout& page,
                             const std::string& id) {
    return "<clipPath id=\"" + id + "\"><path d=\"" + svg_path_of(outline.rings, page) + "\"" +
           (outline.evenodd ? " clip-rule=\"evenodd\"" : "") + "/></clipPath>";
}

std::string use_tile(Point offset, const detail::PageLayout& page) {
    return "<use xlink:href=\"#repeat-tile\" transform=\"translate(" +
           detail::svg_number(page.scale * offset.x, 4) + " " +
           detail::svg_number(page.scale * offset.y, 4) + ")\"/>\n";
}

// What comes before and after the elements' layers in the structured SVG when the output is a
// repeat or is clipped to the region (a wallpaper tile). The layers are the tile's content, in a
// group with id repeat-tile (clipped to the region when asked) drawn where the tile is; the
// other copies are <use>s of it; or, for a pattern, the group is the cell of a <pattern> that
// fills the N x M area.
std::pair<std::string, std::string> svg_frame(const Region& region, const RenderOptions& options,
                                              const detail::PageLayout& page) {
    const std::string clip =
        options.clip_to_region
            ? region_clip_path(outline_of(region, options, page), page, "tile-clip")
            : std::string();
    const std::string clip_attribute =
        options.clip_to_region ? " clip-path=\"url(#tile-clip)\"" : "";
    if (!detail::repeats(options)) {
        if (!options.clip_to_region) return {};
        return {"<defs>" + clip + "</defs>\n<g id=\"tile\"" + clip_attribute + ">\n", "</g>\n"};
    }
    const detail::RepeatLayout layout = detail::repeat_layout(region.bounds(), options);
    const std::string area = svg_path_of({layout.corners()}, page);
    const std::string tile_group = "<g id=\"repeat-tile\"" + clip_attribute + ">\n";
    if (!options.svg_pattern) {
        std::string after = "</g>\n";
        for (const Point& o : layout.offsets())
            if (o.x != 0 || o.y != 0) after += use_tile(o, page);
        return {(clip.empty() ? "" : "<defs>" + clip + "</defs>\n") + tile_group, after};
    }
    // The pattern's cell is W x H page units, mapped onto the tile by K (a shear for an oblique
    // tile); the content is drawn in page units, so it goes through K's inverse.
    const RepeatTile& t = layout.tile;
    const Point o{page.offset_x + page.scale * t.origin.x, page.offset_y + page.scale * t.origin.y};
    const Point a{page.scale * t.a.x, page.scale * t.a.y},
        b{page.scale * t.b.x, page.scale * t.b.y};
    const double w = std::hypot(a.x, a.y), h = std::hypot(b.x, b.y);
    const double k[6] = {a.x / w, a.y / w, b.x / h, b.y / h, o.x, o.y};
    const double det = k[0] * k[3] - k[1] * k[2];
    const double ia = k[3] / det, ib = -k[1] / det, ic = -k[2] / det, id = k[0] / det;
    const double inv[6] = {ia, ib, ic, id, -(ia * o.x + ic * o.y), -(ib * o.x + id * o.y)};
    auto matrix = [](const double* m) {
        std::string text = "matrix(";
        for (int i = 0; i < 6; ++i) {
            if (i) text += ' ';
            text += detail::svg_number(m[i], 6);
        }
        return text + ")";
    };
    return {"<defs>" + clip + "<pattern id=\"repeat-pattern\" patternUnits=\"userSpaceOnUse\" " +
                "x=\"0\" y=\"0\" width=\"" + detail::svg_number(w, 4) + "\" height=\"" +
                detail::svg_number(h, 4) + "\" patternTransform=\"" + matrix(k) +
                "\">\n<g transform=\"" + matrix(inv) + "\">\n" + tile_group,
            "</g>\n</g>\n</pattern></defs>\n<path id=\"repeat-area\" d=\"" + area +
                "\" fill=\"url(#repeat-pattern)\"/>\n"};
}

// Clips `cr` to the region.
void clip_to_region(cairo_t* cr, const Outline& outline) {
    cairo_new_path(cr);
    for (const auto& ring : outline.rings) {
        for (std::size_t k = 0; k < ring.size(); ++k)
            (k == 0 ? cairo_move_to : cairo_line_to)(cr, ring[k].x, ring[k].y);
        cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, outline.evenodd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_clip(cr);
}

// A context on a 1x1 surface that is never painted: the Canvas keeps its state there while a
// sink takes the shapes.
class ScratchContext {
  public:
    ScratchContext()
        : surface_(cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1), &cairo_surface_destroy),
          context_(cairo_create(surface_.get()), &cairo_destroy) {}
    cairo_t* get() const { return context_.get(); }

  private:
    std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface_;
    std::unique_ptr<cairo_t, void (*)(cairo_t*)> context_;
};

// The flattening error of bent shapes: a quarter of a page unit.
double bend_tolerance(const detail::PageLayout& page) { return 0.25 / page.scale; }

// The elements drawn in the straight band's coordinates and painted bent onto `target`.
void draw_bent(cairo_t* target, const Pattern& pattern, const std::vector<const Element*>& elements,
               RenderStyle style, const detail::PageLayout& page, const detail::CurveStroke& curves,
               const detail::Band& band) {
    ScratchContext scratch;
    detail::BandSink sink(band, target, bend_tolerance(page));
    Canvas canvas(scratch.get(), &sink);
    long count = static_cast<long>(elements.size());
    for (long index = 0; index < count; ++index) {
        const Element& element = *elements[static_cast<std::size_t>(index)];
        if (!is_drawn(pattern, element, style, curves)) continue;
        draw_element(canvas, scratch.get(), pattern, element, index, count, style, page, curves);
    }
    if (curves.stroke) draw_all_stroke_chains(canvas, scratch.get(), elements, page, curves);
}

// The structured SVG (docs/rendering.md): a layer per element type (layer_order.hpp), a group
// per element, written to the file one element at a time. The Canvas
// keeps its state on a context of a 1x1 surface that is never painted; the shapes go to the
// writer. An element whose drawing the writer cannot follow is drawn again by Cairo's SVG surface.
void render_structured_svg(const std::string& path, const Pattern& pattern, const Region& region,
                           const std::vector<const Element*>& elements,
                           const RenderOptions& options, RenderStyle style,
                           const detail::PageLayout& page, const detail::CurveStroke& curves) {
    detail::OutputStream out(path);
    detail::SvgWriter svg(out, page.width, page.height, pattern.name);
    if (options.background) svg.background(*options.background);
    const bool repeat = detail::repeats(options);
    const std::pair<std::string, std::string> frame = svg_frame(region, options, page);

    ScratchContext page_context, band_context;
    cairo_t* cr = page_context.get();
    page.apply(cr);
    Canvas outline_canvas(cr, &svg);
    // With a band, elements are drawn in the straight band's coordinates and bent onto `cr`.
    std::optional<detail::BandSink> band_sink;
    if (options.band) band_sink.emplace(*options.band, cr, bend_tolerance(page), &svg);
    cairo_t* draw_cr = options.band ? band_context.get() : cr;
    Canvas canvas(draw_cr, options.band ? static_cast<detail::CanvasSink*>(&*band_sink) : &svg);
    const Outline outline = outline_of(region, options, page);

    if (options.draw_region && !repeat) {
        svg.begin_layer("panel outline", "layer-panel-outline");
        cairo_save(cr);
        draw_region_outline(outline_canvas, outline, page);
        cairo_restore(cr);
        svg.end_layer();
    }

    svg.raw(frame.first);

    // Each type's elements in placement order.
    std::vector<const ElementType*> types = detail::layer_order(elements);
    long count = static_cast<long>(elements.size());
    for (const ElementType* type : types) {
        svg.begin_layer(type->name, "layer-" + type->name);
        for (long index = 0; index < count; ++index) {
            const Element& element = *elements[static_cast<std::size_t>(index)];
            if (&element.type() != type) continue;
            long id = element.id >= 0 ? element.id : index;
            svg.begin_element(type->name, id, element.parent ? element.parent->id : -1);
            if (!is_drawn(pattern, element, style, curves)) {
                svg.end_element();  // an empty group: every element is in the file
                continue;
            }
            canvas.reset_used_cairo();
            draw_element(canvas, draw_cr, pattern, element, index, count, style, page, curves);
            if (canvas.used_cairo() || svg.needs_fallback()) {
                svg.replace_shapes(detail::cairo_svg_fragment(
                    page,
                    [&](cairo_t* raw) {
                        if (options.band) {
                            draw_bent(raw, pattern, {&element}, style, page, {}, *options.band);
                            return;
                        }
                        Canvas cairo_canvas(raw);
                        draw_element(cairo_canvas, raw, pattern, element, index, count, style, page,
                                     curves);
                    },
                    type->name + "-" + std::to_string(id) + "-"));
            }
            svg.end_element();
        }
        svg.end_layer();
    }
    if (curves.stroke) {
        // Skeletal strokes are drawn through Cairo (they fill warped outlines with its paths).
        svg.begin_layer("skeletal strokes", "layer-skeletal-strokes");
        svg.raw(detail::cairo_svg_fragment(
            page,
            [&](cairo_t* raw) {
                if (options.band) {
                    ScratchContext scratch;
                    detail::BandSink sink(*options.band, raw, bend_tolerance(page));
                    Canvas band_canvas(scratch.get(), &sink);
                    draw_all_stroke_chains(band_canvas, scratch.get(), elements, page, curves);
                    return;
                }
                Canvas cairo_canvas(raw);
                draw_all_stroke_chains(cairo_canvas, raw, elements, page, curves);
            },
            "strokes-"));
        svg.end_layer();
    }
    svg.raw(frame.second);
    svg.finish();
    out.commit();
}

}  // namespace

void render_to_file(const std::string& path, const Pattern& pattern, const Region& region,
                    const std::vector<const Element*>& elements, const RenderOptions& options) {
    OutputFormat format = format_for_path(path);
    RenderStyle style = detail::parse_render_style(options.style);
    if (options.svg_pattern && format != OutputFormat::svg)
        throw UsageError("--svg-pattern writes an SVG <pattern>: give -o a .svg file name, not '" +
                         path + "'");
    // A repeat's page holds the N x M copies of the tile.
    const bool repeat = detail::repeats(options);
    const detail::RepeatLayout layout = detail::repeat_layout(region.bounds(), options);
    if (repeat && options.band)
        throw UsageError("--repeat and --svg-pattern repeat a tile, not a band (--band)");
    const Rect drawn = options.band ? options.band->bounds() : region.bounds();
    detail::PageLayout page = detail::page_layout(repeat ? layout.bounds() : drawn, options.width);
    std::optional<SkeletalStroke> stroke = resolve_stroke(options.stroke);
    detail::CurveStroke curves;
    if (stroke) curves = {&*stroke, skeletal_stroke_widths * page.line_width};

    if (format == OutputFormat::svg) {
        render_structured_svg(path, pattern, region, elements, options, style, page, curves);
        return;
    }

    // The SVG's page, scaled: line widths and margins as the SVG shown at that size.
    double zoom = 1;
    int pixels_x = page.width, pixels_y = page.height;
    if (format == OutputFormat::png && options.fit_width > 0 && options.fit_height > 0) {
        zoom = std::min(static_cast<double>(options.fit_width) / page.width,
                        static_cast<double>(options.fit_height) / page.height);
        pixels_x = std::max(1, static_cast<int>(std::lround(page.width * zoom)));
        pixels_y = std::max(1, static_cast<int>(std::lround(page.height * zoom)));
    }
    // Streamed to the temporary file: Cairo's own record of the page is memory enough.
    detail::OutputStream out(path);
    detail::OutputDocument document(format, pixels_x, pixels_y, pattern.name, out);
    if (options.stored_png) document.store_png_uncompressed();
    cairo_t* cr = document.context();
    if (options.draft && format == OutputFormat::png) {
        // Cairo's coarser antialiasing and flattening: a quarter to a third less of its work.
        cairo_set_antialias(cr, CAIRO_ANTIALIAS_FAST);
        cairo_set_tolerance(cr, 0.3);
    }
    if (options.background) {
        const Color& c = *options.background;
        cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
        cairo_paint(cr);
    }
    cairo_scale(cr, zoom, zoom);
    page.apply(cr);
    const Outline outline = outline_of(region, options, page);
    // A PNG is painted as it goes; only the vector surfaces record every operation, so there
    // shapes go through a CoalescingSink (flushed before any change of clip or transformation).
    const bool coalesce = options.coalesce && format != OutputFormat::png;
    auto draw_coalesced = [&] {
        std::unique_ptr<detail::CoalescingSink> sink;
        if (coalesce) sink = std::make_unique<detail::CoalescingSink>(cr, page.width, page.height);
        draw_elements(cr, pattern, elements, style, page, curves, sink.get());
        if (sink) sink->flush();
    };
    if (repeat) {
        // Each copy of the content where its tile is, clipped to it when asked; no outline.
        for (const Point& offset : layout.offsets()) {
            cairo_save(cr);
            cairo_translate(cr, offset.x, offset.y);
            if (options.clip_to_region) clip_to_region(cr, outline);
            draw_coalesced();
            cairo_restore(cr);
        }
    } else {
        if (options.draw_region) {
            Canvas canvas(cr);
            draw_region_outline(canvas, outline, page);
        }
        if (options.clip_to_region) clip_to_region(cr, outline);
        if (options.band)
            draw_bent(cr, pattern, elements, style, page, curves, *options.band);
        else
            draw_coalesced();
    }

    document.finish();
    out.commit();
}

}  // namespace acanthus
