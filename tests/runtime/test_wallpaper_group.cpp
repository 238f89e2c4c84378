// The wallpaper catalog (docs/symmetry.md): each of the 17 groups is a set of isometries closed
// under composition modulo the tile's translations, of the right order per primitive cell, with
// the rotations and mirrors that tell the groups apart; tiles are parsed, and every lattice a
// group cannot live on is refused naming the lattice it needs.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "symmetry/wallpaper_group.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

bool same(const Isometry& x, const Isometry& y, double scale) {
    const auto p = x.matrix(), q = y.matrix();
    for (int k = 0; k < 4; ++k)
        if (std::abs(p[k] - q[k]) > 1e-9) return false;
    return std::abs(p[4] - q[4]) <= 1e-9 * scale && std::abs(p[5] - q[5]) <= 1e-9 * scale;
}

bool contains(const WallpaperGroup& g, const Isometry& t) {
    const double scale = g.tile.width + g.tile.height;
    for (const auto& s : g.transforms)
        if (same(s, t, scale)) return true;
    return false;
}

// A lattice on which the group lives.
Tile tile_for(const std::string& name) {
    for (const char* hex : {"p3", "p3m1", "p31m", "p6", "p6m"})
        if (name == hex) return {90, 90, 120};
    for (const char* sq : {"p4", "p4m", "p4g"})
        if (name == sq) return {80, 80, 90};
    if (name == "p1" || name == "p2") return {70, 50, 75};
    return {100, 60, 90};
}

// Rotation order of a linear part (1 for the identity and for reflections).
int rotation_order(const Isometry& t) {
    if (t.reverses()) return 1;
    const double angle = std::abs(std::atan2(t.b, t.a));
    if (angle < 1e-9) return 1;
    return static_cast<int>(std::lround(2 * std::numbers::pi / angle));
}

// True when some element of t's coset (t followed by a lattice translation) is a mirror: a
// reflection with fixed points, i.e. an involution.
bool coset_has_mirror(const Isometry& t, Point a, Point b) {
    if (!t.reverses()) return false;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j) {
            Isometry s = t;
            s.e += i * a.x + j * b.x;
            s.f += i * a.y + j * b.y;
            const Isometry twice = s.then(s);
            if (std::hypot(twice.e, twice.f) < 1e-9 * (std::hypot(a.x, a.y) + std::hypot(b.x, b.y)))
                return true;
        }
    return false;
}

}  // namespace

TEST(WallpaperTile, ParsesSidesAndAngle) {
    const Tile t = parse_tile("100,80");
    EXPECT_EQ(t.width, 100);
    EXPECT_EQ(t.height, 80);
    EXPECT_EQ(t.angle, 90);
    EXPECT_EQ(t.b().x, 0);
    EXPECT_EQ(t.b().y, 80);
    const Tile h = parse_tile("50,50,60");
    EXPECT_NEAR(h.b().x, 25, 1e-12);
    EXPECT_NEAR(h.b().y, 50 * std::sqrt(3) / 2, 1e-12);
    EXPECT_EQ(h.text(), "50,50,60");
    for (const char* bad :
         {"", "100", "100,", ",100", "100,80,", "a,b", "100,80,90,1", "0,80", "-5,80", "100,80,0",
          "100,80,180", "100,80,200", "inf,80", "100 80", "100,80x"})
        EXPECT_THROW(parse_tile(bad), UsageError) << bad;
}

