// The 17 wallpaper groups (docs/symmetry.md) on a tile: the tile's two sides a and b span the
// translations the output repeats by, and the group is given as one isometry per coset of those
// translations, in the standard settings of the International Tables for Crystallography, Vol. A.
#pragma once

#include <acanthus/point.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "symmetry/isometry.hpp"

namespace acanthus::detail {

// "W,H[,ANGLE]": sides a = (W, 0) and b = H (cos ANGLE, sin ANGLE), ANGLE in degrees
// (default 90; y points down, as everywhere on the page).
struct Tile {
    double width = 0, height = 0, angle = 90;

    Point a() const;
    Point b() const;
    // "100,80" or "100,100,60"
    std::string text() const;
};

// Throws UsageError unless `text` is two or three numbers, the sides finite and positive and
// the angle strictly between 0 and 180 degrees.
Tile parse_tile(std::string_view text);

struct WallpaperGroup {
    std::string name;  // canonical: p1 p2 pm pg cm pmm pmg pgg cmm p4 p4m p4g p3 p3m1 p31m p6 p6m
    Tile tile;
    // One isometry per coset of the tile's translations (integer combinations of a and b),
    // identity first, each translation part reduced into the tile (fractional coordinates in
    // [0, 1)). cm and cmm take the centred rectangular cell as their tile, which holds two
    // primitive cells: their transforms include the centring translation (a + b) / 2.
    std::vector<Isometry> transforms;
    // Primitive cells per tile: 2 for cm and cmm, else 1.
    int cells = 1;

    std::size_t size() const { return transforms.size(); }
    // The group's order counted per primitive cell (1 2 2 2 2 4 4 4 4 4 8 8 3 6 6 6 12).
    std::size_t order() const { return transforms.size() / static_cast<std::size_t>(cells); }
};

// The 17 names, in the International Tables' order.
const std::vector<std::string>& wallpaper_group_names();

// `name` is one of the 17 (case-insensitive) or its full symbol (p2mm, p2mg, p2gg, c2mm, p4mm,
// p4gm, p6mm). Throws UsageError listing the 17 on an unknown name, and saying which lattice
// the group needs when the tile is not one: pm pg pmm pmg pgg cm cmm a rectangle (ANGLE 90),
// p4 p4m p4g a square (W = H, ANGLE 90), p3 p3m1 p31m p6 p6m a hexagonal cell (W = H, ANGLE 60
// or 120); p1 and p2 take any.
WallpaperGroup make_wallpaper_group(std::string_view name, const Tile& tile);

// `t` with its translation reduced modulo the lattice spanned by a and b: its fractional
// coordinates in [0, 1), snapped to 0 within 1e-9.
Isometry modulo_lattice(const Isometry& t, Point a, Point b);

}  // namespace acanthus::detail
