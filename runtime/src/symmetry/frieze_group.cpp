#include "symmetry/frieze_group.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>

namespace acanthus::detail {

namespace {

struct FriezeName {
    const char* iuc;
    const char* conway;
};

// The seven, with Conway's names (Conway, Burgiel, Goodman-Strauss, The Symmetries of Things).
constexpr FriezeName kNames[] = {
    {"p1", "hop"},          {"p11g", "step"},           {"p1m1", "sidle"},         {"p11m", "jump"},
    {"p2", "spinning-hop"}, {"p2mg", "spinning-sidle"}, {"p2mm", "spinning-jump"},
};

std::string normalized(std::string_view name) {
    std::string s;
    for (char c : name) {
        if (c == ' ' || c == '_') c = '-';
        s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return s;
}

Isometry translation(double x) { return {1, 0, 0, 1, x, 0}; }
Isometry mirror_x() { return {-1, 0, 0, 1, 0, 0}; }  // in the vertical line x = 0
Isometry mirror_y() { return {1, 0, 0, -1, 0, 0}; }  // in the axis y = 0
Isometry half_turn() { return {-1, 0, 0, -1, 0, 0}; }

}  // namespace

const std::vector<std::string>& frieze_group_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const auto& n : kNames) v.emplace_back(n.iuc);
        return v;
    }();
    return names;
}

Isometry modulo_period(const Isometry& t, double period) {
    Isometry r = t;
    r.e = std::fmod(r.e, period);
    if (r.e < 0) r.e += period;
    if (r.e < 1e-9 * period || r.e > period * (1 - 1e-9)) r.e = 0;
    return r;
}

FriezeGroup make_frieze_group(std::string_view name, double period) {
    const std::string key = normalized(name);
    const auto* found =
        std::find_if(std::begin(kNames), std::end(kNames),
                     [&](const FriezeName& n) { return key == n.iuc || key == n.conway; });
    if (found == std::end(kNames)) {
        std::string list;
        for (const auto& n : frieze_group_names()) list += (list.empty() ? "" : " ") + n;
        throw UsageError("--frieze: unknown frieze group '" + std::string(name) +
                         "' (one of: " + list + ")");
    }
    if (!(period > 0) || !std::isfinite(period))
        throw UsageError("--period: the period must be a positive number");

    FriezeGroup g{found->iuc, period, {Isometry{}}};
    const std::string iuc = found->iuc;
    const Isometry glide = mirror_y().then(translation(period / 2));
    if (iuc == "p11g") g.transforms.push_back(glide);
    if (iuc == "p1m1") g.transforms.push_back(mirror_x());
    if (iuc == "p11m") g.transforms.push_back(mirror_y());
    if (iuc == "p2") g.transforms.push_back(half_turn());
    if (iuc == "p2mg") {
        // Mirrors at x = 0 and x = P/2, glides along the axis, half-turns at x = P/4 and 3P/4.
        g.transforms.push_back(mirror_x());
        g.transforms.push_back(glide);
        g.transforms.push_back(mirror_x().then(glide));
    }
    if (iuc == "p2mm") {
        g.transforms.push_back(mirror_x());
        g.transforms.push_back(mirror_y());
        g.transforms.push_back(half_turn());
    }
    for (auto& t : g.transforms) t = modulo_period(t, period);
    return g;
}

}  // namespace acanthus::detail