TEST(WallpaperGroup, EveryGroupIsClosedModuloTheLatticeWithTheRightOrder) {
    const std::map<std::string, std::size_t> orders = {
        {"p1", 1},  {"p2", 2},   {"pm", 2},   {"pg", 2}, {"cm", 2},  {"pmm", 4},
        {"pmg", 4}, {"pgg", 4},  {"cmm", 4},  {"p4", 4}, {"p4m", 8}, {"p4g", 8},
        {"p3", 3},  {"p3m1", 6}, {"p31m", 6}, {"p6", 6}, {"p6m", 12}};
    ASSERT_EQ(wallpaper_group_names().size(), 17u);
    for (const auto& name : wallpaper_group_names()) {
        std::vector<Tile> tiles = {tile_for(name)};
        if (tile_for(name).angle == 120) tiles.push_back({90, 90, 60});
        for (const Tile& tile : tiles) {
            SCOPED_TRACE(name + " on " + tile.text());
            const WallpaperGroup g = make_wallpaper_group(name, tile);
            EXPECT_EQ(g.name, name);
            EXPECT_EQ(g.order(), orders.at(name));
            EXPECT_EQ(g.cells, name == "cm" || name == "cmm" ? 2 : 1);
            EXPECT_TRUE(same(g.transforms.front(), Isometry{}, 1));
            const Point a = tile.a(), b = tile.b();
            for (const auto& x : g.transforms) {
                // An isometry: orthonormal linear part.
                EXPECT_NEAR(x.a * x.a + x.b * x.b, 1, 1e-9);
                EXPECT_NEAR(x.c * x.c + x.d * x.d, 1, 1e-9);
                EXPECT_NEAR(x.a * x.c + x.b * x.d, 0, 1e-9);
                // It maps the lattice onto itself.
                for (const Point v : {a, b}) {
                    const Isometry lin{x.a, x.b, x.c, x.d, 0, 0};
                    const Point w = lin.apply(v);
                    EXPECT_TRUE(contains(
                        g, modulo_lattice({x.a, x.b, x.c, x.d, x.e + w.x, x.f + w.y}, a, b)));
                }
                EXPECT_TRUE(contains(g, modulo_lattice(x.inverse(), a, b)));
                for (const auto& y : g.transforms)
                    EXPECT_TRUE(contains(g, modulo_lattice(x.then(y), a, b)));
            }
            for (std::size_t i = 0; i < g.size(); ++i)
                for (std::size_t j = i + 1; j < g.size(); ++j)
                    EXPECT_FALSE(same(g.transforms[i], g.transforms[j], tile.width));
        }
    }
}

TEST(WallpaperGroup, RotationsAndMirrorsTellTheGroupsApart) {
    struct Expect {
        int rotation;  // the largest rotation order
        bool reflections, mirrors;
    };
    const std::map<std::string, Expect> expected = {
        {"p1", {1, false, false}}, {"p2", {2, false, false}}, {"pm", {1, true, true}},
        {"pg", {1, true, false}},  {"cm", {1, true, true}},   {"pmm", {2, true, true}},
        {"pmg", {2, true, true}},  {"pgg", {2, true, false}}, {"cmm", {2, true, true}},
        {"p4", {4, false, false}}, {"p4m", {4, true, true}},  {"p4g", {4, true, true}},
        {"p3", {3, false, false}}, {"p3m1", {3, true, true}}, {"p31m", {3, true, true}},
        {"p6", {6, false, false}}, {"p6m", {6, true, true}}};
    for (const auto& name : wallpaper_group_names()) {
        SCOPED_TRACE(name);
        const Tile tile = tile_for(name);
        const WallpaperGroup g = make_wallpaper_group(name, tile);
        int rotation = 1;
        bool reflections = false, mirrors = false;
        for (const auto& t : g.transforms) {
            rotation = std::max(rotation, rotation_order(t));
            reflections = reflections || t.reverses();
            mirrors = mirrors || coset_has_mirror(t, tile.a(), tile.b());
        }
        EXPECT_EQ(rotation, expected.at(name).rotation);
        EXPECT_EQ(reflections, expected.at(name).reflections);
        EXPECT_EQ(mirrors, expected.at(name).mirrors);
    }
    // cm and cmm, unlike pm and pmm, have glides besides their mirrors: the centring translation.
    EXPECT_EQ(make_wallpaper_group("cm", {100, 60, 90}).size(), 4u);
    // p4m has mirrors through its 4-fold centres, p4g has none there.
    auto mirror_through_origin = [](const WallpaperGroup& g) {
        for (const auto& t : g.transforms)
            if (t.reverses() && std::hypot(t.e, t.f) < 1e-9) return true;
        return false;
    };
    EXPECT_TRUE(mirror_through_origin(make_wallpaper_group("p4m", {80, 80, 90})));
    EXPECT_FALSE(mirror_through_origin(make_wallpaper_group("p4g", {80, 80, 90})));
    // p3m1 has a mirror through every 3-fold centre; p31m none through (1/3, 2/3).
    for (const char* name : {"p3m1", "p31m"}) {
        const Tile tile{90, 90, 120};
        const Point a = tile.a(), b = tile.b();
        const Point centre{(a.x + 2 * b.x) / 3, (a.y + 2 * b.y) / 3};
        bool mirrored = false;
        for (const auto& t : make_wallpaper_group(name, tile).transforms)
            if (t.reverses())
                for (int i = -2; i <= 2; ++i)
                    for (int j = -2; j <= 2; ++j) {
                        const Point q = t.apply(centre);
                        mirrored =
                            mirrored || std::hypot(q.x + i * a.x + j * b.x - centre.x,
                                                   q.y + i * a.y + j * b.y - centre.y) < 1e-9;
                    }
        EXPECT_EQ(mirrored, std::string(name) == "p3m1") << name;
    }
}

