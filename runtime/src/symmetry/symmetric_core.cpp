#include "symmetry/symmetric_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "field/empty_circle_finder.hpp"
#include "geometry/spatial_index.hpp"

namespace acanthus::detail {

std::vector<int> pixels_outside_core(const RasterBuffer& raster, const SymmetryGroup& group) {
    const GridFrame& grid = raster.grid();
    const auto& occ = raster.occupancy();
    const auto& g = group.transforms();
    const int w = grid.width, h = grid.height;
    // A pixel's square maps into the 3 x 3 pixels round the one holding its centre's image:
    // when all of those are free, the whole image is inside the region.
    auto clear_round = [&](int q) {
        if (q < 0) return false;
        const int i = q % w, j = q / w;
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                const int x = i + di, y = j + dj;
                if (x < 0 || y < 0 || x >= w || y >= h) return false;
                if (occ[static_cast<std::size_t>(y * w + x)] ==
                    static_cast<std::uint8_t>(ObstacleKind::boundary))
                    return false;
            }
        return true;
    };
    std::vector<int> out;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int p = j * w + i;
            if (occ[static_cast<std::size_t>(p)] != static_cast<std::uint8_t>(ObstacleKind::none))
                continue;
            const Point c = grid.center_of(i, j);
            for (std::size_t k = 1; k < g.size(); ++k)
                if (!clear_round(raster.pixel_of(g[k].apply(c)))) {
                    out.push_back(p);
                    break;
                }
        }
    return out;
}

namespace {

// A group with translations: the domain is convex (an intersection of half-planes), so each row's
// pixels in it are one run. Each half-plane's crossing of the row bounds the pixels surely in
// (every half-plane's measure below -eps) and surely out (one above eps); in_domain() decides
// the few pixels left near the run's ends, so rounding decides as it does there.
void domain_rows(const GridFrame& grid, const SymmetryGroup& group,
                 std::vector<std::uint8_t>& out) {
    const double tol = grid.pixel;
    const double eps = 1e-9 * (1 + std::abs(grid.x0) + std::abs(grid.y0) +
                               grid.pixel * (grid.width + grid.height));
    const double inf = std::numeric_limits<double>::infinity();
    // The pixel index of x, clamped to the row (and a pixel beyond either end).
    auto index = [&](double x) {
        return std::clamp((x - grid.x0) / grid.pixel - 0.5, -2.0, grid.width + 2.0);
    };
    for (int j = 0; j < grid.height; ++j) {
        const double y = grid.center_of(0, j).y;
        // Surely in for x in [in_lo, in_hi]; surely out below out_lo or above out_hi.
        double in_lo = -inf, in_hi = inf, out_lo = -inf, out_hi = inf;
        bool measure_all = false;
        for (const auto& [m, n] : group.halfplanes()) {
            // (x - m.x) n.x - k is the half-plane's measure less the widening.
            const double k = tol - (y - m.y) * n.y;
            if (n.x == 0) {
                if (k < -eps)
                    out_lo = inf;  // the row is out
                else if (k <= eps)
                    measure_all = true;
                continue;
            }
            const double at = m.x + k / n.x, slack = eps / std::abs(n.x);
            if (n.x > 0) {
                in_hi = std::min(in_hi, at - slack);
                out_hi = std::min(out_hi, at + slack);
            } else {
                in_lo = std::max(in_lo, at + slack);
                out_lo = std::max(out_lo, at - slack);
            }
        }
        std::uint8_t* row = out.data() + static_cast<std::size_t>(j) * grid.width;
        if (out_lo == inf) continue;
        int first_in = grid.width, last_in = -1, last_out_low = -1, first_out_high = grid.width;
        if (!measure_all) {
            // One pixel's margin each way against the rounding of the index itself.
            first_in = static_cast<int>(std::ceil(index(in_lo))) + 1;
            last_in = static_cast<int>(std::floor(index(in_hi))) - 1;
            last_out_low = static_cast<int>(std::floor(index(out_lo))) - 1;
            first_out_high = static_cast<int>(std::ceil(index(out_hi))) + 1;
        }
        for (int i = std::max(0, last_out_low + 1); i < std::min(grid.width, first_out_high); ++i)
            row[i] = (i >= first_in && i <= last_in) || group.in_domain(grid.center_of(i, j), tol)
                         ? 1
                         : 0;
    }
}

}  // namespace

