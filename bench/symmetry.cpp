// Growth under a symmetry group against growth without: Appendix A's dots filling a disc of
// radius 500 at 1024 px, without symmetry and under c6, d8 and d12, each grown --runs times (3 by
// default, in turns), the run of median time reported. Friezes (frieze:G, on a band 2000 x 250
// with period 250) and wallpaper groups (wallpaper:G, on a tile 500 x 500, 500,500,60 for the
// hexagonal ones) are measured against growth without symmetry on the same band or tile. Prints a
// table on stderr and, last, one JSON object: per group the elements (images included), the
// fundamental ones, the seconds of the engine's construction and growth, a hash of the tree, the
// cost per fundamental element and per placed element, and both as a ratio to the cost per
// element without symmetry (the issue asks 1.5 per fundamental element).
//
//   bench_symmetry [--runs N] [--resolution PX] [--disc R] [--groups none,c6,frieze:p2mg,...]
//
// --groups picks the groups (default none,c6,d8,d12); without "none" (to profile one group alone)
// the ratios are left out. none:band, none:tile and none:tile60 grow without symmetry on that
// panel alone (to profile it). --disc R grows in a disc of radius R (500 by default) on the same
// grid: two radii give a group's cost as a part per run and a part per element.
#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "fixtures/dots_pattern.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/translation_groups.hpp"

