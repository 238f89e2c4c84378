// The built-in skeletal strokes. Shapes are SVG path data in width units (y in [-0.5, 0.5]
// across the skeleton); stretched strokes span x in [0, 1], motifs x in [0, motif length].
#include <2geom/svg-path-parser.h>
#include <2geom/transforms.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <map>

#include "draw/skeletal_stroke_data.hpp"

namespace acanthus {

// This file builds public types from private (detail) parts.
using namespace detail;

namespace {

// A band along the whole skeleton; its profile gives it a shape.
constexpr const char* band = "M 0,-0.5 H 1 V 0.5 H 0 Z";

// A broad nib held at 45 degrees, pointing up and to the right on screen (y grows downwards):
// strokes along the nib are hairlines, strokes across it are full width.
constexpr double nib_angle = -M_PI / 4;
constexpr double hairline = 0.12;

StrokeShape shape(const char* path_data, double motif_length = 1) {
    Geom::PathVector paths = Geom::parse_svg_path(path_data);
    paths *= Geom::Scale(1 / motif_length, 1);
    return {paths, false};
}

// Semicircular cap of diameter `width` at the start of the skeleton.
double round_start(const StrokeSample& p) {
    double r = p.width / 2;
    if (p.s >= r) return 1;
    double u = (r - p.s) / r;
    return std::sqrt(std::max(0.0, 1 - u * u));
}

SkeletalStroke::Data tapered() {
    SkeletalStroke::Data d;
    d.name = "tapered";
    d.shapes = {shape(band)};
    // Full width for the first fifth, then down to a sharp point.
    d.profile = [](const StrokeSample& p) {
        constexpr double hold = 0.2;
        double u = std::clamp((p.x - hold) / (1 - hold), 0.0, 1.0);
        return round_start(p) * (1 - std::pow(u, 1.6));
    };
    return d;
}

SkeletalStroke::Data calligraphic() {
    SkeletalStroke::Data d;
    d.name = "calligraphic";
    d.shapes = {shape(band)};
    d.profile = [](const StrokeSample& p) {
        return hairline + (1 - hairline) * std::abs(std::sin(p.tangent - nib_angle));
    };
    return d;
}

SkeletalStroke::Data leafy() {
    SkeletalStroke::Data d;
    d.name = "leafy";
    constexpr double motif = 1.2;
    // A thin stem (overlapping its neighbours a little) with one leaf on each side.
    d.shapes = {
        shape("M -0.02,-0.05 H 1.22 V 0.05 H -0.02 Z "
              "M 0.06,0.03 C 0.34,-0.042 0.534,0.187 0.56,0.46 "
              "C 0.307,0.451 0.071,0.27 0.06,0.03 Z "
              "M 0.66,-0.03 C 0.94,0.042 1.134,-0.187 1.16,-0.46 "
              "C 0.907,-0.451 0.671,-0.269 0.66,-0.03 Z",
              motif)};
    d.motif_length = motif;
    // Leaves shrink towards the tip of the skeleton.
    d.profile = [](const StrokeSample& p) { return 1 - 0.45 * p.x; };
    return d;
}

SkeletalStroke::Data beaded() {
    SkeletalStroke::Data d;
    d.name = "beaded";
    constexpr double motif = 1.5;
    // A large bead followed by a small one.
    d.shapes = {
        shape("M 0.05,0 A 0.45,0.45 0 1 0 0.95,0 A 0.45,0.45 0 1 0 0.05,0 Z "
              "M 1.02,0 A 0.16,0.16 0 1 0 1.34,0 A 0.16,0.16 0 1 0 1.02,0 Z",
              motif)};
    d.motif_length = motif;
    return d;
}

SkeletalStroke::Data ribbon() {
    SkeletalStroke::Data d;
    d.name = "ribbon";
    d.shapes = {shape(band)};
    // A flat ribbon twisting a half turn every 2.5 widths: it narrows to an edge and widens again.
    d.profile = [](const StrokeSample& p) {
        constexpr double half_turn = 2.5;
        return std::cos(M_PI * p.s / (half_turn * p.width));
    };
    return d;
}

SkeletalStroke::Data thorny() {
    SkeletalStroke::Data d;
    d.name = "thorny";
    constexpr double motif = 1.6;
    // A stem with a forward-hooked thorn on each side.
    d.shapes = {
        shape("M -0.02,-0.11 H 1.62 V 0.11 H -0.02 Z "
              "M 0.25,0.1 Q 0.65,0.2 0.9,0.5 Q 0.7,0.25 0.7,0.1 Z "
              "M 0.95,-0.1 Q 1.35,-0.2 1.6,-0.5 Q 1.4,-0.25 1.4,-0.1 Z",
              motif)};
    d.motif_length = motif;
    d.profile = [](const StrokeSample& p) { return round_start(p) * (1 - 0.6 * p.x); };
    return d;
}

const std::map<std::string, SkeletalStroke, std::less<>>& builtins() {
    static const std::map<std::string, SkeletalStroke, std::less<>> strokes = [] {
        std::map<std::string, SkeletalStroke, std::less<>> m;
        for (auto make : {tapered, calligraphic, leafy, beaded, ribbon, thorny}) {
            SkeletalStroke::Data d = make();
            std::string name = d.name;
            m.emplace(name, SkeletalStroke(std::move(d)));
        }
        return m;
    }();
    return strokes;
}

}  // namespace

const SkeletalStroke& SkeletalStroke::builtin(std::string_view name) {
    const auto& strokes = builtins();
    auto it = strokes.find(name);
    if (it == strokes.end()) {
        std::string known;
        for (const auto& [n, s] : strokes) known += (known.empty() ? "" : ", ") + n;
        throw UsageError("unknown stroke '" + std::string(name) + "' (built-in strokes: " + known +
                         "; or give an .svg file)");
    }
    return it->second;
}

std::vector<std::string> SkeletalStroke::builtin_names() {
    std::vector<std::string> names;
    for (const auto& [n, s] : builtins()) names.push_back(n);
    return names;
}

}  // namespace acanthus