std::vector<std::uint8_t> domain_pixels(const GridFrame& grid, const SymmetryGroup& group) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(grid.width) * grid.height, 0);
    if (!group.rosette()) {
        domain_rows(grid, group, out);
        return out;
    }
    // in_domain() takes an arc tangent per pixel. Most pixels are decided without one by their
    // angle to the wedge's bisector: inside the wedge's half angle they are in; beyond it by
    // more than the widening allows at their radius they are out (the widening is tol / r, so
    // at least kFar / 2^k pixels out it is below 2^k / kFar); a margin keeps rounding from
    // deciding otherwise than in_domain(), which decides the rest (the centre, and thin bands
    // along the edges).
    constexpr double kFar = 64, kMargin = 1e-9;
    constexpr int kLevels = 6;  // widenings 1/64, 1/32, ... 1/2
    const double tol = grid.pixel;
    const std::vector<std::pair<Point, Point>> edges = group.domain_edges(1);
    const bool cheap = group.rosette() && edges.size() == 2;
    Vector bisector(0, 0);
    double half = 0;
    if (cheap) {
        const Vector u0 = edges[0].second - edges[0].first;
        half = group.wedge() / 2;
        // The bisector: the first edge turned by half the wedge (as in_domain() measures).
        const double c = std::cos(half), sn = std::sin(half);
        bisector = Vector(u0.x * c - u0.y * sn, u0.x * sn + u0.y * c);
    }
    const double cos_in = std::cos(half);
    const double far_angle = half + 1 / kFar;
    const bool can_be_out = far_angle + kMargin < M_PI;
    // Level k: pixels farther than kFar / 2^k pixels are out beyond half + 2^k / kFar.
    double level_r[kLevels], level_cos[kLevels];
    int levels = 0;
    for (int k = 0; k < kLevels; ++k) {
        const double angle = half + static_cast<double>(1 << k) / kFar;
        if (!(angle + kMargin < M_PI)) break;
        level_r[k] = kFar / (1 << k) * tol;
        level_cos[k] = std::cos(angle);
        levels = k + 1;
    }
    const Point center = group.center();
    auto decide = [&](int i, int j) {
        const Point p = grid.center_of(i, j);
        auto& cell = out[static_cast<std::size_t>(j * grid.width + i)];
        if (cheap) {
            const Vector v = p - center;
            const double r = std::sqrt(v.dot(v));  // hypot's care is not needed here
            if (r > 0) {
                const double cosine = bisector.dot(v) / r;
                if (cosine >= cos_in + kMargin) {
                    cell = 1;
                    return;
                }
                for (int k = 0; k < levels; ++k)
                    if (r > level_r[k]) {
                        if (cosine <= level_cos[k] - kMargin) return;
                        break;
                    }
            }
        }
        cell = group.in_domain(p, tol) ? 1 : 0;
    };
    // A whole 8 x 8 tile at once when every pixel centre of it (within `spread_radius` of the
    // tile's middle) lies on the inner side of both of the wedge's edges (all in), or on the
    // outer side of an edge of the wedge widened by 1 / kFar, at least kFar pixels from the
    // centre (all out); pixel by pixel otherwise. Half-planes hold a wedge under a half-turn.
    constexpr int kTile = 8;
    const double spread_radius = (kTile - 1) / 2.0 * M_SQRT2 * grid.pixel;
    const bool by_edges = cheap && far_angle + kMargin < M_PI / 2;
    auto turned = [&](double a) {
        const double c = std::cos(a), sn = std::sin(a);
        return Vector(bisector.x * c - bisector.y * sn, bisector.x * sn + bisector.y * c);
    };
    auto cross = [](Vector a, Vector b) { return a.x * b.y - a.y * b.x; };
    const Vector in_lo = turned(-half), in_hi = turned(half);
    const Vector out_lo = turned(-far_angle), out_hi = turned(far_angle);
    const double bisector_length = std::sqrt(bisector.dot(bisector));
    for (int j0 = 0; j0 < grid.height; j0 += kTile)
        for (int i0 = 0; i0 < grid.width; i0 += kTile) {
            const int i1 = std::min(grid.width, i0 + kTile), j1 = std::min(grid.height, j0 + kTile);
            if (cheap) {
                const Point mid =
                    grid.center_of(i0, j0) + Vector(1, 1) * ((kTile - 1) / 2.0 * grid.pixel);
                const Vector v = mid - center;
                const double r = std::sqrt(v.dot(v));
                bool in = false, away = false;
                if (by_edges) {
                    // Distances to the edges' lines, in units of the bisector's length.
                    const double reach = (spread_radius + kMargin * (1 + r)) * bisector_length;
                    in = cross(in_lo, v) > reach && cross(v, in_hi) > reach;
                    away = !in && r > spread_radius + kFar * tol &&
                           (cross(out_lo, v) < -reach || cross(v, out_hi) < -reach);
                } else if (r > spread_radius + kFar * tol) {
                    const double theta = std::acos(std::clamp(bisector.dot(v) / r, -1.0, 1.0));
                    const double spread = std::asin(spread_radius / r);
                    in = theta + spread < half - kMargin;
                    away = can_be_out && theta - spread > far_angle + kMargin;
                }
                if (in || away) {
                    if (in)  // (the pixels are 0 already: most tiles are away)
                        for (int j = j0; j < j1; ++j)
                            std::fill(out.begin() + j * grid.width + i0,
                                      out.begin() + j * grid.width + i1, 1);
                    continue;
                }
            }
            for (int j = j0; j < j1; ++j)
                for (int i = i0; i < i1; ++i) decide(i, j);
        }
    return out;
}

