// Region from an SVG file: the union of every filled shape the SVG reader finds. Lines draw no
// area; polygons and polylines of fewer than three points neither. docs/regions.md.
#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <acanthus/region.hpp>
#include <filesystem>

#include "region/build.hpp"
#include "svg/shape_reader.hpp"

namespace acanthus {

Region Region::from_svg_string(std::string_view svg, const std::string& name) {
    std::vector<detail::FilledShape> shapes;
    for (detail::SvgShape& s : detail::read_svg_shapes(svg, name)) {
        const std::string& tag = s.element->tag;
        if (tag == "line") continue;
        if ((tag == "polygon" || tag == "polyline") && s.paths.front().size_open() < 2) continue;
        shapes.push_back({std::move(s.paths), s.evenodd, s.element->label});
    }
    if (shapes.empty())
        throw InputError(name +
                         ": no fillable shape (path, polygon, polyline, rect, circle or "
                         "ellipse) outside defs, clipPath, mask and symbol");
    return Region(detail::build_region_data(name, std::move(shapes)));
}

Region Region::from_svg_file(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::status(path, ec)))
        throw InputError(path +
                         ": cannot open region file: no such file (expected an SVG file "
                         "or rect:W,H, circle:R, ellipse:RX,RY)");
    const std::string text =
        read_input_file_or_throw(path, "region file", detail::kMaxSvgFileBytes);
    return from_svg_string(text, path);
}

}  // namespace acanthus
