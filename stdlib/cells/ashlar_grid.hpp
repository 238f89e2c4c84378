// The grid every stone of an ashlar wall is laid on (ashlar, sill stones, stone lintels): the
// grid tool's units of Options::ashlar_unit, made once per face and shared.
#pragma once

#include <string>

#include "context_data.hpp"
#include "course_grid.hpp"

namespace acanthus::cells::detail {

inline double ashlar_unit(const Options& o) {
    return o.ashlar_unit > 0 ? o.ashlar_unit : o.brick_height + o.mortar;
}

inline CourseGrid& ashlar_grid(Context& c, int face) {
    return c.data().layout<CourseGrid>("ashlar:" + std::to_string(face), [&] {
        const double unit = ashlar_unit(c.options());
        return make_grid(c.facade(), face, unit, unit);
    });
}

}  // namespace acanthus::cells::detail
