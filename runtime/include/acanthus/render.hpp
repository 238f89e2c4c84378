// Rendering the grown ornament to SVG, PDF, PS, EPS or PNG through one Cairo drawing path.
#pragma once

#include <acanthus/canvas.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/region.hpp>
#include <optional>
#include <string>
#include <vector>

namespace acanthus {

enum class OutputFormat { svg, pdf, ps, eps, png };

// From the file extension; "-" is SVG. Throws UsageError on an unknown extension.
OutputFormat format_for_path(const std::string& path);

struct RenderOptions {
    double width = 800;               // output width in pixels (PNG) or points (vector formats)
    std::string style = "drawn";      // drawn | outline | filled | order | overlay
    std::optional<Color> background;  // none: transparent (PNG) / no background rectangle
    bool draw_region = true;          // the region's outline
    std::string stroke;               // skeletal stroke name applied to curves, or empty
    // PDF, PostScript, EPS: shapes of one colour and style that nothing between them touches go
    // to Cairo as one path (the same picture, far less of Cairo's memory). Off only to compare.
    bool coalesce = true;
};

// Draws the elements (their %draw, or the default for the style). Writes `path` through a
// temporary file renamed on success; "-" writes SVG to stdout.
void render_to_file(const std::string& path, const Pattern& pattern, const Region& region,
                    const std::vector<const Element*>& elements, const RenderOptions& options);

// Figure 8 of the paper for one iteration, as PNG.
void render_debug_frame(const std::string& path, const Region& region, const DebugFrame& frame,
                        const RenderOptions& options);

}  // namespace acanthus