namespace {

struct Result {
    std::string group;
    std::string panel;  // disc, band, tile, tile60
    long elements = 0, fundamental = 0;
    std::vector<double> seconds;
    std::uint64_t tree_hash = 0;  // of the last run's tree: ids, parents, proxy bounds
};

bool hexagonal(const std::string& name) {
    return name.find('3') != std::string::npos || name.find('6') != std::string::npos;
}

void grow(Result& r, int resolution, double disc) {
    acanthus::GrowthOptions o;
    o.resolution = resolution;
    const std::string name = r.group.substr(r.group.find(':') + 1);
    acanthus::Wallpaper tile{"p1", 500, 500, r.panel == "tile60" ? 60.0 : 90.0};
    if (r.group.rfind("frieze:", 0) == 0) {
        o.frieze = acanthus::Frieze{name, 250};
    } else if (r.group.rfind("wallpaper:", 0) == 0) {
        tile.group = name;
        o.wallpaper = tile;
    } else if (r.group != "none") {
        o.symmetry = acanthus::Symmetry::parse(r.group);
    }
    const acanthus::Region region =
        r.panel == "band"   ? acanthus::Region::from_spec("rect:2000,250")
        : r.panel == "disc" ? acanthus::Region::from_spec("circle:" + std::to_string(disc))
                            : acanthus::detail::tile_region(tile);
    dots::dot_count = 0;
    const acanthus::Pattern pattern = dots::pattern();
    // The engine's construction counts: under a group it finds the fundamental domain's pixels
    // and whether the group maps the region onto itself, which the user waits for too.
    const auto start = std::chrono::steady_clock::now();
    acanthus::GrowthEngine engine(pattern, region, o);
    engine.run();
    r.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    const auto elements = engine.elements();
    r.elements = static_cast<long>(elements.size());
    r.fundamental = 0;
    for (const acanthus::Element* e : elements)
        if (!acanthus::detail::as_image(*e)) ++r.fundamental;
    // FNV-1a over each element's id, parent and the bits of its proxies' bounds: the same
    // growth gives the same hash (a change that should not alter the trees is checked so).
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](std::uint64_t v) {
        for (int k = 0; k < 8; ++k) h = (h ^ ((v >> (8 * k)) & 0xff)) * 1099511628211ull;
    };
    for (const acanthus::Element* e : elements) {
        mix(static_cast<std::uint64_t>(e->id));
        mix(static_cast<std::uint64_t>(e->parent ? e->parent->id : -1));
        for (std::size_t k = 0; k < e->proxy_count(); ++k) {
            const acanthus::Rect b = e->proxy(k).bounds();
            for (double v : {b.x0, b.y0, b.x1, b.y1}) {
                std::uint64_t bits;
                std::memcpy(&bits, &v, sizeof bits);
                mix(bits);
            }
        }
    }
    r.tree_hash = h;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

std::string json_number(double v) {
    if (std::isnan(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 3, resolution = 1024;
    double disc = 500;
    std::string groups = "none,c6,d8,d12";
    for (int k = 1; k + 1 < argc; k += 2) {
        if (!std::strcmp(argv[k], "--runs")) runs = std::max(1, std::atoi(argv[k + 1]));
        if (!std::strcmp(argv[k], "--resolution")) resolution = std::atoi(argv[k + 1]);
        if (!std::strcmp(argv[k], "--groups")) groups = argv[k + 1];
        if (!std::strcmp(argv[k], "--disc")) disc = std::atof(argv[k + 1]);
    }
    std::vector<Result> results;
    for (std::size_t at = 0; at <= groups.size();) {
        const std::size_t comma = std::min(groups.find(',', at), groups.size());
        const std::string g = groups.substr(at, comma - at);
        const std::string panel = g.rfind("frieze:", 0) == 0 ? "band"
                                  : g.rfind("wallpaper:", 0) == 0
                                      ? (hexagonal(g.substr(10)) ? "tile60" : "tile")
                                      : "disc";
        if (g == "none")
            results.insert(results.begin(), {g, "disc", 0, 0, {}});
        else if (g.rfind("none:", 0) == 0)  // none:band, none:tile, none:tile60 (to profile)
            results.push_back({"none", g.substr(5), 0, 0, {}});
        else if (!g.empty())
            results.push_back({g, panel, 0, 0, {}});
        at = comma + 1;
    }
    // Growth without symmetry on each band or tile measured.
    if (!results.empty() && results[0].group == "none" && results[0].panel == "disc")
        for (const char* panel : {"band", "tile", "tile60"}) {
            bool used = false;
            for (const Result& r : results) used = used || r.panel == panel;
            if (used) results.push_back({"none", panel, 0, 0, {}});
        }
    for (int run = 0; run < runs; ++run)
        for (Result& r : results) grow(r, resolution, disc);
    if (results.empty()) return 2;
    // Without the baseline the ratios are NaN (printed as nan, null in the JSON).
    auto base_of = [&](const std::string& panel) {
        for (const Result& r : results)
            if (r.group == "none" && r.panel == panel)
                return median(r.seconds) / static_cast<double>(r.elements);
        return std::nan("");
    };
    std::fprintf(stderr, "%-16s %-6s %9s %11s %9s %14s %9s %14s %9s\n", "group", "panel",
                 "elements", "fundamental", "seconds", "us/fundamental", "ratio", "us/element",
                 "ratio");
    std::string json = "{\"resolution\":" + std::to_string(resolution) + ",\"groups\":[";
    for (std::size_t k = 0; k < results.size(); ++k) {
        const Result& r = results[k];
        const double base = base_of(r.panel);
        const double s = median(r.seconds);
        const double per_fundamental = s / static_cast<double>(r.fundamental);
        const double per_element = s / static_cast<double>(r.elements);
        std::fprintf(stderr, "%-16s %-6s %9ld %11ld %9.3f %14.1f %9.2f %14.1f %9.2f\n",
                     r.group.c_str(), r.panel.c_str(), r.elements, r.fundamental, s,
                     1e6 * per_fundamental, per_fundamental / base, 1e6 * per_element,
                     per_element / base);
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s{\"group\":\"%s\",\"panel\":\"%s\",\"elements\":%ld,\"fundamental\":%ld,"
                      "\"seconds\":%.4f,\"tree_hash\":\"%016llx\","
                      "\"per_fundamental_ratio\":%s,\"per_element_ratio\":%s}",
                      k ? "," : "", r.group.c_str(), r.panel.c_str(), r.elements, r.fundamental, s,
                      static_cast<unsigned long long>(r.tree_hash),
                      json_number(per_fundamental / base).c_str(),
                      json_number(per_element / base).c_str());
        json += line;
    }
    std::printf("%s]}\n", json.c_str());
    return 0;
}
