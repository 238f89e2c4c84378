// A rosette symmetry the ornament grows under (docs/symmetry.md): cyclic cN (N rotations) or
// dihedral dN (N rotations and N mirrors) about a centre.
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

}  // namespace acanthus
