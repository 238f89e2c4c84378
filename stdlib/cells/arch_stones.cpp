// Arch stones [5.2]: voussoirs with radial joints along arc edges, in rows, set out as a mason
// sets out an arch: from the crown, an odd count with a key there, a keystone with real width at a
// pointed apex, skewbacks under a segmental arch, all before the walling round them.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "lintel.hpp"
#include "ring_check.hpp"
#include "run_ends.hpp"
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

bool in_face(const Face& face, Point p) {
    bool in = false;
    for (const std::vector<Point>& loop : face.loops)
        for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
            if ((loop[i].y > p.y) != (loop[j].y > p.y) &&
                p.x < loop[j].x +
                          (p.y - loop[j].y) * (loop[i].x - loop[j].x) / (loop[i].y - loop[j].y))
                in = !in;
    return in;
}

const Edge* plumb_jamb(const Facade& f, const Edge& arc, int corner) {
    if (corner < 0) return nullptr;
    const Corner& k = f.corners()[static_cast<std::size_t>(corner)];
    const Edge* arc_ptr = &arc;
    for (int e : {k.edge_in, k.edge_out}) {
        if (e < 0) continue;
        const Edge& other = f.edges()[static_cast<std::size_t>(e)];
        if (&other == arc_ptr || other.arc) continue;
        if (other.bounds.width() <= 1e-6 * std::max(1.0, other.bounds.height())) return &other;
    }
    return nullptr;
}

namespace {

// A circle the reader split into arcs with no corner between them (their centres a rounding
// error apart): the arcs of that one ring, in edge order; else just `edge`.
std::vector<const Edge*> ring_of(const Facade& f, const Edge& edge) {
    std::vector<const Edge*> out{&edge};
    if (!edge.arc || edge.closed || edge.corner_start >= 0 || edge.corner_end >= 0) return out;
    const Segment& s = edge.segments.front();
    const double tol = 1e-6 * std::max(1.0, s.radius);
    out.clear();
    double sweep = 0;
    for (int e : f.faces()[static_cast<std::size_t>(edge.face)].edges) {
        const Edge& o = f.edges()[static_cast<std::size_t>(e)];
        if (!o.arc || o.closed || o.corner_start >= 0 || o.corner_end >= 0) continue;
        bool same = true;
        for (const Segment& g : o.segments)
            same &= distance(g.center, s.center) <= tol && std::abs(g.radius - s.radius) <= tol;
        if (!same) continue;
        out.push_back(&o);
        for (const Segment& g : o.segments) sweep += g.sweep;
    }
    std::sort(out.begin(), out.end());
    if (std::abs(std::abs(sweep) - 2 * M_PI) > 1e-6) out = {&edge};
    return out;
}

}  // namespace

bool ring_fits(const Facade& f, const Edge& edge, double depth) {
    if (!edge.arc) return true;
    const Face& face = f.faces()[static_cast<std::size_t>(edge.face)];
    // Just inside the extrados and the skewback's plumb side: a ring whose extrados meets the
    // wall's end exactly still fits.
    const double d = depth * (1 - 1e-6);
    const int n = std::clamp(static_cast<int>(std::ceil(edge.length / (0.1 * depth))), 8, 512);
    for (int i = 0; i <= n; ++i) {
        const double s = edge.length * i / n;
        const Point p = edge.at(s);
        if (!in_face(face, p + edge.inward(s) * d) || !in_face(face, p + edge.inward(s) * d / 2))
            return false;
    }
    for (int end = 0; end < 2 && !edge.closed; ++end) {
        const double s = end ? edge.length : 0;
        if (!plumb_jamb(f, edge, end ? edge.corner_end : edge.corner_start)) continue;
        const Point p = edge.at(s);
        const Vector u = edge.inward(s);
        if (u.y >= 0) continue;  // no skewback: the ring springs level or downwards
        const double x = p.x + u.x * d;
        for (double k : {0.5, 0.99})
            if (!in_face(face, {x, p.y + u.y * d * (1 - k)})) return false;
        if (!in_face(face, {p.x + (x - p.x) * 0.99, p.y - 1e-6 * depth})) return false;
    }
    return true;
}

const Edge* nearest_edge(const Facade& f, int face, Point p) {
    const Edge* nearest = nullptr;
    double best = 1e300;
    for (int j : f.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& o = f.edges()[static_cast<std::size_t>(j)];
        const double d = distance(o.at(o.project(p)), p);
        if (d < best) best = d, nearest = &o;
    }
    return nearest;
}