std::vector<bool> near_zone(const GridFrame& g, const std::vector<std::uint8_t>& domain,
                            int cells) {
    if (domain.empty()) return {};
    const int pad = cells;
    const int cw = ((g.width - 1) >> 3) + 1 + 2 * pad;
    const int ch = ((g.height - 1) >> 3) + 1 + 2 * pad;
    const std::vector<std::uint8_t> tiles = nonzero_tiles(domain, g.width, g.height);
    const int tw = cw - 2 * pad, th = ch - 2 * pad;
    // The square of side 2 cells + 1 about each domain cell, as two passes of a sliding
    // count (in bytes: a vector<bool> costs a bit operation per cell).
    std::vector<std::uint8_t> across(static_cast<std::size_t>(cw) * ch, 0);
    for (int tj = 0; tj < th; ++tj) {
        const std::uint8_t* in = tiles.data() + static_cast<std::size_t>(tj) * tw;
        std::uint8_t* row = across.data() + static_cast<std::size_t>(tj + pad) * cw;
        int count = 0;  // domain tiles among columns x - cells .. x + cells
        for (int x = 0; x < cw; ++x) {
            const int enter = x + cells - pad, leave = x - cells - 1 - pad;
            if (enter >= 0 && enter < tw && in[enter]) ++count;
            if (leave >= 0 && leave < tw && in[leave]) --count;
            row[x] = count > 0;
        }
    }
    std::vector<bool> out(across.size(), false);
    for (int x = 0; x < cw; ++x) {
        int count = 0;
        for (int y = 0; y < ch; ++y) {
            const int enter = y + cells, leave = y - cells - 1;
            if (enter < ch && across[static_cast<std::size_t>(enter) * cw + x]) ++count;
            if (leave >= 0 && across[static_cast<std::size_t>(leave) * cw + x]) --count;
            if (count > 0) out[static_cast<std::size_t>(y) * cw + x] = true;
        }
    }
    return out;
}

