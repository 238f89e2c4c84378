// Checks a wallpaper tile from the outside, as the expert would, on the program's --json tree:
//   check_seams TREE.json W,H[,ANGLE] [--sites]
// The tile is the parallelogram from the origin with sides a = (W, 0) and b at ANGLE (as
// --tile gives it). Its elements (translates across its edges included: coincident copies are
// one element) are repeated 3 x 3, and:
// - no two elements overlap across a seam (the elements' first proxies' bounds centres lie in
//   different copies of the tile), unless one is the other's parent or they share one (the
//   rule's business, as inside a tile; an image is related as the element it is of);
// - no gap across the seams is larger than inside: the largest empty circle that touches a seam
//   of the central copy is no larger than 1.1 times the largest one that does not, plus two
//   pixels of the raster the empty circles are measured on (the elements' proxies drawn at
//   1/512 of the tile's larger side, the seed markers left out).
// Exit 0 when both hold, 1 with the faults listed. --sites also prints the empty circle on each
// lattice's rotation centres (corner, edge middles, centre, the hexagonal cell's 3-fold points).
#include <cairo.h>

#include <acanthus/element.hpp>
#include <acanthus/proxy.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geometry/spatial_index.hpp"
#include "proxy/overlap.hpp"
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

struct Loaded final : Element {
    std::string type_name;
    ElementType type_info;
    long parent_id = -1;
    long original = -1;  // the fundamental element an image is of; its own id otherwise
    std::vector<std::unique_ptr<Proxy, void (*)(Proxy*)>> proxies;
    const ElementType& type() const override { return type_info; }
    std::size_t proxy_count() const override { return proxies.size(); }
    Proxy& proxy(std::size_t k) override { return *proxies[k]; }
};

// One element of the 3 x 3 repeat: a tree element and the translation (copy i, j) it is under.
struct Placed {
    const Loaded* element;
    int i, j;
    std::unique_ptr<ImageElement> image;
    int cell_i, cell_j;  // the copy of the tile its reference point lies in
};

// Draws a proxy's shape for the empty-circle raster (curves as hairlines of one pixel).
void trace(cairo_t* cr, const Proxy& p) {
    cairo_new_path(cr);
    switch (p.kind()) {
        case ProxyKind::point:  // a marker, no extent
            return;
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(p);
            cairo_arc(cr, c.center.x, c.center.y, std::abs(c.radius), 0, 2 * M_PI);
            cairo_fill(cr);
            return;
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(p);
            cairo_arc(cr, a.center.x, a.center.y, std::abs(a.radius), a.start, a.end);
            break;
        }
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(p);
            cairo_move_to(cr, l.p0.x, l.p0.y);
            cairo_line_to(cr, l.p1.x, l.p1.y);
            break;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(p);
            cairo_move_to(cr, b.c[0].x, b.c[0].y);
            cairo_curve_to(cr, b.c[1].x, b.c[1].y, b.c[2].x, b.c[2].y, b.c[3].x, b.c[3].y);
            break;
        }
        case ProxyKind::polygon: {
            const auto& g = static_cast<const PolygonProxy&>(p);
            for (const Point& q : g.points) cairo_line_to(cr, q.x, q.y);
            cairo_close_path(cr);
            cairo_fill(cr);
            return;
        }
    }
    cairo_stroke(cr);
}

// Squared Euclidean distance transform of one row or column (Felzenszwalb and Huttenlocher).
void edt_1d(const std::vector<double>& f, std::vector<double>& d) {
    const int n = static_cast<int>(f.size());
    std::vector<int> v(static_cast<std::size_t>(n));
    std::vector<double> z(static_cast<std::size_t>(n) + 1);
    int k = 0;
    v[0] = 0;
    z[0] = -std::numeric_limits<double>::infinity();
    z[1] = std::numeric_limits<double>::infinity();
    for (int q = 1; q < n; ++q) {
        double s;
        while (true) {
            const int p = v[static_cast<std::size_t>(k)];
            s = ((f[static_cast<std::size_t>(q)] + double(q) * q) -
                 (f[static_cast<std::size_t>(p)] + double(p) * p)) /
                (2.0 * (q - p));
            if (s > z[static_cast<std::size_t>(k)] || k == 0) break;
            --k;
        }
        if (s <= z[static_cast<std::size_t>(k)]) {  // k == 0 and the first parabola is hidden
            v[0] = q;
            z[1] = std::numeric_limits<double>::infinity();
            continue;
        }
        ++k;
        v[static_cast<std::size_t>(k)] = q;
        z[static_cast<std::size_t>(k)] = s;
        z[static_cast<std::size_t>(k) + 1] = std::numeric_limits<double>::infinity();
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[static_cast<std::size_t>(k) + 1] < q) ++k;
        const int p = v[static_cast<std::size_t>(k)];
        d[static_cast<std::size_t>(q)] = double(q - p) * (q - p) + f[static_cast<std::size_t>(p)];
    }
}

}  // namespace

