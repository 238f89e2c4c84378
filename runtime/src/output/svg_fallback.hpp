// What the structured SVG cannot see, drawn by Cairo's SVG surface: a drawing that reached for
// canvas.cairo() (or a gradient, a dash, a skew) becomes Cairo's SVG of that element alone.
#pragma once

#include <functional>
#include <string>

typedef struct _cairo cairo_t;

namespace acanthus::detail {

struct PageLayout;

// Runs `draw` on a Cairo SVG surface the size of `page` (user units mapped as on the page) and
// returns the content of the resulting <svg> element, its ids numbered from 1 per call and
// prefixed with `id_prefix` so that they stay unique in the document. Throws InputError if Cairo
// reports an error.
std::string cairo_svg_fragment(const PageLayout& page, const std::function<void(cairo_t*)>& draw,
                               const std::string& id_prefix);

// The content of the first <svg> element of `svg`, with every id and local reference
// (id="x", href="#x", url(#x)) prefixed.
std::string svg_inner_fragment(const std::string& svg, const std::string& id_prefix);

}  // namespace acanthus::detail