std::vector<Point> point_orbit(const SymmetryGroup& group, Point p, double tol,
                               const Rect& bounds) {
    std::vector<Point> out{p};
    out.reserve(group.size());
    // distance(o, q) <= tol, by the square where it surely tells (hypot() is dear).
    constexpr double kLoose = 1 + 1e-12;
    const double tol2 = tol * tol;
    auto same = [&](Point o, Point q) {
        const Vector v = q - o;
        const double s = v.x * v.x + v.y * v.y;
        if (s * kLoose < tol2) return true;
        if (s > tol2 * kLoose) return false;
        return distance(o, q) <= tol;
    };
    const auto& g = group.transforms();
    // g(p) and h(p) are as far apart as p and g^-1 h (p), an isometry of the group: when every
    // one moves p by well over the tolerance, no two images are the same and each is kept (a
    // translate only inside the bounds), in order, without comparing them pairwise. (The
    // margin covers the rounding of the images.)
    const double margin = 1e-9 * (1 + std::abs(p.x) + std::abs(p.y) + std::abs(bounds.x0) +
                                  std::abs(bounds.x1) + std::abs(bounds.y0) + std::abs(bounds.y1));
    if (group.moves_apart(p, 2 * tol + margin)) {
        for (std::size_t k = 1; k < g.size(); ++k) {
            const Point q = g[k].apply(p);
            if (group.rosette() || bounds.contains(q)) out.push_back(q);
        }
        return out;
    }
    for (std::size_t k = 1; k < group.size(); ++k) {
        const Point q = group.transforms()[k].apply(p);
        if (!group.rosette() && !bounds.contains(q)) continue;  // translates beyond the region
        bool seen = false;
        for (Point o : out) seen = seen || same(o, q);
        if (!seen) out.push_back(q);
    }
    return out;
}

bool maps_onto_itself(const Region& region, const SymmetryGroup& group, double tolerance) {
    // Each sampled point's images are measured against the flattened boundary first (an
    // R-tree of its segments): the flattening is within `slack` of the curves both ways, so
    // only an image within `slack` of the threshold needs the exact (costly) distance.
    const double flatten = tolerance / 4, slack = 2 * flatten;
    const auto rings = region.rings(flatten);
    std::vector<std::pair<SpatialIndex::Entry, Rect>> entries;
    for (std::size_t r = 0; r < rings.size(); ++r)
        for (std::size_t k = 0; k < rings[r].size(); ++k) {  // the last closes the ring
            const Point a = rings[r][k], b = rings[r][(k + 1) % rings[r].size()];
            entries.push_back({{static_cast<int>(r), static_cast<int>(k)},
                               Rect{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                                    std::max(a.y, b.y)}});
        }
    if (entries.empty()) return true;
    const SpatialIndex segments(entries);
    auto to_segment = [&](Point q, SpatialIndex::Entry e) {
        const auto& ring = rings[static_cast<std::size_t>(e.element)];
        const Point a = ring[static_cast<std::size_t>(e.proxy)];
        const Point b = ring[(static_cast<std::size_t>(e.proxy) + 1) % ring.size()];
        const Vector ab = b - a;
        const double len2 = ab.dot(ab);
        const double t = len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        return distance(q, a + ab * t);
    };
    // The segment each transformation's last image was near: the next point's image usually
    // lies by it or by a neighbour, which settles it without a query (a segment that near
    // makes the nearest at least as near); the hint follows the images along the ring.
    std::vector<SpatialIndex::Entry> hint(group.size());
    auto near_hint = [&](Point q, SpatialIndex::Entry& e) {
        if (e.element < 0) return false;
        const int n = static_cast<int>(rings[static_cast<std::size_t>(e.element)].size());
        for (int step : {0, 1, -1}) {
            const SpatialIndex::Entry at{e.element, (e.proxy + step + n) % n};
            if (to_segment(q, at) <= tolerance - slack) {
                e = at;
                return true;
            }
        }
        return false;
    };
    for (const auto& ring : rings)
        for (Point p : ring)
            for (std::size_t k = 1; k < group.size(); ++k) {
                const Point q = group.transforms()[k].apply(p);
                if (near_hint(q, hint[k])) continue;
                double d = std::numeric_limits<double>::infinity();
                for (const SpatialIndex::Entry& e : segments.within(q, tolerance + slack)) {
                    const double de = to_segment(q, e);
                    if (de < d) {
                        d = de;
                        hint[k] = e;
                    }
                }
                if (d <= tolerance - slack) continue;
                if (d > tolerance + slack || region.distance_to_boundary(q) > tolerance)
                    return false;
            }
    return true;
}

bool core_contains(const Region& region, const SymmetryGroup& group, Point p) {
    for (const Isometry& g : group.transforms())
        if (!region.contains(g.apply(p))) return false;
    return true;
}

double core_distance_to_boundary(const Region& region, const SymmetryGroup& group, Point p) {
    double d = region.distance_to_boundary(p);
    for (std::size_t k = 1; k < group.size(); ++k)
        d = std::min(d, region.distance_to_boundary(group.transforms()[k].apply(p)));
    return d;
}

}  // namespace acanthus::detail
