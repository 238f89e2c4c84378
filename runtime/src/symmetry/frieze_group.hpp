// The seven frieze groups (docs/symmetry.md): the isometries of one period of a band along x
// about the axis y = 0, modulo the translation by the period.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "symmetry/isometry.hpp"

namespace acanthus::detail {

struct FriezeGroup {
    std::string name;  // canonical: p1 p11g p1m1 p11m p2 p2mg p2mm
    double period = 0;
    // One isometry per coset of the translations by the period, identity first, each with its
    // translation along x reduced into [0, period).
    std::vector<Isometry> transforms;

    std::size_t size() const { return transforms.size(); }
};

// The seven names, in the usual order.
const std::vector<std::string>& frieze_group_names();

// `name` is one of the seven (case-insensitive) or one of Conway's names for it (hop, step,
// sidle, jump, spinning-hop, spinning-sidle, spinning-jump). Throws UsageError listing the
// seven on anything else, and on a period that is not finite and positive.
FriezeGroup make_frieze_group(std::string_view name, double period);

// `t` with its translation along x reduced modulo `period` into [0, period), snapped to 0 within
// 1e-9 of the period.
Isometry modulo_period(const Isometry& t, double period);

}  // namespace acanthus::detail
