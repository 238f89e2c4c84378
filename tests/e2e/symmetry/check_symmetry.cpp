// Checks an ornament grown under a symmetry group from the outside, as the expert would, on the
// program's --json tree:
//   check_symmetry TREE.json GROUP REGION
// GROUP is a rosette (cN, dN), frieze:G:P (a frieze G of period P about the centre line of the
// region's bounds) or wallpaper:G:W,H[,ANGLE] (REGION is then the tile, '-').
// - the images' transformations, with the identity, are the group: for a rosette as many as it
//   has (N for cN, 2N for dN) and closed under composition; with translations, each is one of
//   the catalog's isometries followed by a translation of the period or the lattice;
// - the element set is invariant: every image of every element under every transformation is an
//   element of the same type (to 1e-6 of the panel's size); with translations, every image that
//   lies wholly inside the region (a frieze) or inside the tile's bounds (a wallpaper);
// - nothing leaves the region (a wallpaper's elements cross the tile's edges: not checked);
// - no two elements overlap unless they are an image of two fundamental elements under one
//   transformation (two fundamental elements touching or overlapping is the rule's business, as
//   without symmetry; the seed markers are left out).
// Exit 0 when all hold, 1 with the faults listed.
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/spatial_index.hpp"
#include "proxy/overlap.hpp"
#include "symmetry/frieze_group.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/isometry.hpp"
#include "symmetry/orbit.hpp"
#include "symmetry/wallpaper_group.hpp"
#include "tree_proxy.hpp"

using namespace acanthus;
using namespace acanthus::detail;
using Json = nlohmann::json;
using tree_json::load_proxy;

namespace {

// An element as the tree gives it: its type name and its proxies.
struct Loaded final : Element {
    std::string type_name;
    ElementType type_info;
    std::vector<std::unique_ptr<Proxy, void (*)(Proxy*)>> proxies;
    int image_of = -1;
    Isometry transform;
    const ElementType& type() const override { return type_info; }
    std::size_t proxy_count() const override { return proxies.size(); }
    Proxy& proxy(std::size_t k) override { return *proxies[k]; }
};

bool same(const Isometry& a, const Isometry& b) {
    const auto x = a.matrix(), y = b.matrix();
    for (int k = 0; k < 6; ++k)
        if (std::abs(x[k] - y[k]) > 1e-6) return false;
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: check_symmetry TREE.json GROUP REGION\n";
        return 2;
    }
    std::ifstream in(argv[1]);
    const Json tree = Json::parse(in);
    const std::string group_arg = argv[2];
    const bool frieze = group_arg.rfind("frieze:", 0) == 0;
    const bool wallpaper = group_arg.rfind("wallpaper:", 0) == 0;
    // A group with translations: its cosets and the translations (a, b) on the plane.
    std::vector<Isometry> cosets;
    Vector lattice_a(0, 0), lattice_b(0, 0);
    std::optional<Region> tile;
    if (frieze || wallpaper) {
        const std::string rest = group_arg.substr(group_arg.find(':') + 1);
        const std::string name = rest.substr(0, rest.find(':'));
        const std::string size = rest.substr(rest.find(':') + 1);
        if (wallpaper) {
            const Tile t = parse_tile(size);
            cosets = make_wallpaper_group(name, t).transforms;
            lattice_a = Vector(t.a().x, t.a().y);
            lattice_b = Vector(t.b().x, t.b().y);
            std::ostringstream svg;
            svg.precision(17);
            svg << "<svg xmlns='http://www.w3.org/2000/svg'><polygon points='0,0 " << t.a().x << ','
                << t.a().y << ' ' << t.a().x + t.b().x << ',' << t.a().y + t.b().y << ' ' << t.b().x
                << ',' << t.b().y << "'/></svg>";
            tile = Region::from_svg_string(svg.str(), "tile");
        } else {
            const double period = std::stod(size);
            const Rect rb = Region::from_argument(argv[3]).bounds();
            const double cy = (rb.y0 + rb.y1) / 2;
            const Isometry to{1, 0, 0, 1, rb.x0, cy}, from{1, 0, 0, 1, -rb.x0, -cy};
            for (const Isometry& h : make_frieze_group(name, period).transforms)
                cosets.push_back(from.then(h).then(to));
            lattice_a = Vector(period, 0);
        }
    }
    const bool translations = frieze || wallpaper;
    const Region region = tile ? *tile : Region::from_argument(argv[3]);
    const Rect b = region.bounds();
    const double tol = 1e-6 * std::max(b.width(), b.height());

