// Cairo's SVG of one drawing, to be embedded in the structured SVG.
#include "output/svg_fallback.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <acanthus/error.hpp>

#include "output/document.hpp"
#include "output/page_layout.hpp"

namespace acanthus::detail {

namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string cairo_svg_fragment(const PageLayout& page, const std::function<void(cairo_t*)>& draw,
                               const std::string& id_prefix) {
    std::string bytes;
    cairo_surface_t* surface =
        cairo_svg_surface_create_for_stream(&append, &bytes, page.width, page.height);
    cairo_t* cr = cairo_create(surface);
    page.apply(cr);
    try {
        draw(cr);
    } catch (...) {
        cairo_destroy(cr);
        cairo_surface_destroy(surface);
        throw;
    }
    cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS)
        throw InputError(std::string("drawing an element through Cairo failed: ") +
                         cairo_status_to_string(status));
    return svg_inner_fragment(renumber_svg_surface_ids(bytes), id_prefix);
}

std::string svg_inner_fragment(const std::string& svg, const std::string& id_prefix) {
    std::size_t open = svg.find("<svg");
    std::size_t begin = open == std::string::npos ? std::string::npos : svg.find('>', open);
    std::size_t end = svg.rfind("</svg>");
    if (begin == std::string::npos || end == std::string::npos || end < begin) return {};
    std::string inner = svg.substr(begin + 1, end - begin - 1);
    std::string out;
    out.reserve(inner.size() + 64);
    static constexpr std::string_view markers[] = {"id=\"", "href=\"#", "url(#"};
    for (std::size_t i = 0; i < inner.size();) {
        bool matched = false;
        for (std::string_view marker : markers) {
            // "id=" only as a whole attribute name, not the end of another one.
            bool whole = marker != markers[0] || i == 0 || inner[i - 1] == ' ' ||
                         inner[i - 1] == '\n' || inner[i - 1] == '\t';
            if (whole && inner.compare(i, marker.size(), marker) == 0) {
                out += marker;
                out += id_prefix;
                i += marker.size();
                matched = true;
                break;
            }
        }
        if (!matched) out += inner[i++];
    }
    return out;
}

}  // namespace acanthus::detail
