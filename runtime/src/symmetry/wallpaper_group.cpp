#include "symmetry/wallpaper_group.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

namespace acanthus::detail {

namespace {

enum class Lattice { oblique, rectangular, square, hexagonal };

// A symmetry operation in fractional coordinates: (x, y) -> (m00 x + m01 y + t0,
// m10 x + m11 y + t1), as listed in the International Tables.
struct Op {
    int m00, m01, m10, m11;
    double t0, t1;
};

struct GroupDef {
    const char* name;
    const char* full;
    Lattice lattice;
    bool centred;
    std::vector<Op> ops;
};

constexpr double h = 0.5;

const std::vector<GroupDef>& catalog() {
    // clang-format off
    static const std::vector<GroupDef> groups = {
        {"p1", "p1", Lattice::oblique, false, {{1, 0, 0, 1, 0, 0}}},
        {"p2", "p2", Lattice::oblique, false, {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}}},
        {"pm", "pm", Lattice::rectangular, false, {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, 1, 0, 0}}},
        {"pg", "pg", Lattice::rectangular, false, {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, 1, 0, h}}},
        {"cm", "cm", Lattice::rectangular, true, {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, 1, 0, 0}}},
        {"pmm", "p2mm", Lattice::rectangular, false,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {-1, 0, 0, 1, 0, 0}, {1, 0, 0, -1, 0, 0}}},
        {"pmg", "p2mg", Lattice::rectangular, false,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {-1, 0, 0, 1, h, 0}, {1, 0, 0, -1, h, 0}}},
        {"pgg", "p2gg", Lattice::rectangular, false,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {-1, 0, 0, 1, h, h}, {1, 0, 0, -1, h, h}}},
        {"cmm", "c2mm", Lattice::rectangular, true,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {-1, 0, 0, 1, 0, 0}, {1, 0, 0, -1, 0, 0}}},
        {"p4", "p4", Lattice::square, false,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {0, -1, 1, 0, 0, 0}, {0, 1, -1, 0, 0, 0}}},
        {"p4m", "p4mm", Lattice::square, false,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {0, -1, 1, 0, 0, 0}, {0, 1, -1, 0, 0, 0},
          {-1, 0, 0, 1, 0, 0}, {1, 0, 0, -1, 0, 0}, {0, 1, 1, 0, 0, 0}, {0, -1, -1, 0, 0, 0}}},
        {"p4g", "p4gm", Lattice::square, false,
         {{1, 0, 0, 1, 0, 0}, {-1, 0, 0, -1, 0, 0}, {0, -1, 1, 0, 0, 0}, {0, 1, -1, 0, 0, 0},
          {-1, 0, 0, 1, h, h}, {1, 0, 0, -1, h, h}, {0, 1, 1, 0, h, h}, {0, -1, -1, 0, h, h}}},
        {"p3", "p3", Lattice::hexagonal, false,
         {{1, 0, 0, 1, 0, 0}, {0, -1, 1, -1, 0, 0}, {-1, 1, -1, 0, 0, 0}}},
        {"p3m1", "p3m1", Lattice::hexagonal, false,
         {{1, 0, 0, 1, 0, 0}, {0, -1, 1, -1, 0, 0}, {-1, 1, -1, 0, 0, 0},
          {0, -1, -1, 0, 0, 0}, {-1, 1, 0, 1, 0, 0}, {1, 0, 1, -1, 0, 0}}},
        {"p31m", "p31m", Lattice::hexagonal, false,
         {{1, 0, 0, 1, 0, 0}, {0, -1, 1, -1, 0, 0}, {-1, 1, -1, 0, 0, 0},
          {0, 1, 1, 0, 0, 0}, {1, -1, 0, -1, 0, 0}, {-1, 0, -1, 1, 0, 0}}},
        {"p6", "p6", Lattice::hexagonal, false,
         {{1, 0, 0, 1, 0, 0}, {0, -1, 1, -1, 0, 0}, {-1, 1, -1, 0, 0, 0},
          {-1, 0, 0, -1, 0, 0}, {0, 1, -1, 1, 0, 0}, {1, -1, 1, 0, 0, 0}}},
        {"p6m", "p6mm", Lattice::hexagonal, false,
         {{1, 0, 0, 1, 0, 0}, {0, -1, 1, -1, 0, 0}, {-1, 1, -1, 0, 0, 0},
          {-1, 0, 0, -1, 0, 0}, {0, 1, -1, 1, 0, 0}, {1, -1, 1, 0, 0, 0},
          {0, -1, -1, 0, 0, 0}, {-1, 1, 0, 1, 0, 0}, {1, 0, 1, -1, 0, 0},
          {0, 1, 1, 0, 0, 0}, {1, -1, 0, -1, 0, 0}, {-1, 0, -1, 1, 0, 0}}},
    };
    // clang-format on
    return groups;
}

std::string lowered(std::string_view s) {
    std::string r;
    for (char c : s) r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
}

bool close(double x, double y) {
    return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y));
}

// An empty string when `tile` is a lattice of the kind, else what the kind needs.
std::string lattice_problem(Lattice kind, const Tile& tile) {
    const bool right = std::abs(tile.angle - 90) < 1e-9;
    const bool equal = close(tile.width, tile.height);
    switch (kind) {
        case Lattice::oblique:
            return {};
        case Lattice::rectangular:
            return right ? "" : "a rectangular lattice: --tile W,H or W,H,90";
        case Lattice::square:
            return right && equal ? "" : "a square lattice: --tile W,W or W,W,90";
        case Lattice::hexagonal:
            return equal && (std::abs(tile.angle - 60) < 1e-9 || std::abs(tile.angle - 120) < 1e-9)
                       ? ""
                       : "a hexagonal lattice: --tile W,W,60 or W,W,120";
    }
    return {};
}