    std::vector<std::unique_ptr<Loaded>> elements;
    for (const Json& j : tree.at("elements")) {
        auto e = std::make_unique<Loaded>();
        e->type_name = j.at("type");
        e->type_info.name = e->type_name;
        e->id = j.at("id");
        for (const Json& p : j.at("proxies")) e->proxies.push_back(load_proxy(p));
        if (j.contains("image_of")) {
            e->image_of = j.at("image_of");
            const Json& m = j.at("transform");
            e->transform = {m[0], m[1], m[2], m[3], m[4], m[5]};
        }
        elements.push_back(std::move(e));
    }
    int faults = 0;
    auto fault = [&](const std::string& what) {
        if (++faults <= 20) std::cout << "FAULT: " << what << "\n";
    };

    // The transformations.
    std::vector<Isometry> transforms{Isometry{}};
    for (const auto& e : elements) {
        if (e->image_of < 0) continue;
        bool known = false;
        for (const Isometry& t : transforms) known = known || same(t, e->transform);
        if (!known) transforms.push_back(e->transform);
    }
    // With translations: a coset's isometry and the integer combination of a and b after it.
    auto in_group = [&](const Isometry& t) {
        for (const Isometry& h : cosets) {
            if (std::abs(h.a - t.a) > 1e-6 || std::abs(h.b - t.b) > 1e-6 ||
                std::abs(h.c - t.c) > 1e-6 || std::abs(h.d - t.d) > 1e-6)
                continue;
            const Vector d(t.e - h.e, t.f - h.f);
            double i = 0, j = 0;
            if (wallpaper) {
                const double det = lattice_a.cross(lattice_b);
                i = d.cross(lattice_b) / det;
                j = lattice_a.cross(d) / det;
            } else {
                i = d.x / lattice_a.x;
                if (std::abs(d.y) > tol) continue;
            }
            if (std::abs(i - std::round(i)) < 1e-6 && std::abs(j - std::round(j)) < 1e-6)
                return true;
        }
        return false;
    };
    if (translations) {
        for (const Isometry& t : transforms)
            if (!in_group(t)) fault("an image's transformation is not in " + group_arg);
    } else {
        const Symmetry group = Symmetry::parse(group_arg);
        const std::size_t expected = static_cast<std::size_t>(
            group.kind == Symmetry::Kind::cyclic ? group.order : 2 * group.order);
        if (transforms.size() != expected)
            fault("the images use " + std::to_string(transforms.size()) +
                  " transformations with the identity; " + group.name() + " has " +
                  std::to_string(expected));
        for (const Isometry& s : transforms)
            for (const Isometry& t : transforms) {
                bool found = false;
                for (const Isometry& u : transforms) found = found || same(s.then(t), u);
                if (!found) fault("the transformations are not closed under composition");
            }
    }
    // The isometries each element's images are looked for under: a rosette's transformations;
    // with translations every coset with the translations that can keep an image in the bounds.
    std::vector<Isometry> checked = transforms;
    if (translations) {
        checked.clear();
        const double diagonal = std::hypot(b.width(), b.height());
        const int reach =
            2 + static_cast<int>(std::ceil(
                    2 * diagonal /
                    std::min(lattice_a.length(), wallpaper ? lattice_b.length() : 1e300)));
        for (const Isometry& h : cosets)
            for (int i = -reach; i <= reach; ++i)
                for (int j = wallpaper ? -reach : 0; j <= (wallpaper ? reach : 0); ++j) {
                    const Vector t = lattice_a * i + lattice_b * j;
                    checked.push_back(h.then(Isometry{1, 0, 0, 1, t.x, t.y}));
                }
    }
    // With translations, an image is looked for when it lies wholly in the region (a frieze's
    // band ends there) or in the tile's bounds (the engine keeps more round the tile).
    auto expected_present = [&](const Element& image) {
        if (!translations) return true;
        for (std::size_t k = 0; k < image.proxy_count(); ++k) {
            const Proxy& p = image.proxy(k);
            // Beyond the bounds first: the exact test may miss a curve's end just beyond them.
            const Rect r = p.bounds();
            if (r.x0 < b.x0 - tol || r.y0 < b.y0 - tol || r.x1 > b.x1 + tol || r.y1 > b.y1 + tol)
                return false;
            if (!wallpaper && leaves_region(p, region, tol)) return false;
        }
        return true;
    };

