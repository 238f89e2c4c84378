// Built-in regions: "rect:W,H", "circle:R", "ellipse:RX,RY" and the default panel.
#include <2geom/path-sink.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "region/build.hpp"

namespace acanthus {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// The comma-separated sizes after "kind:", each a finite number > 0.
std::vector<double> parse_sizes(std::string_view spec, std::string_view args,
                                const std::vector<std::string>& names) {
    std::string usage = std::string(spec.substr(0, spec.find(':'))) + ":";
    for (std::size_t i = 0; i < names.size(); ++i) usage += (i ? "," : "") + names[i];
    std::vector<double> values;
    std::size_t start = 0;
    while (true) {
        std::size_t comma = args.find(',', start);
        std::string_view field = trim(args.substr(start, comma - start));
        std::size_t k = values.size();
        if (k >= names.size())
            throw InputError("region \"" + std::string(spec) + "\": too many sizes (expected " +
                             usage + ")");
        double v = 0;
        auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
        if (field.empty() || ec != std::errc() || end != field.data() + field.size() ||
            !std::isfinite(v))
            throw InputError("region \"" + std::string(spec) + "\": " + names[k] + " '" +
                             std::string(field) + "' is not a number (expected " + usage + ")");
        if (!(v > 0))
            throw InputError("region \"" + std::string(spec) + "\": " + names[k] +
                             " must be greater than 0");
        values.push_back(v);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    if (values.size() != names.size())
        throw InputError("region \"" + std::string(spec) + "\": expected " + usage);
    return values;
}

Geom::PathVector ellipse_path(double rx, double ry) {
    Geom::PathVector pv;
    Geom::PathBuilder builder(pv);
    builder.moveTo(Geom::Point(2 * rx, ry));
    builder.arcTo(rx, ry, 0, false, true, Geom::Point(0, ry));
    builder.arcTo(rx, ry, 0, false, true, Geom::Point(2 * rx, ry));
    builder.closePath();
    builder.flush();
    return pv;
}

Geom::PathVector rect_path(double w, double h) {
    Geom::PathVector pv;
    Geom::PathBuilder builder(pv);
    builder.moveTo(Geom::Point(0, 0));
    builder.lineTo(Geom::Point(w, 0));
    builder.lineTo(Geom::Point(w, h));
    builder.lineTo(Geom::Point(0, h));
    builder.closePath();
    builder.flush();
    return pv;
}

bool is_spec(std::string_view arg) {
    for (std::string_view kind : {"rect:", "circle:", "ellipse:"})
        if (arg.substr(0, kind.size()) == kind) return true;
    return false;
}

}  // namespace

Region Region::from_spec(std::string_view spec) {
    std::size_t colon = spec.find(':');
    std::string_view kind = spec.substr(0, colon);
    std::string_view args = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
    Geom::PathVector pv;
    if (kind == "rect") {
        auto v = parse_sizes(spec, args, {"W", "H"});
        pv = rect_path(v[0], v[1]);
    } else if (kind == "circle") {
        auto v = parse_sizes(spec, args, {"R"});
        pv = ellipse_path(v[0], v[0]);
    } else if (kind == "ellipse") {
        auto v = parse_sizes(spec, args, {"RX", "RY"});
        pv = ellipse_path(v[0], v[1]);
    } else {
        throw InputError("region \"" + std::string(spec) +
                         "\": unknown shape (expected rect:W,H, circle:R or ellipse:RX,RY)");
    }
    std::vector<detail::FilledShape> shapes{{std::move(pv), false, std::string(spec)}};
    return Region(detail::build_region_data(std::string(spec), std::move(shapes)));
}

Region Region::from_argument(std::string_view arg) {
    if (is_spec(arg)) return from_spec(arg);
    return from_svg_file(std::string(arg));
}

// A round-arched panel, 120 wide and 160 tall: a 120 x 100 rectangle under a half disc of
// radius 60, bounds (0, 0)-(120, 160), area 12000 + 1800π ≈ 17655. Sized for the Appendix A
// patterns (dots up to radius 3, flowers of radius 3): a few hundred elements.
Region Region::default_panel() {
    Geom::PathVector pv;
    Geom::PathBuilder builder(pv);
    builder.moveTo(Geom::Point(0, 160));
    builder.lineTo(Geom::Point(0, 60));
    builder.arcTo(60, 60, 0, false, true, Geom::Point(120, 60));
    builder.lineTo(Geom::Point(120, 160));
    builder.closePath();
    builder.flush();
    std::string name = "default panel (arch 120x160)";
    std::vector<detail::FilledShape> shapes{{std::move(pv), false, name}};
    return Region(detail::build_region_data(name, std::move(shapes)));
}

}  // namespace acanthus
