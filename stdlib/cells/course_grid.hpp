// The grid tool of [5.1]: lines through the face's corners and segment ends, each interval cut
// into units as close as possible to the wanted size; each unit is outside, partly inside or
// fully inside the face.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <cstdint>
#include <vector>

namespace acanthus::cells::detail {

enum UnitStatus : std::uint8_t { kOutside = 0, kPartial = 1, kFull = 2 };

struct CourseGrid {
    std::vector<double> xs;  // unit i spans [xs[i], xs[i+1]]
    std::vector<double> ys;  // row k spans [ys[k], ys[k+1]]; ys ascend (SVG: top row first)
    std::vector<std::uint8_t> status;  // row-major
    // Bond breaks (brick_grid.hpp): units [first, first + count) span an opening jamb to jamb,
    // nominal but for one of width `odd`, where the courses over and under take the break.
    struct Break {
        int first = 0, count = 0;
        double odd = 0;
    };
    std::vector<Break> breaks;

    int units() const { return static_cast<int>(xs.size()) - 1; }
    int rows() const { return static_cast<int>(ys.size()) - 1; }
    // Courses are counted from the bottom of the face.
    int course(int row) const { return rows() - 1 - row; }
    std::uint8_t at(int row, int unit) const {
        return status[static_cast<std::size_t>(row) * static_cast<std::size_t>(units()) +
                      static_cast<std::size_t>(unit)];
    }
    int unit_at(double x) const;  // -1 outside
    int row_at(double y) const;
    Rect cell(int row, int u0, int u1) const { return {xs[u0], ys[row], xs[u1], ys[row + 1]}; }
};

// Unit width `ux`, row height `uy`.
CourseGrid make_grid(const Facade& facade, int face, double ux, double uy);
// Sets the status of every unit of `g`'s lines against the face's outline.
void classify_units(const Facade& facade, int face, CourseGrid& g);

// A point just inside the face from a corner (along the bisector) or an edge (along its normal).
Point inside_corner(const Corner& c, double step);

}  // namespace acanthus::cells::detail