int main(int argc, char** argv) {
    const bool sites = argc == 4 && std::string(argv[3]) == "--sites";
    if (argc != 3 && !sites) {
        std::cerr << "usage: check_seams TREE.json W,H[,ANGLE] [--sites]\n";
        return 2;
    }
    std::ifstream in(argv[1]);
    const Json tree = Json::parse(in);
    const Tile tile = parse_tile(argv[2]);
    const Point a = tile.a(), b = tile.b();
    const double side = std::max(std::hypot(a.x, a.y), std::hypot(b.x, b.y));
    const double tol = 1e-6 * side;
    auto fractional = [&](Point p) {
        const double det = a.x * b.y - a.y * b.x;
        return Point{(p.x * b.y - p.y * b.x) / det, (a.x * p.y - a.y * p.x) / det};
    };

    std::vector<std::unique_ptr<Loaded>> elements;
    std::map<long, long> parent_of;  // id -> parent id, fundamental elements
    for (const Json& j : tree.at("elements"))
        if (j.contains("parent") && !j.at("parent").is_null())
            parent_of[j.at("id").get<long>()] = j.at("parent").get<long>();
    for (const Json& j : tree.at("elements")) {
        auto e = std::make_unique<Loaded>();
        e->type_name = j.at("type");
        e->type_info.name = e->type_name;
        e->id = j.at("id");
        if (j.contains("parent") && !j.at("parent").is_null()) e->parent_id = j.at("parent");
        e->original = j.contains("image_of") ? j.at("image_of").get<long>() : long(e->id);
        for (const Json& p : j.at("proxies")) e->proxies.push_back(load_proxy(p));
        if (e->type_name != "seed" && !e->proxies.empty()) elements.push_back(std::move(e));
    }

    // The 3 x 3 repeat, coincident copies (a translate the tree already holds) kept once.
    std::vector<Placed> placed;
    SpatialIndex index;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
            for (const auto& e : elements) {
                const Isometry shift{1, 0, 0, 1, i * a.x + j * b.x, i * a.y + j * b.y};
                auto image = std::make_unique<ImageElement>(*e, shift);
                bool duplicate = false;
                for (const SpatialIndex::Entry& en : index.query(image->proxy(0).bounds()))
                    if (en.proxy == 0 &&
                        placed[static_cast<std::size_t>(en.element)].element->type_name ==
                            e->type_name &&
                        same_place(*placed[static_cast<std::size_t>(en.element)].image, *image,
                                   tol)) {
                        duplicate = true;
                        break;
                    }
                if (duplicate) continue;
                const Point f = fractional(image->proxy(0).bounds().center());
                Placed p{e.get(),
                         i,
                         j,
                         std::move(image),
                         static_cast<int>(std::floor(f.x)),
                         static_cast<int>(std::floor(f.y))};
                const int n = static_cast<int>(placed.size());
                for (std::size_t k = 0; k < p.image->proxy_count(); ++k)
                    index.insert(n, static_cast<int>(k), p.image->proxy(k).bounds());
                placed.push_back(std::move(p));
            }

    int faults = 0;
    auto fault = [&](const std::string& what) {
        if (++faults <= 20) std::cout << "FAULT: " << what << "\n";
    };
    if (elements.empty()) {
        fault("the tile holds no element");
        return 1;
    }

    // Overlaps across a seam, around the central copy.
    long seam_overlaps = 0;
    for (std::size_t n = 0; n < placed.size(); ++n) {
        const Placed& p = placed[n];
        if (std::abs(p.cell_i) > 0 || std::abs(p.cell_j) > 0) continue;  // around the centre
        for (std::size_t k = 0; k < p.image->proxy_count(); ++k)
            for (const SpatialIndex::Entry& en : index.query(p.image->proxy(k).bounds())) {
                const Placed& q = placed[static_cast<std::size_t>(en.element)];
                if (&q == &p || (q.cell_i == p.cell_i && q.cell_j == p.cell_j)) continue;
                const Loaded& x = *p.element;
                const Loaded& y = *q.element;
                // Images have no parent: the relation is their originals'.
                auto parent = [&](long id) {
                    const auto it = parent_of.find(id);
                    return it == parent_of.end() ? -1L : it->second;
                };
                const long fx = x.original, fy = y.original;
                if (fx != fy && (parent(fy) == fx || parent(fx) == fy ||
                                 (parent(fx) >= 0 && parent(fx) == parent(fy))))
                    continue;
                if (!overlaps(p.image->proxy(k), q.image->proxy(static_cast<std::size_t>(en.proxy)),
                              tol))
                    continue;
                ++seam_overlaps;
                fault("element " + std::to_string(x.id) + " overlaps element " +
                      std::to_string(y.id) + " of the copy " + std::to_string(q.cell_i) + "," +
                      std::to_string(q.cell_j) + " across a seam");
            }
    }

    // Empty circles on a raster of the 3 x 3 repeat's bounds.
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int j = -1; j <= 2; j += 3)
        for (int i = -1; i <= 2; i += 3) {
            const Point c{i * a.x + j * b.x, i * a.y + j * b.y};
            x0 = std::min(x0, c.x), y0 = std::min(y0, c.y);
            x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
        }
    const double px = side / 512;  // user units per pixel
    const int w = static_cast<int>(std::ceil((x1 - x0) / px)) + 1;
    const int h = static_cast<int>(std::ceil((y1 - y0) / px)) + 1;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
    cairo_t* cr = cairo_create(surface);
    cairo_scale(cr, 1 / px, 1 / px);
    cairo_translate(cr, -x0, -y0);
    cairo_set_line_width(cr, px);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (const Placed& p : placed)
        for (std::size_t k = 0; k < p.image->proxy_count(); ++k) trace(cr, p.image->proxy(k));
    cairo_surface_flush(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    std::vector<double> dist(static_cast<std::size_t>(w) * h);
    const double far = 1e20;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            dist[static_cast<std::size_t>(y) * w + x] = data[y * stride + x] ? 0 : far;
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    {
        std::vector<double> f, d;
        f.resize(static_cast<std::size_t>(std::max(w, h)));
        d.resize(f.size());
        for (int x = 0; x < w; ++x) {
            f.resize(static_cast<std::size_t>(h));
            d.resize(static_cast<std::size_t>(h));
            for (int y = 0; y < h; ++y)
                f[static_cast<std::size_t>(y)] = dist[static_cast<std::size_t>(y) * w + x];
            edt_1d(f, d);
            for (int y = 0; y < h; ++y)
                dist[static_cast<std::size_t>(y) * w + x] = d[static_cast<std::size_t>(y)];
        }
        for (int y = 0; y < h; ++y) {
            f.assign(dist.begin() + static_cast<long>(y) * w,
                     dist.begin() + static_cast<long>(y + 1) * w);
            d.resize(static_cast<std::size_t>(w));
            edt_1d(f, d);
            std::copy(d.begin(), d.end(), dist.begin() + static_cast<long>(y) * w);
        }
    }
    // The central copy's seams: its four edges, as lines in fractional coordinates.
    const double la = std::hypot(a.x, a.y), lb = std::hypot(b.x, b.y);
    const double area = std::abs(a.x * b.y - a.y * b.x);
    double seam_gap = 0, inside_gap = 0;
    Point seam_at{0, 0};  // in fractions of the tile's sides, to tell which site it is
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Point p{x0 + (x + 0.5) * px, y0 + (y + 0.5) * px};
            const Point f = fractional(p);
            if (f.x < 0 || f.x >= 1 || f.y < 0 || f.y >= 1) continue;
            const double r = std::sqrt(dist[static_cast<std::size_t>(y) * w + x]) * px;
            // Distance to the edges: along b's normal for u, along a's normal for v.
            const double to_seam = std::min(
                {f.x * area / lb, (1 - f.x) * area / lb, f.y * area / la, (1 - f.y) * area / la});
            if (to_seam <= r && r > seam_gap) seam_at = f;
            double& gap = to_seam <= r ? seam_gap : inside_gap;
            gap = std::max(gap, r);
        }
    if (sites) {
        // The radius of the empty circle centred on each site (its nearest element).
        std::vector<std::pair<std::string, Point>> at{{"corner", {0, 0}},
                                                      {"edge a/2", {0.5, 0}},
                                                      {"edge b/2", {0, 0.5}},
                                                      {"centre", {0.5, 0.5}}};
        if (std::abs(la - lb) < tol && std::abs(a.x * b.x + a.y * b.y) > tol) {  // hexagonal
            at.push_back({"(a+b)/3", {1.0 / 3, 1.0 / 3}});
            at.push_back({"2(a+b)/3", {2.0 / 3, 2.0 / 3}});
            at.push_back({"(2a-b)/3", {2.0 / 3, 1.0 / 3}});
            at.push_back({"(2b-a)/3", {1.0 / 3, 2.0 / 3}});
        }
        for (const auto& [name, f] : at) {
            const Point p{f.x * a.x + f.y * b.x, f.x * a.y + f.y * b.y};
            const int x = static_cast<int>(std::floor((p.x - x0) / px));
            const int y = static_cast<int>(std::floor((p.y - y0) / px));
            const double r = std::sqrt(dist[static_cast<std::size_t>(y) * w + x]) * px;
            std::cout << "site " << name << " (" << p.x << "," << p.y << "): empty circle " << r
                      << "\n";
        }
    }
    if (seam_gap > 1.1 * inside_gap + 2 * px)
        fault("a gap across a seam (an empty circle of radius " + std::to_string(seam_gap) +
              ") at " + std::to_string(seam_at.x) + " a + " + std::to_string(seam_at.y) +
              " b is larger than inside the tile (" + std::to_string(inside_gap) + ")");

    std::cout << elements.size() << " elements in the tree, " << placed.size()
              << " in the 3 x 3 repeat; " << seam_overlaps
              << " overlaps across seams; largest empty circle on a seam " << seam_gap
              << ", inside " << inside_gap << "; " << faults << " faults\n";
    return faults == 0 ? 0 : 1;
}
