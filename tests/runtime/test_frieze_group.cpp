// The frieze catalog (docs/symmetry.md): each of the seven groups is a set of isometries of the
// band closed under composition modulo the period, of the right order, with the mirrors, glides
// and half-turns the group has and no others.
#include <gtest/gtest.h>

#include <acanthus/error.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "symmetry/frieze_group.hpp"

using namespace acanthus;
using namespace acanthus::detail;

namespace {

bool same(const Isometry& x, const Isometry& y) {
    const auto p = x.matrix(), q = y.matrix();
    for (int k = 0; k < 6; ++k)
        if (std::abs(p[k] - q[k]) > 1e-9) return false;
    return true;
}

bool contains(const std::vector<Isometry>& set, const Isometry& t) {
    for (const auto& s : set)
        if (same(s, t)) return true;
    return false;
}

struct Kinds {
    int translations = 0, half_turns = 0, vertical_mirrors = 0, axis_mirrors = 0, glides = 0;
};

// What each element of one period is, read from its matrix: the band's symmetries keep the axis
// y = 0, so the linear part is diagonal with entries +-1.
Kinds kinds_of(const FriezeGroup& g) {
    Kinds k;
    for (const auto& t : g.transforms) {
        EXPECT_NEAR(t.b, 0, 1e-12);
        EXPECT_NEAR(t.c, 0, 1e-12);
        EXPECT_NEAR(t.f, 0, 1e-12);  // the axis maps onto itself
        const bool flip_x = t.a < 0, flip_y = t.d < 0;
        if (!flip_x && !flip_y) ++k.translations;
        if (flip_x && flip_y) ++k.half_turns;
        if (flip_x && !flip_y) ++k.vertical_mirrors;
        if (!flip_x && flip_y) (std::abs(t.e) < 1e-9 ? k.axis_mirrors : k.glides) += 1;
    }
    return k;
}

}  // namespace

TEST(FriezeGroup, EveryGroupIsClosedModuloThePeriodWithTheRightOrder) {
    const std::vector<std::pair<std::string, std::size_t>> orders = {
        {"p1", 1}, {"p11g", 2}, {"p1m1", 2}, {"p11m", 2}, {"p2", 2}, {"p2mg", 4}, {"p2mm", 4}};
    ASSERT_EQ(frieze_group_names().size(), orders.size());
    for (double period : {1.0, 37.5, 200.0}) {
        for (const auto& [name, order] : orders) {
            SCOPED_TRACE(name + " period " + std::to_string(period));
            const FriezeGroup g = make_frieze_group(name, period);
            EXPECT_EQ(g.name, name);
            ASSERT_EQ(g.size(), order);
            EXPECT_TRUE(same(g.transforms.front(), Isometry{}));  // identity first
            for (const auto& x : g.transforms) {
                EXPECT_GE(x.e, 0);
                EXPECT_LT(x.e, period);
                EXPECT_TRUE(contains(g.transforms, modulo_period(x.inverse(), period)));
                for (const auto& y : g.transforms)
                    EXPECT_TRUE(contains(g.transforms, modulo_period(x.then(y), period)));
            }
            // Distinct cosets: no two differ by a translation only.
            for (std::size_t i = 0; i < g.size(); ++i)
                for (std::size_t j = i + 1; j < g.size(); ++j)
                    EXPECT_FALSE(same(g.transforms[i], g.transforms[j]));
        }
    }
}

TEST(FriezeGroup, MirrorsGlidesAndHalfTurnsWhereTheGroupHasThem) {
    auto check = [](const char* name, int half, int vert, int axis, int glide) {
        SCOPED_TRACE(name);
        const Kinds k = kinds_of(make_frieze_group(name, 10));
        EXPECT_EQ(k.translations, 1);  // the identity only, modulo the period
        EXPECT_EQ(k.half_turns, half);
        EXPECT_EQ(k.vertical_mirrors, vert);
        EXPECT_EQ(k.axis_mirrors, axis);
        EXPECT_EQ(k.glides, glide);
    };
    check("p1", 0, 0, 0, 0);
    check("p11g", 0, 0, 0, 1);
    check("p1m1", 0, 1, 0, 0);
    check("p11m", 0, 0, 1, 0);
    check("p2", 1, 0, 0, 0);
    check("p2mg", 1, 1, 0, 1);
    check("p2mm", 1, 1, 1, 0);
}

TEST(FriezeGroup, TheGlideMovesHalfAPeriodAndP2mgTurnsBetweenItsMirrors) {
    const FriezeGroup step = make_frieze_group("p11g", 8);
    const Point p = step.transforms[1].apply({1, 2});
    EXPECT_NEAR(p.x, 5, 1e-12);
    EXPECT_NEAR(p.y, -2, 1e-12);
    // p2mg: mirrors at x = 0 (and P/2), half-turn centres a quarter period from them.
    const FriezeGroup g = make_frieze_group("p2mg", 8);
    for (const auto& t : g.transforms)
        if (t.a < 0 && t.d < 0) {
            const Point c = t.apply({2, 0});
            EXPECT_NEAR(c.x, 2, 1e-12);  // (P/4, 0) is fixed
            EXPECT_NEAR(c.y, 0, 1e-12);
        }
}

TEST(FriezeGroup, ConwayNamesAndCaseAreAccepted) {
    EXPECT_EQ(make_frieze_group("P2MM", 5).name, "p2mm");
    EXPECT_EQ(make_frieze_group("hop", 5).name, "p1");
    EXPECT_EQ(make_frieze_group("step", 5).name, "p11g");
    EXPECT_EQ(make_frieze_group("sidle", 5).name, "p1m1");
    EXPECT_EQ(make_frieze_group("jump", 5).name, "p11m");
    EXPECT_EQ(make_frieze_group("spinning hop", 5).name, "p2");
    EXPECT_EQ(make_frieze_group("spinning_sidle", 5).name, "p2mg");
    EXPECT_EQ(make_frieze_group("Spinning-Jump", 5).name, "p2mm");
}

TEST(FriezeGroup, UnknownNamesAndBadPeriodsAreUsageErrors) {
    for (const char* bad : {"", "p3", "p4m", "pmm", "d8", "p1m", "p2mm2", "hopp"}) {
        try {
            make_frieze_group(bad, 10);
            ADD_FAILURE() << bad;
        } catch (const UsageError& e) {
            EXPECT_NE(std::string(e.what()).find("p1 p11g p1m1 p11m p2 p2mg p2mm"),
                      std::string::npos)
                << e.what();
        }
    }
    for (double bad : {0.0, -3.0, std::nan(""), static_cast<double>(INFINITY)})
        EXPECT_THROW(make_frieze_group("p2", bad), UsageError) << bad;
}
