// Rings that would meet, found before a stone is laid: each arch's ring and each flat head's
// lintel as a few simple polygons, pairs tested only where their boxes meet (a sweep along x,
// so a front of hundreds of arches costs a few tests per arch).
#include "ring_check.hpp"

#include <algorithm>
#include <cmath>

#include "ashlar_grid.hpp"
#include "lintel.hpp"
#include "voussoirs.hpp"

namespace acanthus::cells::detail {

namespace {

Rect box_of(const std::vector<std::vector<Point>>& parts) {
    Rect b{1e300, 1e300, -1e300, -1e300};
    for (const auto& poly : parts)
        for (Point p : poly)
            b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x),
                 std::max(b.y1, p.y)};
    return b;
}

bool boxes_meet(const Rect& a, const Rect& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

double cross(Point o, Point a, Point b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Strictly inside, further than `tol` from every side (even-odd).
bool inside(const std::vector<Point>& poly, Point p, double tol) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Point a = poly[j], b = poly[i];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        if (len > 0) {
            const double t = std::clamp(
                ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (len * len), 0.0, 1.0);
            if (std::hypot(p.x - a.x - t * (b.x - a.x), p.y - a.y - t * (b.y - a.y)) <= tol)
                return false;
        }
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
            in = !in;
    }
    return in;
}

}  // namespace

std::string names_of(const Edge& e) {
    std::string names;
    for (const std::string& l : e.labels) names += (names.empty() ? "" : " ") + l;
    return names;
}

bool polygons_meet(const std::vector<Point>& a, const std::vector<Point>& b) {
    if (a.size() < 3 || b.size() < 3) return false;
    const Rect ba = box_of({a}), bb = box_of({b});
    if (!boxes_meet(ba, bb)) return false;
    const double size = std::max({ba.width(), ba.height(), bb.width(), bb.height(), 1e-300});
    const double tol = 1e-7 * size, area_tol = tol * size;
    for (std::size_t i = 0, j = a.size() - 1; i < a.size(); j = i++)
        for (std::size_t k = 0, m = b.size() - 1; k < b.size(); m = k++) {
            const double o1 = cross(a[j], a[i], b[m]), o2 = cross(a[j], a[i], b[k]);
            const double o3 = cross(b[m], b[k], a[j]), o4 = cross(b[m], b[k], a[i]);
            // A proper crossing: each segment's ends strictly either side of the other.
            if (((o1 > area_tol && o2 < -area_tol) || (o1 < -area_tol && o2 > area_tol)) &&
                ((o3 > area_tol && o4 < -area_tol) || (o3 < -area_tol && o4 > area_tol)))
                return true;
        }
    // No sides cross: apart, touching, or one within the other.
    for (Point p : a)
        if (inside(b, p, tol)) return true;
    for (Point p : b)
        if (inside(a, p, tol)) return true;
    return false;
}

bool shapes_meet(const RingShape& a, const RingShape& b) {
    if (!boxes_meet(a.box, b.box)) return false;
    for (const auto& p : a.parts)
        for (const auto& q : b.parts)
            if (polygons_meet(p, q)) return true;
    return false;
}

RingShape ring_shape(const Facade& f, const Options& o, const std::vector<const Edge*>& arcs,
                     double depth) {
    RingShape r;
    for (const Edge* e : arcs) {
        // Pieces of four intervals: nearly convex, each a simple polygon.
        const int n = std::clamp(static_cast<int>(std::ceil(e->length / (0.25 * depth))), 8, 512);
        for (int i0 = 0; i0 < n; i0 += 4) {
            const int i1 = std::min(n, i0 + 4);
            std::vector<Point> in, out;
            for (int i = i0; i <= i1; ++i) {
                const double s = e->length * i / n;
                in.push_back(e->at(s));
                out.push_back(e->at(s) + e->inward(s) * depth);
            }
            in.insert(in.end(), out.rbegin(), out.rend());
            r.parts.push_back(std::move(in));
        }
        // A skewback beside a plumb jamb, down to the course line below the springing at most;
        // in brick, its plumb side may move out to the next head joint (a quarter brick).
        for (int end = 0; end < 2 && !e->closed; ++end) {
            const double s = end ? e->length : 0;
            if (!plumb_jamb(f, *e, end ? e->corner_end : e->corner_start)) continue;
            const Point p = e->at(s);
            const Vector u = e->inward(s);
            if (u.y >= 0) continue;
            const Point q = p + u * depth;
            const double below = o.brick_height + o.mortar;
            const double x = o.bond == Bond::ashlar
                                 ? q.x
                                 : q.x + (q.x > p.x ? 1 : -1) * (o.brick_length + o.mortar) / 4;
            r.parts.push_back({p, q, {x, q.y}, {x, p.y + below}, {p.x, p.y + below}});
        }
    }
    r.box = box_of(r.parts);
    return r;
}

