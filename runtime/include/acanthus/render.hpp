// Rendering the grown ornament to SVG, PDF, PS, EPS or PNG through one Cairo drawing path.
#pragma once

#include <acanthus/canvas.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/region.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace acanthus {

namespace detail {
class Band;
}

enum class OutputFormat { svg, pdf, ps, eps, png };

// From the file extension; "-" is SVG. Throws UsageError on an unknown extension.
OutputFormat format_for_path(const std::string& path);

// The tile the output repeats: the parallelogram origin + u a + v b, 0 <= u, v < 1.
struct RepeatTile {
    Point origin, a, b;
};

struct RenderOptions {
    double width = 800;               // output width in pixels (PNG) or points (vector formats)
    std::string style = "drawn";      // drawn | outline | filled | order | overlay
    std::optional<Color> background;  // none: transparent (PNG) / no background rectangle
    bool draw_region = true;          // the region's outline
    std::string stroke;               // skeletal stroke name applied to curves, or empty
    // PDF, PostScript, EPS: shapes of one colour and style that nothing between them touches go
    // to Cairo as one path (the same picture, far less of Cairo's memory). Off only to compare.
    bool coalesce = true;
    // Elements drawn clipped to the region (a wallpaper tile, whose elements cross its edges).
    bool clip_to_region = false;
    // --repeat NxM (docs/symmetry.md): the tile drawn N x M times, each copy clipped to the
    // region when clip_to_region; --svg-pattern: the SVG as a <pattern> of the tile filling that
    // area.
    int repeat_x = 1, repeat_y = 1;
    bool svg_pattern = false;
    std::optional<RepeatTile> tile;  // none: the region's bounding box
    // --band: the region is the straight band, drawn bent onto the band's centre line.
    std::shared_ptr<const detail::Band> band;
    // PNG for a viewer: the page of `width` drawn scaled to fit fit_width x fit_height pixels,
    // as the viewer shows the SVG at that size (0: `width` pixels wide); its pixels stored, not
    // deflated (a viewer on the same machine: deflating took a quarter of flowers' run).
    int fit_width = 0, fit_height = 0;
    bool stored_png = false;
    // A PNG drawn quickly, to be replaced soon (the growth so far in a viewer): coarser
    // antialiasing, curves flattened to 0.3 pixels instead of 0.1. Vector formats ignore it.
    bool draft = false;
};

// Draws the elements (their %draw, or the default for the style). Writes `path` through a
// temporary file renamed on success; "-" writes SVG to stdout.
void render_to_file(const std::string& path, const Pattern& pattern, const Region& region,
                    const std::vector<const Element*>& elements, const RenderOptions& options);

// Figure 8 of the paper for one iteration, as PNG.
void render_debug_frame(const std::string& path, const Region& region, const DebugFrame& frame,
                        const RenderOptions& options);

}  // namespace acanthus
