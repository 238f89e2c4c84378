// Arch stones [5.2]: voussoirs with radial joints along arc edges, in rows, set out as a mason
// sets out an arch: from the crown, an odd count with a key there, a keystone with real width at a
// pointed apex, skewbacks under a segmental arch, all before the walling round them.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "voussoirs.hpp"

namespace acanthus::cells {

namespace detail {

namespace {

// Unit radial at p on the arc of `s`, pointing into the wall (away from the opening).
Vector away_at(const Edge& e, const Segment& s, Point p, double at) {
    Vector u = (p - s.center).normalized();
    return u.dot(e.inward(at)) < 0 ? -u : u;
}

const Edge* arc_at(const Facade& f, int e) {
    if (e < 0) return nullptr;
    const Edge& edge = f.edges()[static_cast<std::size_t>(e)];
    return edge.arc ? &edge : nullptr;
}

// A pointed apex: two arcs meeting at an angle.
bool apex(const Facade& f, const Corner& k) {
    const Edge* a = arc_at(f, k.edge_in);
    const Edge* b = arc_at(f, k.edge_out);
    if (!a || !b) return false;
    Vector ua = away_at(*a, a->segments.back(), k.position, a->length);
    Vector ub = away_at(*b, b->segments.front(), k.position, 0);
    return ua.dot(ub) <= std::cos(1.0 * M_PI / 180);
}

}  // namespace

void place_voussoirs(const Edge& edge, Context& c, double width, double depth, int rows) {
    if (!edge.arc) return;
    const Facade& facade = c.facade();
    const Segment& first = edge.segments.front();
    const Point center = first.center;
    const double radius = first.radius;
    const double dir = first.sweep >= 0 ? 1 : -1;
    // Rows grow away from the opening: outwards when the wall lies outside the circle.
    const Vector out = edge.at(edge.length / 2) - center;
    const double grow = edge.inward(edge.length / 2).dot(out) > 0 ? 1 : -1;
    double tol = c.options().arc_tolerance > 0 ? c.options().arc_tolerance
                                               : std::max(1e-3, c.options().mortar / 20);
    auto arc_points = [&](double r, double a0, double a1, std::vector<Point>& pts) {
        double step = 2 * std::acos(std::max(-1.0, 1 - tol / std::max(r, 1e-300)));
        int n = std::clamp(static_cast<int>(std::ceil(std::abs(a1 - a0) / std::max(step, 1e-6))), 1,
                           1024);
        for (int i = 0; i <= n; ++i) {
            double a = a0 + (a1 - a0) * i / n;
            pts.push_back({center.x + r * std::cos(a), center.y + r * std::sin(a)});
        }
    };
    // A whole arch (springing to springing, or a whole ring): an odd count, a key at the crown.
    auto ends_at_apex = [&](int k) {
        return k >= 0 && apex(facade, facade.corners()[static_cast<std::size_t>(k)]);
    };
    const bool half = ends_at_apex(edge.corner_start) || ends_at_apex(edge.corner_end);
    const double slack = 1e-6 * edge.length;
    auto intervals =
        c.edge_occupancy(static_cast<int>(&edge - facade.edges().data())).free_intervals(slack);
    for (auto [s0, s1] : intervals) {
        const bool whole = !half && s0 <= slack && s1 >= edge.length - slack;
        Point p0 = edge.at(s0);
        double a0 = std::atan2(p0.y - center.y, p0.x - center.x);
        double sweep = dir * (s1 - s0) / radius;
        // A ring with no springing is set out from its crown (SVG: y down, the crown at -pi/2):
        // starting opposite it, the middle stone of an odd count is centred on the crown.
        if (edge.closed && whole) a0 = M_PI / 2;
        for (int row = 0; row < rows; ++row) {
            double r_in = radius + grow * depth * row, r_out = radius + grow * depth * (row + 1);
            if (r_in <= 0 || r_out <= 0) break;
            double mid = (r_in + r_out) / 2;
            const double want = std::abs(sweep) * mid / width;
            int n = std::max(1, static_cast<int>(std::lround(want)));
            if (whole && n % 2 == 0)  // the odd count nearer the wanted width
                n = want >= n ? n + 1 : std::max(1, n - 1);
            for (int i = 0; i < n; ++i) {
                double t0 = a0 + sweep * i / n, t1 = a0 + sweep * (i + 1) / n;
                std::vector<Point> poly;
                arc_points(r_in, t0, t1, poly);
                arc_points(r_out, t1, t0, poly);
                c.place(poly, row);
            }
        }
    }
}

// Where two arcs meet at an angle (a pointed arch's apex): a keystone half a voussoir along each
// arc from the apex, so it has real width at the intrados, its sides the radial joints there.
void place_keystone(const Corner& k, Context& c, double depth, double width) {
    const Facade& facade = c.facade();
    if (!apex(facade, k)) return;
    const Edge& a = facade.edges()[static_cast<std::size_t>(k.edge_in)];
    const Edge& b = facade.edges()[static_cast<std::size_t>(k.edge_out)];
    const double ha = std::min(width / 2, a.length / 3), hb = std::min(width / 2, b.length / 3);
    const int n = 8;
    std::vector<Point> in, out;
    for (int i = 0; i <= n; ++i) {  // up arc a to the apex
        double s = a.length - ha + ha * i / n;
        Point p = a.at(s);
        in.push_back(p);
        out.push_back(p + away_at(a, a.segments.back(), p, s) * depth);
    }
    for (int i = 0; i <= n; ++i) {  // and down arc b
        double s = hb * i / n;
        Point p = b.at(s);
        if (i > 0) in.push_back(p);
        out.push_back(p + away_at(b, b.segments.front(), p, s) * depth);
    }
    std::vector<Point> poly = in;
    poly.insert(poly.end(), out.rbegin(), out.rend());
    c.place(poly);
}

// Under a segmental arch, where the arc springs from a straight jamb at an angle: a skewback,
// bounded by the jamb, the ring's first radial joint, a plumb side and a bed on the course line
// below the springing, so the walling beside it is cut square.
void place_skewback(const Corner& k, Context& c, double depth, double bed) {
    const Facade& facade = c.facade();
    const Edge* arc = arc_at(facade, k.edge_in);
    int other = k.edge_out;
    double at = 0;
    if (arc) {
        at = arc->length, other = k.edge_out;
    } else {
        arc = arc_at(facade, k.edge_out), other = k.edge_in;
    }
    if (!arc || other < 0 || arc_at(facade, other)) return;
    const Edge& jamb = facade.edges()[static_cast<std::size_t>(other)];
    if (jamb.bounds.width() > 1e-6 * std::max(1.0, jamb.bounds.height())) return;  // plumb only
    const Point p = k.position;
    const Segment& s = at > 0 ? arc->segments.back() : arc->segments.front();
    const Vector u = away_at(*arc, s, p, at);
    if (u.y >= 0) return;  // the ring springs upwards from a segmental arch's springing
    const Point q = p + u * depth;
    const double yb = std::max(p.y, bed);
    // Its plumb side: where the bond beside it would keep less than a queen closer between the
    // side and the next head joint of a course, the skewback takes that piece in, so the walling
    // starts at a joint there (a 3 cm piece was left beside each skewback of a 1.2 m window).
    std::vector<Point> poly{p, q};
    double x = q.x;
    if (c.options().bond != Bond::ashlar) {
        const BrickLayout& layout = brick_layout(c, k.face);
        const CourseGrid& g = layout.grid;
        const double sx = q.x > p.x ? 1 : -1;
        const double tiny = 1e-9 * std::max(1.0, std::abs(g.xs.back()) + std::abs(g.ys.back()));
        for (int row = std::max(0, g.row_at(q.y + tiny)); row >= 0 && row < g.rows(); ++row) {
            const double top = std::max(g.ys[static_cast<std::size_t>(row)], q.y);
            const double bottom = std::min(g.ys[static_cast<std::size_t>(row) + 1], yb);
            if (bottom <= top + tiny) break;
            double gap = 1e300;
            for (const Piece& piece : layout.rows[static_cast<std::size_t>(row)])
                for (int unit : {piece.start, piece.start + piece.length}) {
                    const double d = (g.xs[static_cast<std::size_t>(unit)] - q.x) * sx;
                    if (d > tiny) gap = std::min(gap, d);
                }
            const double to = gap < layout.unit - tiny ? q.x + sx * gap : q.x;
            if (to != x) poly.push_back({to, top});
            poly.push_back({to, bottom});
            x = to;
        }
    }
    if (poly.size() == 2) poly.push_back({q.x, yb});
    if (poly.back().y != yb) poly.push_back({x, yb});
    poly.push_back({p.x, yb});
    // A skewback with no bed below its springing is a triangle: no vertex twice.
    poly.erase(std::unique(poly.begin(), poly.end(),
                           [](Point a, Point b) { return a.x == b.x && a.y == b.y; }),
               poly.end());
    if (poly.size() > 1 && poly.front().x == poly.back().x && poly.front().y == poly.back().y)
        poly.pop_back();
    c.place(poly);
}

}  // namespace detail

namespace {

// A corner on an arc: the keystone or skewback there, then the whole ring of each arc edge at
// it, recorded against that edge (the checker and add_cells see voussoirs on their arc).
void set_out_from(const FeatureRef& f, Context& c, double width, double depth, int rows) {
    const Facade& facade = c.facade();
    const Corner& k = facade.corners()[static_cast<std::size_t>(f.index)];
    auto& keyed = c.data().layout<std::set<int>>("arch:keystones", [] { return std::set<int>{}; });
    const std::string generator = c.data().generator;
    auto key = [&](int corner) {
        if (corner < 0 || !keyed.insert(corner).second) return;
        c.begin(generator, {FeatureKind::corner, corner});
        const Corner& kk = facade.corners()[static_cast<std::size_t>(corner)];
        detail::place_keystone(kk, c, depth * rows, width);
    };
    key(f.index);
    // The course line at or below the springing, for a skewback's bed.
    double bed = k.position.y;
    if (c.options().bond != Bond::ashlar) {
        const detail::CourseGrid& g = detail::brick_layout(c, k.face).grid;
        const double tiny = 1e-6 * (g.ys.back() - g.ys.front());
        const int row = g.row_at(k.position.y - tiny);
        if (row >= 0) bed = g.ys[static_cast<std::size_t>(row) + 1];
    }
    c.begin(generator, f);
    detail::place_skewback(k, c, depth * rows, bed);
    for (int e : {k.edge_in, k.edge_out}) {
        if (e < 0 || !facade.edges()[static_cast<std::size_t>(e)].arc) continue;
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        key(edge.corner_start);
        key(edge.corner_end);
        c.begin(generator, {FeatureKind::edge, e});
        detail::place_voussoirs(edge, c, width, depth, rows);
    }
    c.begin(generator, f);
}

}  // namespace

Generator arch_stones() {
    return [](const FeatureRef& f, Context& c) {
        const Options& o = c.options();
        double depth = o.arch_depth > 0 ? o.arch_depth : o.brick_length + o.mortar;
        double width = o.voussoir_width > 0 ? o.voussoir_width : 2 * (o.brick_height + o.mortar);
        const int rows = std::max(1, o.arch_rows);
        if (f.kind == FeatureKind::corner) {
            set_out_from(f, c, width, depth, rows);
            return;
        }
        if (f.kind != FeatureKind::edge) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(f.index)];
        detail::place_voussoirs(e, c, width, depth, rows);
    };
}

Generator arch_bricks() {
    // Bricks on end round the arc (a rowlock arch): one course height wide, a brick deep.
    return [](const FeatureRef& f, Context& c) {
        const Options& o = c.options();
        const double width = o.brick_height + o.mortar, depth = o.brick_length + o.mortar;
        if (f.kind == FeatureKind::corner) {
            set_out_from(f, c, width, depth, 1);
            return;
        }
        if (f.kind != FeatureKind::edge) return;
        const Edge& e = c.facade().edges()[static_cast<std::size_t>(f.index)];
        detail::place_voussoirs(e, c, width, depth, 1);
    };
}

}  // namespace acanthus::cells
