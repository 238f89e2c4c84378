// Lintels: one stone in the courses (or the ashlar rows of a stone wall) over an opening's
// straight head, bearing past each jamb. The head's corners lay it too (corners come first), so
// no corner brick notches it.
#include "lintel.hpp"

#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "ashlar_grid.hpp"
#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"
#include "head_edge.hpp"

namespace acanthus::cells {

namespace detail {

bool lintel_span(const Edge& e, const CourseGrid& grid, double unit, int bearing, int courses,
                 int& top, int& bottom, int& u0, int& u1) {
    const Point above = e.at(e.length / 2) + e.inward(e.length / 2) * (0.25 * unit);
    bottom = grid.row_at(above.y);
    const double tiny = 1e-6 * e.bounds.width();
    u0 = grid.unit_at(e.bounds.x0 + tiny), u1 = grid.unit_at(e.bounds.x1 - tiny);
    if (bottom < 0 || u0 < 0 || u1 < 0) return false;
    u0 = std::max(0, u0 - bearing);
    u1 = std::min(grid.units(), u1 + 1 + bearing);
    // As deep as `courses` courses (rows above have lower indices in SVG numbers).
    top = std::max(0, bottom - std::max(1, courses) + 1);
    return true;
}

void set_lintel_rows(const Facade& facade, int face, const Options& o, BrickLayout& layout) {
    struct Laid {
        int head, top, bottom;
    };
    std::vector<Laid> laid;
    for (int h : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& e = facade.edges()[static_cast<std::size_t>(h)];
        if (e.arc || e.part != Part::top || !e.opening) continue;
        int top = 0, bottom = 0, u0 = 0, u1 = 0;
        if (!lintel_span(e, layout.grid, o.brick_height, o.lintel_bearing, o.lintel_courses, top,
                         bottom, u0, u1))
            continue;
        // A bearing moved by a quarter brick (framed_moves.hpp), never under the least a lintel
        // bears on (to the drawn end: half a joint inside the claim).
        const double least = kMinBearing * o.brick_length + 0.5 * o.mortar;
        const int l = u0 - layout.moves.count(layout.moves.bearing, h, 0);
        const int r = u1 + layout.moves.count(layout.moves.bearing, h, 1);
        if (l >= 0 && e.bounds.x0 - layout.grid.xs[static_cast<std::size_t>(l)] >= least) u0 = l;
        if (r <= layout.grid.units() &&
            layout.grid.xs[static_cast<std::size_t>(r)] - e.bounds.x1 >= least)
            u1 = r;
        // Two lintels whose bearings meet over a pier (in the same courses) are one stone over
        // both openings: butted there, their joint stood under a head joint of the course above.
        for (const Laid& prev : laid) {
            const auto [a, b] = layout.lintel_units[prev.head];
            if (prev.top != top || prev.bottom != bottom || a > u1 || b < u0) continue;
            u0 = std::min(u0, a), u1 = std::max(u1, b);
        }
        for (const Laid& prev : laid) {
            auto& [a, b] = layout.lintel_units[prev.head];
            if (prev.top == top && prev.bottom == bottom && a >= u0 && b <= u1) a = u0, b = u1;
        }
        laid.push_back({h, top, bottom});
        layout.lintel_units[h] = {u0, u1};
        for (int row = top; row <= bottom; ++row) {
            auto& pieces = layout.rows[static_cast<std::size_t>(row)];
            // Within the run the head's middle is in (a lintel never reaches past the wall).
            int lo = u0, hi = u1;
            while (lo < hi && layout.grid.at(row, lo) == kOutside) ++lo;
            while (hi > lo && layout.grid.at(row, hi - 1) == kOutside) --hi;
            if (hi - lo < 1) continue;
            std::vector<Piece> out = cut_out(pieces, lo, hi);
            Piece l{lo, hi - lo, false, false};
            l.head = true;
            out.push_back(l);
            std::sort(out.begin(), out.end(),
                      [](const Piece& x, const Piece& y) { return x.start < y.start; });
            // A one-unit remnant beside the lintel joins its neighbour away from it.
            for (std::size_t k = 0; k < out.size(); ++k) {
                if (out[k].fixed() || out[k].length != 1 || out[k].sill) continue;
                const bool after = k > 0 && out[k - 1].head;
                const bool before = k + 1 < out.size() && out[k + 1].head;
                if (!after && !before) continue;
                const std::size_t n = after ? k + 1 : k - 1;
                if ((!after && k == 0) || n >= out.size() || out[n].fixed() || out[n].sill)
                    continue;
                const bool touching = after ? out[k].start + 1 == out[n].start
                                            : out[n].start + out[n].length == out[k].start;
                if (!touching || out[k].length + out[n].length > 4) continue;
                const int left = std::min(out[k].start, out[n].start);
                out[k] = {left, out[k].length + out[n].length, true, false};
                out.erase(out.begin() + static_cast<std::ptrdiff_t>(n));
                if (n < k) --k;
            }
            pieces = std::move(out);
        }
    }
}

bool laid_lintel(Context& c, const Edge& e, Rect& r, int* course) {
    // On the grid the wall is laid on: the bricks' courses, or the ashlar's units in stone.
    const Options& o = c.options();
    const CourseGrid& grid = c.data().stone ? ashlar_grid(c, e.face) : brick_layout(c, e.face).grid;
    const double unit = c.data().stone ? ashlar_unit(o) : o.brick_height;
    // Bearing in quarter bricks; in stone, as many units as cover it.
    int b = o.lintel_bearing;
    if (c.data().stone)
        b = std::max(1, static_cast<int>(std::ceil(
                            b * (o.brick_length + o.mortar) / 4 / ashlar_unit(o) - 1e-9)));
    int top = 0, row = 0, u0 = 0, u1 = 0;
    if (!lintel_span(e, grid, unit, b, o.lintel_courses, top, row, u0, u1)) return false;
    // Bonded into the courses (the framed tree): as long as the layout laid it.
    if (!c.data().stone && c.data().lintels) {
        const auto& spans = brick_layout(c, e.face).lintel_units;
        if (auto it = spans.find(static_cast<int>(&e - c.facade().edges().data()));
            it != spans.end())
            u0 = it->second.first, u1 = it->second.second;
    }
    r = grid.cell(row, u0, u1);
    r.y0 = grid.ys[static_cast<std::size_t>(top)];
    if (course) *course = grid.course(row);
    return true;
}

}  // namespace detail

Generator lintel() {
    return [](const FeatureRef& f, Context& c) {
        const int head = detail::head_edge(c.facade(), f);
        if (head < 0) return;
        Rect r;
        int course = 0;
        if (detail::laid_lintel(c, c.facade().edges()[static_cast<std::size_t>(head)], r, &course))
            c.place(detail::polygon_of(r), course);
    };
}

}  // namespace acanthus::cells