const Edge* opening_in_ring(const Facade& f, const Edge& edge, double depth) {
    if (!edge.arc) return nullptr;
    const Face& face = f.faces()[static_cast<std::size_t>(edge.face)];
    const int n = std::clamp(static_cast<int>(std::ceil(edge.length / (0.1 * depth))), 8, 512);
    for (int i = 0; i <= n; ++i) {
        const double s = edge.length * i / n;
        for (double k : {0.5, 1 - 1e-6}) {
            const Point p = edge.at(s) + edge.inward(s) * (depth * k);
            if (in_face(face, p)) continue;
            // Out of the wall: through the wall's end or another opening.
            const Edge* nearest = nearest_edge(f, edge.face, p);
            if (nearest && nearest->opening && nearest->labels != edge.labels) return nearest;
        }
    }
    return nullptr;
}

std::vector<const Edge*> arch_arcs(const Facade& f, const Edge& e) {
    std::vector<const Edge*> out = ring_of(f, e);
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int k : {out[i]->corner_start, out[i]->corner_end}) {
            if (k < 0) continue;
            const Corner& c = f.corners()[static_cast<std::size_t>(k)];
            for (int j : {c.edge_in, c.edge_out}) {
                const Edge* o = j >= 0 ? &f.edges()[static_cast<std::size_t>(j)] : nullptr;
                if (o && o->arc && std::find(out.begin(), out.end(), o) == out.end())
                    out.push_back(o);
            }
        }
    return out;
}

