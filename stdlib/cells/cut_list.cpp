// The cut list: each laid cell measured and named as a mason orders it. Bricks are named by their
// length in quarter bricks (a header and a half bat look alike on the face: 2 quarters are headers
// in bonds that lay headers, half bats in the others); arch pieces by the widths at the arc and
// away from it.
#include <acanthus/error.hpp>
#include <acanthus/output_file.hpp>
#include <acanthus/stdlib/cells/cut_list.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "clip.hpp"

namespace acanthus::cells {

namespace {

// Rounded sizes, the key of a line.
using Key = std::tuple<std::string, std::string, long, long, long, long>;

bool is_rect(const std::vector<Point>& polygon, Rect& r) {
    if (detail::axis_rect(polygon, r)) return true;
    r = detail::bounds_of(polygon);
    const double box = r.width() * r.height();
    return box > 0 && std::abs(std::abs(detail::signed_area(polygon)) - box) <= 1e-6 * box;
}

bool near(double a, double b, double tol) { return std::abs(a - b) <= tol; }

// A brick's face of drawn width w and height h.
std::string brick_kind(double w, double h, const Options& o, double tol) {
    if (!near(h, o.brick_height, tol)) return "cut brick";  // a cut course, or cut to an opening
    const double quarter = (o.brick_length + o.mortar) / 4;
    const long n = std::lround((w + o.mortar) / quarter);
    if (n < 1 || n > 4 || !near(w, static_cast<double>(n) * quarter - o.mortar, tol))
        return "cut brick";
    const bool headers =
        o.bond == Bond::english || o.bond == Bond::flemish || o.bond == Bond::header;
    switch (n) {
        case 4:
            return "stretcher";
        case 3:
            return "three-quarter bat";
        case 2:
            return headers ? "header" : "half bat";
        default:
            return "queen closer";
    }
}

// Widths at the intrados and the extrados, and the depth, of an arch piece: its vertices split by
// their distance from the nearest arc (of any opening: a keystone at a pointed apex lies on two)
// into the near and far sides.
bool taper(const Facade& facade, const std::vector<Point>& polygon, double& intrados,
           double& extrados, double& depth) {
    if (polygon.size() < 3) return false;
    std::vector<double> d(polygon.size(), 1e300);
    for (const Edge& e : facade.edges())
        if (e.arc)
            for (std::size_t i = 0; i < polygon.size(); ++i)
                d[i] = std::min(d[i], distance(e.at(e.project(polygon[i])), polygon[i]));
    if (d[0] == 1e300) return false;
    const auto [lo, hi] = std::minmax_element(d.begin(), d.end());
    const double mid = (*lo + *hi) / 2;
    auto width = [&](bool inner) {
        double w = 0;
        for (std::size_t i = 0; i < polygon.size(); ++i)
            for (std::size_t j = i + 1; j < polygon.size(); ++j)
                if ((d[i] <= mid) == inner && (d[j] <= mid) == inner)
                    w = std::max(w, distance(polygon[i], polygon[j]));
        return w;
    };
    intrados = width(true);
    extrados = width(false);
    depth = *hi - *lo;
    return depth > 0;
}

// The same for a voussoir of a relieving arch, whose circle is no edge of the facade: its two
// longest sides are its joints, their near ends the intrados.
bool joint_taper(const std::vector<Point>& polygon, double& intrados, double& extrados,
                 double& depth) {
    const std::size_t n = polygon.size();
    if (n < 4) return false;
    std::size_t a = n, b = n;
    auto side = [&](std::size_t i) { return distance(polygon[i], polygon[(i + 1) % n]); };
    for (std::size_t i = 0; i < n; ++i)
        if (a == n || side(i) > side(a))
            b = a, a = i;
        else if (b == n || side(i) > side(b))
            b = i;
    const Point p0 = polygon[a], p1 = polygon[(a + 1) % n];
    const Point q0 = polygon[b], q1 = polygon[(b + 1) % n];
    // Ends paired across the voussoir (not its diagonals): the pairing with the shorter sum.
    double u = distance(p0, q0), v = distance(p1, q1);
    if (distance(p0, q1) + distance(p1, q0) < u + v) u = distance(p0, q1), v = distance(p1, q0);
    intrados = std::min(u, v), extrados = std::max(u, v);
    depth = (side(a) + side(b)) / 2;
    return depth > 0;
}

}  // namespace

std::vector<CutListItem> cut_list(const Facade& facade, const std::vector<Cell>& cells,
                                  const Options& o, double mm_per_unit) {
    if (!(mm_per_unit > 0) || !std::isfinite(mm_per_unit))
        throw InputError(facade.name() + ": cut list: millimetres per unit must be positive");
    const double tol = 1 / mm_per_unit;  // a millimetre: the checker's whole-brick tolerance
    auto mm = [&](double v) { return std::lround(v * mm_per_unit); };
    const bool stone_wall = o.bond == Bond::ashlar;
    std::map<Key, long> counts;
    for (const Cell& c : cells) {
        Rect r;
        const bool rect = is_rect(c.polygon, r);
        if (!rect) r = detail::bounds_of(c.polygon);
        const double w = r.width(), h = r.height();
        std::string kind;
        const std::string& g = c.generator;
        if (g == "arch_stones" || g == "arch_bricks") {
            double in = 0, out = 0, depth = 0;
            if (rect) {
                kind = "skewback";
            } else if (taper(facade, c.polygon, in, out, depth)) {
                kind = "voussoir";
                const long a = mm(in), b = mm(out);
                // Width: the wider side, height: the depth along the joints.
                counts[{g, kind, mm(std::max(in, out)), mm(depth), a, b}] += 1;
                continue;
            } else {
                kind = "shaped cut";
            }
        } else if (g == "relieving_arch") {
            double in = 0, out = 0, depth = 0;
            if (c.piece == "voussoir" && joint_taper(c.polygon, in, out, depth)) {
                counts[{g, "voussoir", mm(std::max(in, out)), mm(depth), mm(in), mm(out)}] += 1;
                continue;
            }
            kind = "skewback";
        } else if (!rect) {
            kind = "shaped cut";
        } else if (g == "bricks") {
            kind = c.piece.empty() ? brick_kind(w, h, o, tol) : c.piece;
        } else if (g == "window_bottom") {
            kind = stone_wall ? "sill stone" : "sill header";
        } else if (g == "soldier_course") {
            kind = "soldier";
        } else if (g == "lintel") {
            kind = "lintel";
        } else if (g == "quoins") {
            kind = "quoin stone";
        } else if (g == "ashlar") {
            kind = "ashlar stone";
        } else {
            kind = "block";
        }
        counts[{g, kind, mm(w), mm(h), 0, 0}] += 1;
    }
    std::vector<CutListItem> items;
    for (const auto& [key, n] : counts) {
        const auto& [g, kind, w, h, a, b] = key;
        CutListItem it;
        it.facade = facade.name();
        it.generator = g;
        it.kind = kind;
        it.width = static_cast<double>(w);
        it.height = static_cast<double>(h);
        it.intrados = static_cast<double>(a);
        it.extrados = static_cast<double>(b);
        it.count = n;
        items.push_back(std::move(it));
    }
    return items;
}

namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string field(const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char ch : s) {
        if (ch == '"') q += '"';
        q += ch;
    }
    return q + "\"";
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

}  // namespace

