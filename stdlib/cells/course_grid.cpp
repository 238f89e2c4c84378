#include "course_grid.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::cells::detail {

namespace {

// Sorted values merged where closer than half a unit, then each interval cut into units.
std::vector<double> lines(std::vector<double> v, double unit) {
    std::sort(v.begin(), v.end());
    std::vector<double> kept;
    for (double x : v)
        if (kept.empty() || x - kept.back() >= unit / 2) kept.push_back(x);
    if (kept.size() >= 2 && v.back() > kept.back()) kept.back() = v.back();
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
        double w = kept[i + 1] - kept[i];
        int n = std::max(1, static_cast<int>(std::lround(w / unit)));
        for (int k = 0; k < n; ++k) out.push_back(kept[i] + w * k / n);
    }
    out.push_back(kept.back());
    return out;
}

}  // namespace

int CourseGrid::unit_at(double x) const {
    if (x < xs.front() || x > xs.back()) return -1;
    auto it = std::upper_bound(xs.begin(), xs.end(), x);
    return std::min(static_cast<int>(it - xs.begin()) - 1, units() - 1);
}

int CourseGrid::row_at(double y) const {
    if (y < ys.front() || y > ys.back()) return -1;
    auto it = std::upper_bound(ys.begin(), ys.end(), y);
    return std::min(static_cast<int>(it - ys.begin()) - 1, rows() - 1);
}

Point inside_corner(const Corner& c, double step) {
    Vector d = c.out - c.in;
    if (d.length() < 1e-9) d = c.out.perp();
    d = d.normalized();
    if (!c.convex) d = -d;
    return c.position + d * step;
}

CourseGrid make_grid(const Facade& facade, int face, double ux, double uy) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    std::vector<double> vx{f.bounds.x0, f.bounds.x1}, vy{f.bounds.y0, f.bounds.y1};
    for (int e : f.edges) {
        // Edge ends only: the inner ends of a flattened curve's chords are no features, and
        // lines through them would cut courses to half height along the curve.
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        for (Point p : {edge.segments.front().a, edge.segments.back().b}) {
            vx.push_back(p.x);
            vy.push_back(p.y);
        }
        if (edge.arc || edge.closed) {
            vx.push_back(edge.bounds.x0), vx.push_back(edge.bounds.x1);
            vy.push_back(edge.bounds.y0), vy.push_back(edge.bounds.y1);
        }
    }
    CourseGrid g;
    g.xs = lines(std::move(vx), ux);
    g.ys = lines(std::move(vy), uy);
    classify_units(facade, face, g);
    return g;
}

void classify_units(const Facade& facade, int face, CourseGrid& g) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const int nu = g.units(), nr = g.rows();
    g.status.assign(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nr), kOutside);

    // Scanline per row: boundary chords met inside the row make units partial; elsewhere the
    // mid-line's crossings say inside or outside.
    struct Chord {
        Point a, b;
    };
    std::vector<Chord> chords;
    for (const std::vector<Point>& loop : f.loops)
        for (std::size_t k = 0; k < loop.size(); ++k)
            chords.push_back({loop[k], loop[(k + 1) % loop.size()]});
    std::vector<std::vector<int>> by_row(static_cast<std::size_t>(nr));
    for (std::size_t c = 0; c < chords.size(); ++c) {
        double y0 = std::min(chords[c].a.y, chords[c].b.y),
               y1 = std::max(chords[c].a.y, chords[c].b.y);
        int r0 = std::max(0, g.row_at(y0));
        int r1 = g.row_at(y1);
        if (r1 < 0) r1 = nr - 1;
        for (int r = r0; r <= r1; ++r)
            by_row[static_cast<std::size_t>(r)].push_back(static_cast<int>(c));
    }
    const double eps =
        1e-9 * std::max({1.0, std::abs(f.bounds.x1), std::abs(f.bounds.y1), std::abs(f.bounds.x0)});
    std::vector<double> crossings;
    std::vector<std::uint8_t> partial(static_cast<std::size_t>(nu));
    for (int r = 0; r < nr; ++r) {
        double y0 = g.ys[r], y1 = g.ys[r + 1], ym = (y0 + y1) / 2;
        crossings.clear();
        std::fill(partial.begin(), partial.end(), 0);
        for (int c : by_row[static_cast<std::size_t>(r)]) {
            Point a = chords[static_cast<std::size_t>(c)].a,
                  b = chords[static_cast<std::size_t>(c)].b;
            if ((a.y > ym) != (b.y > ym))
                crossings.push_back(a.x + (ym - a.y) * (b.x - a.x) / (b.y - a.y));
            // The chord's part strictly inside the row.
            double lo = std::max(std::min(a.y, b.y), y0), hi = std::min(std::max(a.y, b.y), y1);
            if (hi - lo <= eps && !(std::min(a.y, b.y) > y0 + eps && std::max(a.y, b.y) < y1 - eps))
                continue;
            double xa, xb;
            if (std::abs(b.y - a.y) < 1e-300) {
                xa = std::min(a.x, b.x), xb = std::max(a.x, b.x);
            } else {
                double ta = (lo - a.y) / (b.y - a.y), tb = (hi - a.y) / (b.y - a.y);
                xa = a.x + ta * (b.x - a.x);
                xb = a.x + tb * (b.x - a.x);
                if (xa > xb) std::swap(xa, xb);
            }
            int u0 = std::max(0, g.unit_at(xa)), u1 = g.unit_at(xb);
            if (u1 < 0) u1 = nu - 1;
            for (int u = u0; u <= u1; ++u)
                if (xa < g.xs[u + 1] - eps && xb > g.xs[u] + eps)
                    partial[static_cast<std::size_t>(u)] = 1;
        }
        std::sort(crossings.begin(), crossings.end());
        std::size_t next = 0;
        bool inside = false;
        for (int u = 0; u < nu; ++u) {
            double xm = (g.xs[u] + g.xs[u + 1]) / 2;
            while (next < crossings.size() && crossings[next] <= xm) {
                inside = !inside;
                ++next;
            }
            std::uint8_t& s = g.status[static_cast<std::size_t>(r) * static_cast<std::size_t>(nu) +
                                       static_cast<std::size_t>(u)];
            s = partial[static_cast<std::size_t>(u)] ? kPartial : (inside ? kFull : kOutside);
        }
    }
}

}  // namespace acanthus::cells::detail
