#include "symmetry/translation_groups.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "symmetry/frieze_group.hpp"
#include "symmetry/wallpaper_group.hpp"

namespace acanthus::detail {

namespace {

// Fractions of a period (or of the tile's sides) at which the domain's point lies: off every
// mirror, glide axis and rotation centre of the catalogs (multiples of 1/8, 1/6 and x = y).
constexpr double kGenericX = 0.1371, kGenericY = 0.0391;

Isometry translation(double x, double y) { return Isometry{1, 0, 0, 1, x, y}; }

Rect widened(const Rect& r, double dx, double dy) {
    return {r.x0 - dx, r.y0 - dy, r.x1 + dx, r.y1 + dy};
}

Region box_region(const Rect& r, const std::string& name) {
    std::ostringstream svg;
    svg.precision(17);
    svg << "<svg xmlns='http://www.w3.org/2000/svg'><rect x='" << r.x0 << "' y='" << r.y0
        << "' width='" << r.width() << "' height='" << r.height() << "'/></svg>";
    return Region::from_svg_string(svg.str(), name);
}

// Every coset representative composed with every translation i a + j b (|i|, |j| <= reach)
// that moves the box's centre by no more than the box's diagonal: each maps some point of the
// box into it. The identity first.
std::vector<Isometry> reaching(const std::vector<Isometry>& cosets, Vector a, Vector b, int reach_a,
                               int reach_b, const Rect& box) {
    const Point c = box.center();
    const double diagonal = std::hypot(box.width(), box.height());
    std::vector<Isometry> out{Isometry{}};
    for (std::size_t h = 0; h < cosets.size(); ++h)
        for (int i = -reach_a; i <= reach_a; ++i)
            for (int j = -reach_b; j <= reach_b; ++j) {
                if (h == 0 && i == 0 && j == 0) continue;
                const Vector t = a * i + b * j;
                const Isometry g = cosets[h].then(translation(t.x, t.y));
                if (distance(g.apply(c), c) <= diagonal + 1e-9 * (1 + diagonal)) out.push_back(g);
            }
    return out;
}

}  // namespace

TranslationSetup frieze_setup(const Frieze& frieze, const Region& region,
                              std::optional<double> wrap_x) {
    const Rect bounds = region.bounds();
    double period = frieze.period;
    if (!std::isfinite(period) || period <= 0)
        throw UsageError("--period must be a positive number of user units");
    if (wrap_x) {
        const double length = *wrap_x;
        if (!std::isfinite(length) || length <= 0)
            throw UsageError("a closed band's length must be positive");
        period = length / std::max(1.0, std::round(length / period));
    }
    const FriezeGroup catalog = make_frieze_group(frieze.group, period);
    // The catalog's frieze runs along y = 0 from x = 0: moved onto the centre line.
    const double x0 = bounds.x0, cy = (bounds.y0 + bounds.y1) / 2;
    const Isometry to = translation(x0, cy), from = translation(-x0, -cy);
    std::vector<Isometry> cosets;
    for (const Isometry& h : catalog.transforms) cosets.push_back(from.then(h).then(to));

    TranslationSetup out;
    out.period = period;
    Rect box = bounds;
    if (wrap_x) {
        // Elements cross the band's ends, their translates finish them: a margin of a period
        // (and of the band's height, the largest circle) lets the field see them.
        box = widened(bounds, std::max(period, bounds.height()), 0);
        out.box = box_region(box, region.name());
        out.group.window = box;
    }
    // A mirror at x maps 0 to 2x: translations up to twice the box's length.
    const int reach = static_cast<int>(std::ceil(2 * box.width() / period)) + 2;
    out.group.name = "frieze " + catalog.name;
    out.group.transforms = reaching(cosets, Vector(period, 0), Vector(0, 0), reach, 0, box);
    out.group.cosets = cosets;
    out.group.a = Vector(period, 0);
    const double cells = std::floor(bounds.width() / period / 2);
    out.group.generic = {x0 + (cells + kGenericX) * period, cy + kGenericY * bounds.height()};
    out.group.frame = box;
    return out;
}

TranslationSetup wallpaper_setup(const Wallpaper& wallpaper) {
    Tile tile;
    tile.width = wallpaper.width;
    tile.height = wallpaper.height;
    tile.angle = wallpaper.angle_degrees;
    const WallpaperGroup catalog = make_wallpaper_group(wallpaper.group, tile);
    const Point a = tile.a(), b = tile.b();
    const Rect bounds{std::min({0.0, a.x, b.x, a.x + b.x}), std::min({0.0, a.y, b.y, a.y + b.y}),
                      std::max({0.0, a.x, b.x, a.x + b.x}), std::max({0.0, a.y, b.y, a.y + b.y})};
    // Elements may cross the tile's edges by half its larger side; the field over the tile sees
    // the translates within that margin, enough for the largest circle in the domain.
    const double margin = std::max(bounds.width(), bounds.height()) / 2;
    const Rect box = widened(bounds, margin, margin);
    TranslationSetup out;
    out.box = box_region(box, "tile " + tile.text());
    out.group.window = box;
    out.group.name = "wallpaper " + catalog.name;
    const Vector va(a.x, a.y), vb(b.x, b.y);
    // The translations moving the box onto itself in part: its size over the cell's heights.
    const double area = std::abs(va.cross(vb));
    const double diagonal = std::hypot(box.width(), box.height());
    const int reach_a = static_cast<int>(std::ceil(2 * diagonal / (area / vb.length()))) + 1;
    const int reach_b = static_cast<int>(std::ceil(2 * diagonal / (area / va.length()))) + 1;
    out.group.transforms = reaching(catalog.transforms, va, vb, reach_a, reach_b, box);
    out.group.cosets = catalog.transforms;
    out.group.a = va;
    out.group.b = vb;
    out.group.generic = Point{0, 0} + va * (0.5 + kGenericX) + vb * (0.5 + kGenericY);
    out.group.frame = box;
    return out;
}

Region tile_region(const Wallpaper& wallpaper) {
    Tile tile;
    tile.width = wallpaper.width;
    tile.height = wallpaper.height;
    tile.angle = wallpaper.angle_degrees;
    const Point a = tile.a(), b = tile.b();
    std::ostringstream svg;
    svg.precision(17);
    svg << "<svg xmlns='http://www.w3.org/2000/svg'><polygon points='0,0 " << a.x << ',' << a.y
        << ' ' << a.x + b.x << ',' << a.y + b.y << ' ' << b.x << ',' << b.y << "'/></svg>";
    return Region::from_svg_string(svg.str(), "tile " + tile.text());
}

}  // namespace acanthus::detail