    // Elements by type, in a grid of cells of their first proxy's bounds centre.
    const double cell = std::max(b.width(), b.height()) / 64;
    auto key = [&](const Element& e) {
        const Point c = e.proxy(0).bounds().center();
        return std::make_pair(static_cast<long>(std::floor(c.x / cell)),
                              static_cast<long>(std::floor(c.y / cell)));
    };
    std::map<std::pair<long, long>, std::vector<const Loaded*>> grid;
    for (const auto& e : elements)
        if (e->proxy_count() > 0) grid[key(*e)].push_back(e.get());

    // The stored element of `type` in the place of `probe`, or null.
    auto find_like = [&](const Element& probe, const std::string& type) -> Loaded* {
        const auto [kx, ky] = key(probe);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                const auto it = grid.find({kx + dx, ky + dy});
                if (it == grid.end()) continue;
                for (const Loaded* f : it->second)
                    if (f->type_name == type && same_place(probe, *f, tol))
                        return const_cast<Loaded*>(f);
            }
        return nullptr;
    };
    long images = 0;
    for (const auto& e : elements) {
        if (e->image_of >= 0) ++images;
        for (std::size_t k = 0; k < e->proxy_count() && !wallpaper; ++k)
            if (leaves_region(e->proxy(k), region, tol))
                fault("element " + std::to_string(e->id) + " leaves the region");
        if (e->proxy_count() == 0) continue;
        for (const Isometry& t : checked) {
            ImageElement image(*e, t);
            if (!expected_present(image)) continue;
            const auto [kx, ky] = key(image);
            bool found = false;
            for (long dx = -1; dx <= 1 && !found; ++dx)
                for (long dy = -1; dy <= 1 && !found; ++dy) {
                    const auto it = grid.find({kx + dx, ky + dy});
                    if (it == grid.end()) continue;
                    for (const Loaded* f : it->second)
                        if (f->type_name == e->type_name && same_place(image, *f, tol)) {
                            found = true;
                            break;
                        }
                }
            if (!found) {
                const Point c = image.proxy(0).bounds().center();
                fault("an image of element " + std::to_string(e->id) + " is missing (at " +
                      std::to_string(c.x) + "," + std::to_string(c.y) + ", translation " +
                      std::to_string(t.e) + "," + std::to_string(t.f) + ")");
            }
        }
    }

    // Overlaps the symmetry caused.
    SpatialIndex index;
    for (const auto& e : elements)
        if (e->type_name != "seed")
            for (std::size_t k = 0; k < e->proxy_count(); ++k)
                index.insert(e->id, static_cast<int>(k), e->proxy(k).bounds());
    long overlaps_found = 0;
    for (const auto& a : elements) {
        if (a->type_name == "seed") continue;
        for (std::size_t k = 0; k < a->proxy_count(); ++k)
            for (const SpatialIndex::Entry& en : index.query(a->proxy(k).bounds())) {
                if (en.element <= a->id) continue;
                Loaded& other = *elements[static_cast<std::size_t>(en.element)];
                // Decided as the engine decided it: in the frame where the later element is
                // fundamental, against the stored image of the earlier one, later element
                // first (the exact tests of curves may round a touch either way otherwise).
                const std::size_t q = static_cast<std::size_t>(en.proxy);
                const Isometry back = other.transform.inverse();
                Loaded* later = other.image_of >= 0
                                    ? elements[static_cast<std::size_t>(other.image_of)].get()
                                    : &other;
                ImageElement carried_back(*a, back);
                Loaded* earlier = find_like(carried_back, a->type_name);
                if (!(earlier ? overlaps(later->proxy(q), earlier->proxy(k), tol)
                              : overlaps(later->proxy(q), carried_back.proxy(k), 2 * tol)))
                    continue;
                // A pair of fundamental elements carried by one transformation is the rule's
                // (an element on a mirror is carried onto itself by more than one).
                auto fundamental = [&](Loaded& e) -> Element& {
                    return e.image_of >= 0 ? *elements[static_cast<std::size_t>(e.image_of)] : e;
                };
                Element& a0 = fundamental(*a);
                Element& b0 = fundamental(other);
                bool carried = false;
                for (const Isometry& t : transforms)
                    carried = carried || (same_place(ImageElement(a0, t), *a, tol) &&
                                          same_place(ImageElement(b0, t), other, tol));
                if (carried) continue;
                ++overlaps_found;
                fault("elements " + std::to_string(a->id) + " and " + std::to_string(other.id) +
                      " overlap (an image)");
            }
    }
    std::cout << elements.size() << " elements, " << images << " images, " << transforms.size()
              << " transformations; " << faults << " faults\n";
    return faults == 0 ? 0 : 1;
}