Point scaled(Point p, double s) { return {p.x * s, p.y * s}; }

// Fractional coordinates (u, v) of p in the basis a, b.
Point fractional(Point p, Point a, Point b) {
    const double det = a.x * b.y - a.y * b.x;
    return {(p.x * b.y - p.y * b.x) / det, (a.x * p.y - a.y * p.x) / det};
}

double wrapped(double u) {
    u -= std::floor(u);
    if (u < 1e-9 || u > 1 - 1e-9) u = 0;
    return u;
}

// The Cartesian isometry of `op` given in fractional coordinates of the basis a, b:
// L = B M B^-1, t = B t_f, with B the matrix of columns a and b.
Isometry cartesian(const Op& op, Point a, Point b) {
    auto image = [&](Point f) {  // B M f
        const double u = op.m00 * f.x + op.m01 * f.y, v = op.m10 * f.x + op.m11 * f.y;
        return Point{u * a.x + v * b.x, u * a.y + v * b.y};
    };
    const Point ex = image(fractional({1, 0}, a, b)), ey = image(fractional({0, 1}, a, b));
    return {ex.x, ex.y, ey.x, ey.y, op.t0 * a.x + op.t1 * b.x, op.t0 * a.y + op.t1 * b.y};
}

}  // namespace

Point Tile::a() const { return {width, 0}; }

Point Tile::b() const {
    const double t = angle * std::numbers::pi / 180;
    // Exact at the usual angles, so that a square tile's b is (0, H).
    if (std::abs(angle - 90) < 1e-12) return {0, height};
    return {height * std::cos(t), height * std::sin(t)};
}

std::string Tile::text() const {
    std::ostringstream s;
    s << width << ',' << height;
    if (angle != 90) s << ',' << angle;
    return s.str();
}

Tile parse_tile(std::string_view text) {
    const std::string usage =
        "--tile expects W,H or W,H,ANGLE (sides and the angle between them in degrees), not '" +
        std::string(text) + "'";
    std::vector<double> v;
    std::string part;
    std::istringstream in{std::string(text)};
    while (std::getline(in, part, ',')) {
        const char* begin = part.c_str();
        char* end = nullptr;
        const double x = std::strtod(begin, &end);
        if (part.empty() || end == begin || *end != '\0' || !std::isfinite(x))
            throw UsageError(usage);
        v.push_back(x);
    }
    if (!text.empty() && text.back() == ',') throw UsageError(usage);
    if (v.size() < 2 || v.size() > 3) throw UsageError(usage);
    Tile tile{v[0], v[1], v.size() == 3 ? v[2] : 90.0};
    if (!(tile.width > 0) || !(tile.height > 0))
        throw UsageError("--tile: the sides must be positive, not '" + std::string(text) + "'");
    if (!(tile.angle > 0 && tile.angle < 180))
        throw UsageError("--tile: the angle must lie strictly between 0 and 180 degrees, not '" +
                         std::string(text) + "'");
    return tile;
}

const std::vector<std::string>& wallpaper_group_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const auto& g : catalog()) v.emplace_back(g.name);
        return v;
    }();
    return names;
}

Isometry modulo_lattice(const Isometry& t, Point a, Point b) {
    const Point f = fractional({t.e, t.f}, a, b);
    const double u = wrapped(f.x), v = wrapped(f.y);
    Isometry r = t;
    r.e = u * a.x + v * b.x;
    r.f = u * a.y + v * b.y;
    return r;
}

WallpaperGroup make_wallpaper_group(std::string_view name, const Tile& tile) {
    const std::string key = lowered(name);
    const auto& groups = catalog();
    const auto found = std::find_if(groups.begin(), groups.end(), [&](const GroupDef& g) {
        return key == g.name || key == g.full;
    });
    if (found == groups.end()) {
        std::string list;
        for (const auto& n : wallpaper_group_names()) list += (list.empty() ? "" : " ") + n;
        throw UsageError("--wallpaper: unknown wallpaper group '" + std::string(name) +
                         "' (one of: " + list + ")");
    }
    const GroupDef& def = *found;
    if (const std::string need = lattice_problem(def.lattice, tile); !need.empty())
        throw UsageError("--wallpaper " + std::string(def.name) + " needs " + need +
                         ", not --tile " + tile.text());

    const Point a = tile.a(), b = tile.b();
    // The tables' hexagonal setting has 120 degrees between a and b; a 60 degree tile spans
    // the same lattice with b - a in place of b.
    const Point b_setting =
        def.lattice == Lattice::hexagonal && tile.angle < 90 ? Point{b.x - a.x, b.y - a.y} : b;

    WallpaperGroup g{def.name, tile, {}, def.centred ? 2 : 1};
    for (const Op& op : def.ops) g.transforms.push_back(cartesian(op, a, b_setting));
    if (def.centred) {
        const std::size_t n = g.transforms.size();
        const Point centring = scaled({a.x + b.x, a.y + b.y}, 0.5);
        for (std::size_t k = 0; k < n; ++k) {
            Isometry t = g.transforms[k];
            t.e += centring.x;
            t.f += centring.y;
            g.transforms.push_back(t);
        }
    }
    for (auto& t : g.transforms) t = modulo_lattice(t, a, b);
    return g;
}

}  // namespace acanthus::detail