double ring_depth(const Facade& f, const Edge& e, const Options& o, double depth) {
    const std::vector<const Edge*> arcs = arch_arcs(f, e);
    auto fits = [&](double d) {
        return std::all_of(arcs.begin(), arcs.end(),
                           [&](const Edge* a) { return ring_fits(f, *a, d); });
    };
    if (fits(depth)) return depth;
    const double half = (o.brick_length + o.mortar) / 2;
    return half < depth && fits(half) ? half : 0;
}

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
    // A ring split into arcs is set out whole from its crown, by its first arc.
    const std::vector<const Edge*> ring = ring_of(facade, edge);
    if (ring.size() > 1) {
        if (ring.front() != &edge) return;
        double total = 0;
        for (const Edge* e : ring) total += e->length;
        for (int row = 0; row < rows; ++row) {
            double r_in = radius + grow * depth * row, r_out = radius + grow * depth * (row + 1);
            if (r_in <= 0 || r_out <= 0) break;
            const double want = total / radius * (r_in + r_out) / 2 / width;
            int n = std::max(1, static_cast<int>(std::lround(want)));
            if (n % 2 == 0) n = want >= n ? n + 1 : std::max(1, n - 1);
            for (int i = 0; i < n; ++i) {
                double t0 = M_PI / 2 + dir * 2 * M_PI * i / n;
                double t1 = M_PI / 2 + dir * 2 * M_PI * (i + 1) / n;
                std::vector<Point> poly;
                arc_points(r_in, t0, t1, poly);
                arc_points(r_out, t1, t0, poly);
                c.place(poly, row);
            }
        }
        return;
    }
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
    // Its top, level between the two arcs' radials at the apex, is coursed in: moved to the
    // nearest bed joint of the walling, so the brick over it is laid whole (it had been cut a
    // few millimetres in height over a lancet's key). Lowered only while it stays over the
    // ends of its radial sides (a key no shorter than the voussoirs beside it), raised with
    // plumb sides only by up to half a course and within the wall.
    const double top = std::min(out[n].y, out[n + 1].y);
    if (c.options().bond != Bond::ashlar) {
        const std::vector<double>& ys = brick_layout(c, k.face).grid.ys;
        const double course = c.options().brick_height + c.options().mortar;
        const double lowest = std::min(out.front().y, out.back().y);
        const Face& face = facade.faces()[static_cast<std::size_t>(k.face)];
        double line = top, best = 1e300;
        for (double y : ys) {
            const double d = std::abs(y - top);
            if (d >= best) continue;
            const bool ok = y > top ? y < lowest - 1e-6 * course
                                    : top - y <= course / 2 && in_face(face, {out[n].x, y}) &&
                                          in_face(face, {out[n + 1].x, y});
            if (ok) line = y, best = d;
        }
        if (line < top) {  // raised: plumb sides up to the bed joint over it
            const Point a_up{out[n].x, line}, b_up{out[n + 1].x, line};
            out.insert(out.begin() + n + 1, {a_up, b_up});
        } else if (line > top) {  // lowered: cut level at the bed joint
            std::vector<Point> poly = in;
            poly.insert(poly.end(), out.rbegin(), out.rend());
            std::vector<Point> cut;
            for (std::size_t i = 0; i < poly.size(); ++i) {
                const Point p = poly[i], q = poly[(i + 1) % poly.size()];
                if (p.y >= line) cut.push_back(p);
                if ((p.y >= line) != (q.y >= line))
                    cut.push_back({p.x + (q.x - p.x) * (line - p.y) / (q.y - p.y), line});
            }
            c.place(cut);
            return;
        }
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
        BrickLayout& layout = brick_layout(c, k.face);
        const CourseGrid& g = layout.grid;
        const double sx = q.x > p.x ? 1 : -1;
        const double tiny = 1e-9 * std::max(1.0, std::abs(g.xs.back()) + std::abs(g.ys.back()));
        // The runs the plumb side crosses end at it, laid again as at a jamb: the piece beside
        // it cut at a joint, not shaved (a 20.5 cm brick stood beside a window's skewback).
        fit_run_ends_at(facade, k.face, c.options(), layout, Jamb{q.x, q.y, yb, sx > 0}, p.x);
        const double h = layout.mortar / 2;
        for (int row = std::max(0, g.row_at(q.y + tiny)); row >= 0 && row < g.rows(); ++row) {
            const double top = std::max(g.ys[static_cast<std::size_t>(row)], q.y);
            const double bottom = std::min(g.ys[static_cast<std::size_t>(row) + 1], yb);
            if (bottom <= top + tiny) break;
            // The course's head joints as laid, beyond the side.
            double gap = 1e300;
            for (std::size_t i = 0; i < layout.rows[static_cast<std::size_t>(row)].size(); ++i) {
                const Rect d = layout.drawn(row, static_cast<int>(i));
                for (double x : {d.x0 - h, d.x1 + h})
                    if ((x - q.x) * sx > tiny) gap = std::min(gap, (x - q.x) * sx);
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

// The depth the ring of arc `e` is laid at: by the wall, and half a brick where it would meet
// another ring or a lintel (plan_rings, made once per depth).
double planned_depth(Context& c, const Edge& e, double depth) {
    const detail::RingPlan& plan =
        c.data().layout<detail::RingPlan>("arch:rings:" + std::to_string(depth), [&] {
            if (c.options().bond == Bond::ashlar)
                return detail::plan_rings(c.facade(), c.options(), depth);
            // Brick lintels as the courses lay them: their real bearings and courses.
            return detail::plan_rings(
                c.facade(), c.options(), depth,
                [&c](const Edge& head, Rect& r) { return detail::laid_lintel(c, head, r); });
        });
    auto it = plan.depth.find(detail::arch_key(c.facade(), e));
    return it != plan.depth.end() ? it->second
                                  : detail::ring_depth(c.facade(), e, c.options(), depth);
}

// A corner on an arc: the keystone or skewback there, then the whole ring of each arc edge at
// it, recorded against that edge (the checker and add_cells see voussoirs on their arc).
void set_out_from(const FeatureRef& f, Context& c, double width, double depth, int rows) {
    const Facade& facade = c.facade();
    const Corner& k = facade.corners()[static_cast<std::size_t>(f.index)];
    // A ring that would reach past the wall (a springing near its end) or meet another ring or
    // a lintel is turned in one half-brick ring; check_limits() refuses an arch where not even
    // that fits.
    for (int e : {k.edge_in, k.edge_out}) {
        if (e < 0 || !facade.edges()[static_cast<std::size_t>(e)].arc) continue;
        const double d =
            planned_depth(c, facade.edges()[static_cast<std::size_t>(e)], depth * rows);
        if (d > 0 && d < depth * rows) depth = d, rows = 1;
    }
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
        const double fit = planned_depth(c, e, depth * rows);
        if (fit > 0 && fit < depth * rows)
            detail::place_voussoirs(e, c, width, fit, 1);
        else
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
        const double fit = planned_depth(c, e, depth);
        detail::place_voussoirs(e, c, width, fit > 0 ? fit : depth, 1);
    };
}

}  // namespace acanthus::cells
