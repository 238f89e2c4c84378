// Friezes and wallpaper groups as the growth engine uses them (docs/symmetry.md): the catalog's
// isometries of one period or tile placed on the region, with every translate that reaches it,
// and the box growth runs in.
#pragma once

#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <optional>

#include "symmetry/symmetry_group.hpp"

namespace acanthus::detail {

struct TranslationSetup {
    TranslationGroup group;
    // Periodic (a wallpaper tile, a closed band): the box the engine grows in, the tile or band
    // widened so that elements cross its edges and the field sees their translates; none: the
    // region itself.
    std::optional<Region> box;
    double period = 0;  // a frieze's period, adjusted to divide a closed band's length
};

// The frieze along x about the centre line of the region's bounds, the period starting at
// their left edge. With `wrap_x` the bounds must start at x = 0 and be `wrap_x` long, and the
// period becomes wrap_x / round(wrap_x / period). Throws UsageError (bad group or period).
TranslationSetup frieze_setup(const Frieze& frieze, const Region& region,
                              std::optional<double> wrap_x);
// The wallpaper group on its tile (the region). Throws UsageError (bad group, a lattice the
// group cannot have).
TranslationSetup wallpaper_setup(const Wallpaper& wallpaper);
// The tile as a region: the parallelogram from the origin spanned by its two sides.
Region tile_region(const Wallpaper& wallpaper);

}  // namespace acanthus::detail
