// The symmetry an ornament grows under (docs/symmetry.md): a rosette (cyclic cN or dihedral dN
// about a centre), a frieze along x, or a wallpaper group on a periodic tile.
#pragma once

#include <acanthus/point.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace acanthus {

struct Symmetry {
    enum class Kind { cyclic, dihedral };
    Kind kind = Kind::cyclic;
    int order = 1;                // N
    std::optional<Point> center;  // none: the centre of the region's largest inscribed circle

    static constexpr int kMaxOrder = 360;
    // "c6", "d8" (case-insensitive). Throws UsageError naming what is wrong.
    static Symmetry parse(std::string_view text);
    std::string name() const;  // "c6", "d8"
};

// A frieze group repeating along x about the horizontal centre line of the region's bounds.
struct Frieze {
    std::string group = "p1";  // p1 p11g p1m1 p11m p2 p2mg p2mm
    double period = 0;         // the translation along x
};

// A wallpaper group on the tile spanned by (width, 0) and height * (cos angle, sin angle) from
// the origin (y down): the region is the tile and the plane is periodic.
struct Wallpaper {
    std::string group = "p1";  // p1 ... p6m
    double width = 0, height = 0;
    double angle_degrees = 90;
};

}  // namespace acanthus