std::string cut_list_csv(const std::vector<CutListItem>& items) {
    std::string out = "facade,generator,kind,count,width_mm,height_mm,intrados_mm,extrados_mm\n";
    for (const CutListItem& it : items) {
        const bool arch = it.kind == "voussoir";
        out += field(it.facade) + "," + field(it.generator) + "," + field(it.kind) + "," +
               std::to_string(it.count) + "," + number(it.width) + "," + number(it.height) + "," +
               (arch ? number(it.intrados) : "") + "," + (arch ? number(it.extrados) : "") + "\n";
    }
    return out;
}

std::string cut_list_json(const std::vector<CutListItem>& items) {
    nlohmann::ordered_json facades = nlohmann::ordered_json::array();
    for (const CutListItem& it : items) {
        if (facades.empty() || facades.back()["name"] != it.facade)
            facades.push_back({{"name", it.facade}, {"pieces", nlohmann::ordered_json::array()}});
        nlohmann::ordered_json p = {{"generator", it.generator},
                                    {"kind", it.kind},
                                    {"count", it.count},
                                    {"width_mm", std::lround(it.width)},
                                    {"height_mm", std::lround(it.height)}};
        if (it.kind == "voussoir") {
            p["intrados_mm"] = std::lround(it.intrados);
            p["extrados_mm"] = std::lround(it.extrados);
        }
        facades.back()["pieces"].push_back(std::move(p));
    }
    nlohmann::ordered_json doc = {{"facades", std::move(facades)}};
    return doc.dump(2) + "\n";
}

void write_cut_list(const std::string& path, const std::vector<CutListItem>& items) {
    auto ends_with = [&](const char* ext) {
        const std::string e = ext;
        return path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
    };
    std::string bytes;
    if (ends_with(".csv"))
        bytes = cut_list_csv(items);
    else if (ends_with(".json"))
        bytes = cut_list_json(items);
    else
        throw InputError("cut list '" + path + "': expected a .csv or .json file name");
    std::string error;
    if (!write_file_atomically(path, bytes, error)) throw InputError("cut list: " + error);
}

}  // namespace acanthus::cells
