// Relieving (discharging) arches: over the lintel of an opening labelled `relieving`, a segmental
// rowlock ring (half a brick deep; in stone walls, of arch stones) springing a quarter brick beyond
// the lintel's ends from skewbacks on the course line of its top, set out from the crown with an
// odd count and a key. Laid before the walling (texture() lays relieving heads right after the
// arches), so the tympanum between lintel and ring and the walling over it are cut to the ring.
#include "relieving_arch.hpp"

#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "ashlar_grid.hpp"
#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"
#include "head_edge.hpp"
#include "lintel.hpp"
#include "ring_check.hpp"
#include "voussoirs.hpp"

namespace acanthus::cells {

namespace detail {

bool relieving(const Edge& e) {
    return std::find(e.labels.begin(), e.labels.end(), "relieving") != e.labels.end();
}

double relieving_least_span(const Options& o) { return 6 * (o.brick_height + o.mortar); }

namespace {

// The pieces of one relieving arch as claims: voussoirs from left to right, then the two
// skewbacks.
struct ReliefPieces {
    std::vector<std::vector<Point>> voussoirs, skewbacks;
};

// `stone`: in a stone wall the ring is of arch stones (Options::arch_depth deep,
// Options::voussoir_width at the intrados), in brick a rowlock.
ReliefPieces set_out(const Rect& lintel, const Options& o, const CourseGrid& grid, bool stone) {
    const double quarter = (o.brick_length + o.mortar) / 4;
    const double xl = lintel.x0 - quarter, xr = lintel.x1 + quarter, y = lintel.y0;
    // A segmental ring rising a sixth of its span: the intrados through both springings.
    const double span = xr - xl, rise = span / 6;
    const double radius = (span * span / 4 + rise * rise) / (2 * rise);
    const Point center{(xl + xr) / 2, y + radius - rise};
    const double depth = !stone             ? (o.brick_length + o.mortar) / 2  // a header on edge
                         : o.arch_depth > 0 ? o.arch_depth
                                            : o.brick_length + o.mortar;
    const double half = std::asin(std::min(1.0, span / 2 / radius));
    // An odd count of voussoirs a course wide at the intrados: the middle one the key.
    const double pitch = !stone                 ? o.brick_height + o.mortar
                         : o.voussoir_width > 0 ? o.voussoir_width
                                                : 2 * (o.brick_height + o.mortar);
    const double fit = 2 * half * radius / pitch;
    int n = std::max(3, static_cast<int>(std::lround(fit)));
    if (n % 2 == 0) n += fit > n ? 1 : -1;
    n = std::max(3, n);
    const double tol = o.arc_tolerance > 0 ? o.arc_tolerance : std::max(1e-3, o.mortar / 20);
    auto arc = [&](double r, double a0, double a1, std::vector<Point>& pts) {
        const double step = 2 * std::acos(std::max(-1.0, 1 - tol / r));
        const int k = std::clamp(
            static_cast<int>(std::ceil(std::abs(a1 - a0) / std::max(step, 1e-6))), 1, 256);
        for (int i = 0; i <= k; ++i) {
            const double a = a0 + (a1 - a0) * i / k;
            pts.push_back({center.x + r * std::cos(a), center.y + r * std::sin(a)});
        }
    };
    ReliefPieces out;
    const double start = -M_PI / 2 - half;  // the left springing (SVG: y down)
    for (int i = 0; i < n; ++i) {
        const double a0 = start + 2 * half * i / n, a1 = start + 2 * half * (i + 1) / n;
        std::vector<Point> poly, outer;
        arc(radius, a0, a1, poly);
        arc(radius + depth, a0, a1, outer);
        poly.insert(poly.end(), outer.rbegin(), outer.rend());
        out.voussoirs.push_back(std::move(poly));
    }
    // Skewbacks: the springing joint radial, a plumb side on the next quarter-brick line out,
    // the top on the course line at or over the ring's extrados there, the bed on the lintel's
    // top course line.
    for (int side = 0; side < 2; ++side) {
        const double a = side ? start + 2 * half : start;
        const Point p{center.x + radius * std::cos(a), center.y + radius * std::sin(a)};
        const Point q{center.x + (radius + depth) * std::cos(a),
                      center.y + (radius + depth) * std::sin(a)};
        const double tiny = 1e-6 * quarter;
        double x = side ? q.x + quarter : q.x - quarter;
        if (const int u = grid.unit_at(side ? q.x + tiny : q.x - tiny); u >= 0)
            x = grid.xs[static_cast<std::size_t>(side ? u + 1 : u)];
        double top = q.y;
        if (const int row = grid.row_at(q.y - tiny); row >= 0)
            top = grid.ys[static_cast<std::size_t>(row)];
        std::vector<Point> poly{p, q};
        if (top < q.y) poly.push_back({q.x, top});
        poly.push_back({x, top});
        poly.push_back({x, y});
        if (side) std::reverse(poly.begin(), poly.end());
        out.skewbacks.push_back(std::move(poly));
    }
    return out;
}

// Refuses the arch where its pieces would not lie in the wall (past its top or end, into another
// opening) or would meet a piece laid before (another ring): InputError naming both shapes.
void check_room(Context& c, const Edge& head, const ReliefPieces& pieces) {
    const Facade& f = c.facade();
    const Face& face = f.faces()[static_cast<std::size_t>(head.face)];
    const std::string name = f.name() + ": the opening \"" + names_of(head) + "\": ";
    for (const auto* set : {&pieces.voussoirs, &pieces.skewbacks})
        for (const std::vector<Point>& poly : *set) {
            Point mid{0, 0};
            for (Point p : poly) mid = mid + (p - Point{0, 0}) * (1.0 / poly.size());
            std::vector<Point> probes{mid};
            for (Point p : poly) probes.push_back(p + (mid - p) * 0.02);
            for (Point p : probes) {
                if (in_face(face, p)) continue;
                const Edge* other = nearest_edge(f, head.face, p);
                if (other && other->opening && other->labels != head.labels)
                    throw InputError(name + "its relieving arch would reach into the opening \"" +
                                     names_of(*other) +
                                     "\": move them apart or leave out the label relieving");
                throw InputError(name +
                                 "its relieving arch would reach past the wall (no room under "
                                 "its top or beside its end): a relieving arch needs wall over "
                                 "its lintel; lower the opening or leave out the label relieving");
            }
            for (const Cell& cell : c.cells())
                if (polygons_meet(poly, cell.polygon))
                    throw InputError(name + "its relieving arch would meet the " + cell.generator +
                                     " of \"" + cell.label +
                                     "\": move the openings apart or leave out the label "
                                     "relieving");
        }
}

}  // namespace

}  // namespace detail

Generator relieving_arch() {
    return [](const FeatureRef& f, Context& c) {
        const int head = detail::head_edge(c.facade(), f);
        if (head < 0) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(head)];
        if (!detail::relieving(e)) return;
        auto& laid =
            c.data().layout<std::set<int>>("relieving:laid", [] { return std::set<int>{}; });
        if (!laid.insert(head).second) return;
        Rect lintel;
        if (!detail::laid_lintel(c, e, lintel)) return;
        const detail::CourseGrid& grid =
            c.data().stone ? detail::ashlar_grid(c, e.face) : detail::brick_layout(c, e.face).grid;
        const detail::ReliefPieces pieces =
            detail::set_out(lintel, c.options(), grid, c.data().stone);
        detail::check_room(c, e, pieces);
        auto lay = [&](const std::vector<Point>& poly, const char* piece) {
            const int n = c.place(poly);
            for (int i = 0; i < n; ++i)
                c.cells()[c.cells().size() - 1 - static_cast<std::size_t>(i)].piece = piece;
        };
        for (const auto& v : pieces.voussoirs) lay(v, "voussoir");
        for (const auto& s : pieces.skewbacks) lay(s, "skewback");
    };
}

}  // namespace acanthus::cells
