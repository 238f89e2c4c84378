// Reference arrangements shared by the growth tests.
#pragma once

#include <acanthus/stdlib/growth.hpp>
#include <cmath>
#include <string>
#include <vector>

namespace growth_fixtures {

using acanthus::Point;
using acanthus::growth::ReferenceElement;

// A triangular (hexagonal-packing) lattice of `rows` x `cols` points, spacing `a`; the symbol
// cycles through `symbols` along each row, every element has its own sub-id.
inline std::vector<ReferenceElement> triangular_lattice(int rows, int cols, double a,
                                                        const std::vector<std::string>& symbols = {
                                                            "a"}) {
    std::vector<ReferenceElement> out;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            ReferenceElement e;
            e.symbol = symbols[static_cast<std::size_t>(c) % symbols.size()];
            e.sub = std::to_string(out.size());
            e.position = {c * a + (r % 2) * a / 2, r * a * std::sqrt(3.0) / 2};
            out.push_back(e);
        }
    return out;
}

// The lattice above with every point moved by up to `jitter` in x and y (a fixed pattern, so the
// same in every test run): an irregular uniform reference.
inline std::vector<ReferenceElement> jittered_lattice(int rows, int cols, double a, double jitter,
                                                      const std::vector<std::string>& symbols = {
                                                          "a"}) {
    auto out = triangular_lattice(rows, cols, a, symbols);
    for (std::size_t i = 0; i < out.size(); ++i) {
        // Deterministic pseudo-random offsets in [-1, 1] from the index.
        double u = std::sin(12.9898 * static_cast<double>(i) + 1.0) * 43758.5453;
        double v = std::sin(78.233 * static_cast<double>(i) + 2.0) * 12345.6789;
        out[i].position.x += jitter * (2 * (u - std::floor(u)) - 1);
        out[i].position.y += jitter * (2 * (v - std::floor(v)) - 1);
    }
    return out;
}

// Points on a hexagonal patch: the centre and `rings` hexagonal rings around it, spacing a.
inline std::vector<Point> hex_patch(int rings, double a) {
    std::vector<Point> out;
    for (int q = -rings; q <= rings; ++q)
        for (int r = -rings; r <= rings; ++r) {
            int s = -q - r;
            if (std::abs(s) > rings) continue;
            out.push_back({a * (q + r / 2.0), a * r * std::sqrt(3.0) / 2});
        }
    return out;
}

}  // namespace growth_fixtures