RingShape lintel_shape(const Edge& head, const Options& o, const CourseGrid* grid) {
    RingShape r;
    if (grid) {
        // In stone the lintel is laid on the face's ashlar grid, whose lines pass through the
        // jambs: the rectangle it will take is known before any stone is laid.
        const double unit = ashlar_unit(o);
        const int bearing = std::max(
            1, static_cast<int>(
                   std::ceil(o.lintel_bearing * (o.brick_length + o.mortar) / 4 / unit - 1e-9)));
        int top = 0, bottom = 0, u0 = 0, u1 = 0;
        if (!lintel_span(head, *grid, unit, bearing, o.lintel_courses, top, bottom, u0, u1))
            return r;
        const Rect b = grid->cell(bottom, u0, u1);
        const double y0 = grid->ys[static_cast<std::size_t>(top)];
        r.parts.push_back({{b.x0, y0}, {b.x1, y0}, {b.x1, b.y1}, {b.x0, b.y1}});
        r.box = box_of(r.parts);
        return r;
    }
    const double ux = (o.brick_length + o.mortar) / 4, uy = o.brick_height + o.mortar;
    // The bearing rounded out to the unit the jamb falls in, and a quarter brick a framed
    // tree may move it by; the courses from the one the head falls in.
    const double x = (o.lintel_bearing + 2) * ux;
    const double y = head.bounds.y0;
    const int courses = std::max(1, o.lintel_courses);
    r.parts.push_back({{head.bounds.x0 - x, y - (courses + 0.25) * uy},
                       {head.bounds.x1 + x, y - (courses + 0.25) * uy},
                       {head.bounds.x1 + x, y + 0.75 * uy},
                       {head.bounds.x0 - x, y + 0.75 * uy}});
    r.box = box_of(r.parts);
    return r;
}

int arch_key(const Facade& f, const Edge& e) {
    int key = static_cast<int>(&e - f.edges().data());
    for (const Edge* a : arch_arcs(f, e))
        key = std::min(key, static_cast<int>(a - f.edges().data()));
    return key;
}

RingPlan plan_rings(const Facade& f, const Options& o, double depth, const LintelRect& laid) {
    struct Item {
        int key = -1;  // an arch's key, or -1: a lintel
        const Edge* edge = nullptr;
        std::vector<const Edge*> arcs;
        double base = 0;
        RingShape shape;
        bool halve = false;
    };
    std::vector<Item> items;
    std::map<int, CourseGrid> grids;  // per face, the ashlar grid stone lintels are laid on
    for (const Edge& e : f.edges()) {
        if (!e.opening) continue;
        if (e.arc) {
            const int key = arch_key(f, e);
            if (key != static_cast<int>(&e - f.edges().data())) continue;
            Item it{key, &e, arch_arcs(f, e), ring_depth(f, e, o, depth), {}, false};
            if (it.base > 0) it.shape = ring_shape(f, o, it.arcs, it.base);
            items.push_back(std::move(it));
        } else if (e.part == Part::top) {
            const CourseGrid* grid = nullptr;
            if (o.bond == Bond::ashlar) {
                auto it = grids.find(e.face);
                if (it == grids.end())
                    it = grids.emplace(e.face, make_grid(f, e.face, ashlar_unit(o), ashlar_unit(o)))
                             .first;
                grid = &it->second;
            }
            RingShape shape;
            Rect r;
            if (!grid && laid) {
                if (laid(e, r))
                    shape.parts.push_back({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}});
                shape.box = r;
            } else
                shape = lintel_shape(e, o, grid);
            items.push_back({-1, &e, {}, 0, std::move(shape), false});
        }
    }
    RingPlan plan;
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < items.size(); ++i)
        if (!items[i].shape.parts.empty()) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return items[a].shape.box.x0 < items[b].shape.box.x0 ||
               (items[a].shape.box.x0 == items[b].shape.box.x0 && a < b);
    });
    // Calls `meet(i, j)` for every pair with at least one arch whose shapes share area.
    auto each_meeting = [&](auto&& meet) {
        for (std::size_t k = 0; k < order.size(); ++k)
            for (std::size_t m = k + 1;
                 m < order.size() && items[order[m]].shape.box.x0 < items[order[k]].shape.box.x1;
                 ++m) {
                Item& a = items[order[k]];
                Item& b = items[order[m]];
                if ((a.key < 0 && b.key < 0) || !shapes_meet(a.shape, b.shape)) continue;
                meet(std::min(order[k], order[m]), std::max(order[k], order[m]));
            }
    };
    each_meeting([&](std::size_t i, std::size_t j) { items[i].halve = items[j].halve = true; });
    const double half = (o.brick_length + o.mortar) / 2;
    for (Item& it : items)
        if (it.key >= 0 && it.halve && it.base > half) {
            it.base = half;
            it.shape = ring_shape(f, o, it.arcs, half);
        }
    std::pair<std::size_t, std::size_t> first{items.size(), items.size()};
    // Two rings that still meet refuse the facade (a lintel that still meets a half-brick ring
    // is cut to its extrados: the rings are laid first).
    each_meeting([&](std::size_t i, std::size_t j) {
        if (items[i].key >= 0 && items[j].key >= 0) first = std::min(first, std::pair{i, j});
    });
    if (first.first < items.size()) {
        plan.clash_a = names_of(*items[first.first].edge);
        plan.clash_b = names_of(*items[first.second].edge);
    }
    for (const Item& it : items)
        if (it.key >= 0) plan.depth[it.key] = it.base;
    return plan;
}

}  // namespace acanthus::cells::detail