TEST(WallpaperGroup, EveryNameIsAcceptedInBothSpellings) {
    const std::map<std::string, std::string> full = {
        {"pmm", "p2mm"}, {"pmg", "p2mg"}, {"pgg", "p2gg"}, {"cmm", "c2mm"},
        {"p4m", "p4mm"}, {"p4g", "p4gm"}, {"p6m", "p6mm"}};
    for (const auto& name : wallpaper_group_names()) {
        EXPECT_EQ(make_wallpaper_group(name, tile_for(name)).name, name);
        std::string upper = name;
        for (char& c : upper) c = static_cast<char>(std::toupper(c));
        EXPECT_EQ(make_wallpaper_group(upper, tile_for(name)).name, name);
    }
    for (const auto& [name, long_name] : full)
        EXPECT_EQ(make_wallpaper_group(long_name, tile_for(name)).name, name);
    try {
        make_wallpaper_group("p5", {100, 100, 90});
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("p1 p2 pm pg cm pmm pmg pgg cmm p4 p4m p4g p3 p3m1 "
                                             "p31m p6 p6m"),
                  std::string::npos)
            << e.what();
    }
}

TEST(WallpaperGroup, EveryImpossibleLatticeIsRefusedNamingTheLatticeNeeded) {
    const std::vector<Tile> tiles = {{100, 60, 90}, {100, 60, 75}, {80, 80, 90},  {80, 80, 60},
                                     {80, 80, 120}, {80, 80, 75},  {100, 60, 60}, {100, 60, 120}};
    auto kind = [](const std::string& name) -> std::string {
        for (const char* hex : {"p3", "p3m1", "p31m", "p6", "p6m"})
            if (name == hex) return "hexagonal";
        for (const char* sq : {"p4", "p4m", "p4g"})
            if (name == sq) return "square";
        if (name == "p1" || name == "p2") return "oblique";
        return "rectangular";
    };
    auto fits = [](const std::string& k, const Tile& t) {
        const bool equal = t.width == t.height;
        if (k == "oblique") return true;
        if (k == "rectangular") return t.angle == 90;
        if (k == "square") return equal && t.angle == 90;
        return equal && (t.angle == 60 || t.angle == 120);
    };
    int refused = 0;
    for (const auto& name : wallpaper_group_names())
        for (const Tile& tile : tiles) {
            SCOPED_TRACE(name + " on " + tile.text());
            const std::string k = kind(name);
            if (fits(k, tile)) {
                EXPECT_NO_THROW(make_wallpaper_group(name, tile));
                continue;
            }
            ++refused;
            try {
                make_wallpaper_group(name, tile);
                ADD_FAILURE();
            } catch (const UsageError& e) {
                EXPECT_NE(std::string(e.what()).find("needs a " + k + " lattice"),
                          std::string::npos)
                    << e.what();
                EXPECT_NE(std::string(e.what()).find(tile.text()), std::string::npos) << e.what();
            }
        }
    EXPECT_GT(refused, 80);
}
