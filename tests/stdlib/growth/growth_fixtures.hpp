// Reference arrangements shared by the growth tests.
#pragma once

#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace growth_fixtures {

using acanthus::Point;
using acanthus::growth::ReferenceElement;

// A triangular (hexagonal-packing) lattice of `rows` x `cols` points, spacing `a`; the symbol
// cycles through `symbols` along each row; no labels (every element is its own sub-id anyway).
inline std::vector<ReferenceElement> triangular_lattice(int rows, int cols, double a,
                                                        const std::vector<std::string>& symbols = {
                                                            "a"}) {
    std::vector<ReferenceElement> out;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            ReferenceElement e;
            e.symbol = symbols[static_cast<std::size_t>(c) % symbols.size()];
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

// A square grid of `rows` x `cols` points, spacing `a`, whose columns run a, a, ..., b with the
// given period: a near-regular reference whose 1-ring cannot tell the a columns apart.
inline std::vector<ReferenceElement> striped_grid(int rows, int cols, double a, int period) {
    std::vector<ReferenceElement> out;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            ReferenceElement e;
            e.symbol = c % period == period - 1 ? "b" : "a";
            e.position = {c * a, r * a};
            out.push_back(e);
        }
    return out;
}

// How faithfully a result keeps the reference's structure beyond the 1-ring: of the motifs whose
// neighbourhood within 2.1 spacings is as full as the fullest reference one, the fraction whose
// symbols there (paired by nearest offset, scaled to the result's spacing, unrotated) match some
// reference element of the same symbol exactly.
struct Placed {
    Point position;
    std::string symbol;
};

inline double median_spacing(const std::vector<Point>& points) {
    std::vector<double> d;
    for (std::size_t i = 0; i < points.size(); ++i) {
        double best = INFINITY;
        for (std::size_t j = 0; j < points.size(); ++j)
            if (i != j) best = std::min(best, acanthus::distance(points[i], points[j]));
        d.push_back(best);
    }
    std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
    return d[d.size() / 2];
}

inline double two_ring_consistency(const std::vector<ReferenceElement>& reference,
                                   const std::vector<Placed>& result) {
    using Hood = std::vector<std::pair<acanthus::Vector, std::string>>;
    auto hoods = [](const std::vector<Point>& p, const std::vector<std::string>& s, double reach) {
        std::vector<Hood> out(p.size());
        for (std::size_t i = 0; i < p.size(); ++i)
            for (std::size_t j = 0; j < p.size(); ++j)
                if (i != j && acanthus::distance(p[i], p[j]) < reach)
                    out[i].push_back({(p[j] - p[i]) * (1 / reach), s[j]});
        return out;
    };
    std::vector<Point> rp, tp;
    std::vector<std::string> rs, ts;
    for (const auto& e : reference) rp.push_back(e.position), rs.push_back(e.symbol);
    for (const auto& m : result) tp.push_back(m.position), ts.push_back(m.symbol);
    std::vector<Hood> rh = hoods(rp, rs, 2.1 * median_spacing(rp));
    std::vector<Hood> th = hoods(tp, ts, 2.1 * median_spacing(tp));
    std::size_t full = 0;
    for (const Hood& h : rh) full = std::max(full, h.size());
    int counted = 0, consistent = 0;
    for (std::size_t i = 0; i < th.size(); ++i) {
        if (th[i].size() != full) continue;
        ++counted;
        for (std::size_t k = 0; k < rh.size(); ++k) {
            if (rh[k].size() != full || rs[k] != ts[i]) continue;
            bool same = true;
            for (const auto& [offset, symbol] : th[i]) {
                const auto* best = &rh[k].front();
                for (const auto& entry : rh[k])
                    if ((entry.first - offset).length() < (best->first - offset).length())
                        best = &entry;
                if ((best->first - offset).length() > 0.25 || best->second != symbol) {
                    same = false;
                    break;
                }
            }
            if (same) {
                ++consistent;
                break;
            }
        }
    }
    return counted > 0 ? static_cast<double>(consistent) / counted : 0.0;
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
