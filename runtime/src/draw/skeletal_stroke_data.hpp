// What a skeletal stroke is made of: closed shapes in the stroke's frame plus an optional
// width profile. Shared by the warping code and the built-in and SVG stroke definitions.
#pragma once

#include <2geom/pathvector.h>

#include <acanthus/skeletal_stroke.hpp>
#include <functional>
#include <string>
#include <vector>

namespace acanthus::detail {

// Where on the skeleton a shape point lands; the input of a width profile.
struct StrokeSample {
    double x = 0;        // along the whole stroke, 0 at the start, 1 at the end
    double s = 0;        // arc length from the skeleton's start
    double length = 0;   // the skeleton's total arc length
    double width = 0;    // the stroke's nominal width
    double tangent = 0;  // direction of the skeleton at s, radians
};

// One filled shape of a stroke, in frame coordinates: x in [0, 1] along the skeleton (or along
// one motif), y in [-0.5, 0.5] across it, in units of the stroke's width.
struct StrokeShape {
    Geom::PathVector paths;
    bool evenodd = false;
};

}  // namespace acanthus::detail

namespace acanthus {

// The public type's representation (a pimpl, so it lives in the type's own namespace).
struct SkeletalStroke::Data {
    std::string name;
    std::vector<detail::StrokeShape> shapes;
    // 0: the shapes stretch over the whole skeleton. Otherwise the shapes are one motif this many
    // widths long, repeated a whole number of times along the skeleton.
    double motif_length = 0;
    // Multiplies the offset across the skeleton; empty means 1.
    std::function<double(const detail::StrokeSample&)> profile;
};

}  // namespace acanthus
