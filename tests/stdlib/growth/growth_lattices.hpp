// Regular reference arrangements of every lattice kind the issue names, exact or with their
// coordinates rounded to 3 decimals of the spacing (as an editor that saves few digits would).
#pragma once

#include <acanthus/stdlib/growth.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace growth_lattices {

using acanthus::Point;
using acanthus::growth::ReferenceElement;

enum class Kind { triangular, square, honeycomb, three_colour, checker, stripes };

inline const char* name(Kind kind) {
    switch (kind) {
        case Kind::triangular:
            return "triangular";
        case Kind::square:
            return "square";
        case Kind::honeycomb:
            return "honeycomb";
        case Kind::three_colour:
            return "three_colour";
        case Kind::checker:
            return "checker";
        case Kind::stripes:
            return "stripes";
    }
    return "?";
}

inline const std::vector<Kind>& all_kinds() {
    static const std::vector<Kind> kinds{Kind::triangular,   Kind::square,  Kind::honeycomb,
                                         Kind::three_colour, Kind::checker, Kind::stripes};
    return kinds;
}

// x rounded to `decimals` decimals of the spacing a.
inline double rounded(double x, double a, int decimals) {
    const double unit = a * std::pow(10.0, -decimals);
    return std::round(x / unit) * unit;
}

// About `count` x `count` elements of the lattice with nearest-neighbour distance a, its origin
// at `origin`, the author's label per symbol (as the 3-colour reference had: "0", "1",
// "2"). decimals < 0: exact coordinates.
inline std::vector<ReferenceElement> lattice(Kind kind, int count, double a, int decimals = -1,
                                             Point origin = {0, 0}) {
    std::vector<ReferenceElement> out;
    auto add = [&](double x, double y, int symbol) {
        ReferenceElement e;
        e.symbol = std::string(1, static_cast<char>('a' + symbol));
        e.label = std::to_string(symbol);
        e.position = {origin.x + x, origin.y + y};
        if (decimals >= 0)
            e.position = {rounded(e.position.x, a, decimals), rounded(e.position.y, a, decimals)};
        out.push_back(e);
    };
    const double h = a * std::sqrt(3.0) / 2;
    for (int r = 0; r < count; ++r)
        for (int c = 0; c < count; ++c) {
            switch (kind) {
                case Kind::triangular:
                    add(c * a + (r % 2) * a / 2, r * h, 0);
                    break;
                case Kind::three_colour: {
                    // Axial colouring (q - r) mod 3: no two neighbours share a symbol.
                    int q = c - (r - r % 2) / 2;
                    add(c * a + (r % 2) * a / 2, r * h, ((q - r) % 3 + 3) % 3);
                    break;
                }
                case Kind::square:
                    add(c * a, r * a, 0);
                    break;
                case Kind::checker:
                    add(c * a, r * a, (r + c) % 2);
                    break;
                case Kind::stripes:
                    add(c * a, r * a, c % 4 == 3 ? 1 : 0);
                    break;
                case Kind::honeycomb: {
                    // Two sites per cell of a triangular lattice of side sqrt(3) a.
                    double x = c * 2 * h + (r % 2) * h, y = r * 1.5 * a;
                    add(x, y, 0);
                    add(x, y + a, 0);
                    break;
                }
            }
        }
    return out;
}

}  // namespace growth_lattices
