#include "brick_grid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "bond.hpp"
#include "quoin_rows.hpp"

namespace acanthus::cells::detail {

namespace {

// Unit lines across [x0, x1]: stretched when each stretcher's head joint moves within `tol`.
std::vector<double> unit_lines(double x0, double x1, double q, double tol) {
    const double w = x1 - x0;
    const int n = std::max(1, static_cast<int>(std::lround(w / q)));
    std::vector<double> xs;
    if (4 * std::abs(w - n * q) / n <= tol * (1 + 1e-9)) {
        for (int k = 0; k <= n; ++k) xs.push_back(x0 + w * k / n);
        xs.back() = x1;
        return xs;
    }
    const int whole = static_cast<int>(std::ceil(w / q - 1e-9));
    for (int k = 0; k <= whole; ++k) xs.push_back(x0 + k * q);  // the last one past x1: cut
    return xs;
}

// Plumb edges of the face (jambs, reveals, the wall's ends) by x, each weighted by its height:
// about the number of pieces a course line missing it would cut. Those within `merge` of each
// other are one, at the heavier's x. `sides`: kOpensRight for an opening's left jamb (the wall
// to its left), kOpensLeft for its right one.
constexpr int kOpensRight = 1, kOpensLeft = 2;
struct Mark {
    double x = 0, weight = 0;
    int sides = 0;
};
// An opening's plumb side under an arc (a round, pointed or segmental head).
bool under_arc(const Facade& facade, const Edge& edge) {
    for (int k : {edge.corner_start, edge.corner_end}) {
        if (k < 0) continue;
        const Corner& c = facade.corners()[static_cast<std::size_t>(k)];
        for (int o : {c.edge_in, c.edge_out})
            if (o >= 0 && facade.edges()[static_cast<std::size_t>(o)].arc) return true;
    }
    return false;
}

std::vector<Mark> jambs(const Facade& facade, const Face& f, double merge, bool arched) {
    std::vector<Mark> out;
    for (int e : f.edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (edge.arc || edge.closed || edge.bounds.height() <= 0) continue;
        if (edge.bounds.width() > 1e-9 * std::max(1.0, std::abs(edge.bounds.x1))) continue;
        if (!arched && edge.opening && under_arc(facade, edge)) continue;
        // A segmental arch's jamb too: the lines reach it as a mason plumbs the perpends from
        // the jamb, and the skewback over it steps with the bond as laid.
        const int sides = !edge.opening                        ? 0
                          : edge.inward(edge.length / 2).x > 0 ? kOpensLeft
                                                               : kOpensRight;
        out.push_back({edge.bounds.x0, edge.bounds.height(), sides});
    }
    std::sort(out.begin(), out.end(), [](const Mark& a, const Mark& b) { return a.x < b.x; });
    std::vector<Mark> merged;
    for (const Mark& k : out) {
        if (!merged.empty() && k.x - merged.back().x <= merge) {
            if (k.weight > merged.back().weight) merged.back().x = k.x;
            merged.back().weight += k.weight;
            merged.back().sides |= k.sides;
        } else {
            merged.push_back(k);
        }
    }
    return merged;
}

// Unit lines set out from the jambs, as a mason sets out perpends: through as many jambs as can
// be reached (by their weight) with every head joint between two of them opened or closed by no
// more than `tol`, the units stretched evenly; past the last one reached, nominal units to the
// wall's right end, cut there. A jamb no line reaches cuts the bricks beside it. Across an
// opening whose width is no whole number of quarters (`breaks`), the jamb beyond is reached with
// nominal units and one odd one within the opening (a bond break, `wide`: a quarter more than
// the rest) where that reaches more; the layout keeps the breaks only where they leave fewer odd
// pieces the geometry does not force (brick_layout.cpp).
std::vector<double> set_out_lines(double x0, double x1, double q, double tol,
                                  const std::vector<Mark>& marks, bool breaks, bool wide,
                                  std::vector<CourseGrid::Break>& out_breaks) {
    std::vector<double> at{x0}, weight{0};
    std::vector<int> sides{0};
    for (const Mark& k : marks)
        if (k.x > x0 + q / 2 && k.x <= x1)
            at.push_back(k.x), weight.push_back(k.weight), sides.push_back(k.sides);
    if (at.back() < x1) at.push_back(x1), weight.push_back(0), sides.push_back(0);
    weight.back() += 1e-9;  // a wall's end within reach is reached, as unit_lines does
    // The bricks at both jambs stand flush with them (brick_layout.cpp, set_joints): the head
    // joints between take up the difference, and a course of n units has at least
    // ceil(n / 4) - 1 of them.
    auto units = [&](double w) {
        const int n = static_cast<int>(std::lround(w / q));
        const double off = std::abs(w - n * q), slack = 1e-9 * std::max(1.0, w);
        if (n < 1) return 0;
        return off <= slack || off <= tol * ((n + 3) / 4 - 1) + slack ? n : 0;
    };
    // An opening's left jamb and a right jamb with no opening's left jamb between (the odd
    // unit, in the middle, stands within an opening), wide enough for it and its neighbours.
    auto can_break = [&](std::size_t j, std::size_t i) {
        if (!breaks || !(sides[j] & kOpensRight) || !(sides[i] & kOpensLeft) ||
            at[i] - at[j] < 3 * q || units(at[i] - at[j]) > 0)
            return false;
        for (std::size_t k = j + 1; k < i; ++k)
            if (sides[k] & kOpensRight) return false;
        return true;
    };
    const std::size_t m = at.size();
    std::vector<double> best(m, -1);
    std::vector<std::size_t> from(m, 0);
    std::vector<char> broken(m, 0);
    best[0] = 0;
    for (std::size_t i = 1; i < m; ++i)
        for (std::size_t j = 0; j < i; ++j) {
            if (best[j] < 0) continue;
            if (units(at[i] - at[j]) > 0 && best[j] + weight[i] > best[i])
                best[i] = best[j] + weight[i], from[i] = j, broken[i] = 0;
            if (!can_break(j, i)) continue;
            if (best[j] + weight[i] > best[i])
                best[i] = best[j] + weight[i], from[i] = j, broken[i] = 1;
        }
    std::size_t last = 0;
    for (std::size_t i = 1; i < m; ++i)
        if (best[i] > best[last]) last = i;
    std::vector<std::size_t> chain{last};
    while (chain.back() != 0) chain.push_back(from[chain.back()]);
    std::vector<double> xs{x0};
    for (std::size_t k = chain.size() - 1; k-- > 0;) {
        const double a = at[chain[k + 1]], b = at[chain[k]];
        if (broken[chain[k]]) {
            // Nominal units but one, the odd one in the middle (set_breaks moves it).
            int n = static_cast<int>(std::floor((b - a) / q));
            double odd = b - a - n * q;
            if (wide) odd += q, n -= 1;
            const int count = n + 1, mid = count / 2;
            out_breaks.push_back({static_cast<int>(xs.size()) - 1, count, odd});
            for (int t = 1; t < count; ++t) xs.push_back(a + t * q + (t > mid ? odd - q : 0));
            xs.push_back(b);
            continue;
        }
        const int n = units(b - a);
        for (int t = 1; t < n; ++t) xs.push_back(a + (b - a) * t / n);
        xs.push_back(b);
    }
    if (xs.back() < x1) {
        const double a = xs.back();
        const int whole = static_cast<int>(std::ceil((x1 - a) / q - 1e-9));
        for (int k = 1; k <= whole; ++k) xs.push_back(a + k * q);  // the last one past x1: cut
    }
    return xs;
}

// The cut course at the top of a wall whose whole courses leave `rest` (0 < rest < g): one,
// or two of (g + rest) / 2 when one would be thinner than half a course. Lines from `at` up.
void cut_courses(double at, double rest, double g, int whole, std::vector<double>& down) {
    if (rest >= g / 2 || whole == 0) {
        down.push_back(at - rest);
        return;
    }
    down.pop_back();  // the last whole course becomes part of the two
    down.push_back(at + g - (g + rest) / 2);
    down.push_back(at - rest);
}

// The courses from a level edge at `anchor` up to the wall's level top `w` above it, which whole
// courses do not reach within the tolerance: whole courses, then one cut course right under the
// top, where the wall plate or coping hides it. Where the cut course would be thinner than half
// a course, the joints of the whole courses close (each by no more than the tolerance) to make
// it thicker; a mason lays one cut course, not two.
void top_courses(double anchor, double w, double g, double tol, std::vector<double>& down) {
    const int whole = static_cast<int>(std::floor(w / g));
    const double rest = w - whole * g;
    if (whole == 0) {
        down.push_back(anchor - w);
        return;
    }
    const double cut = std::clamp(g / 2, rest, rest + whole * tol);
    if (cut < g / 4) {  // too thin even so: it and the last whole course cut as two
        for (int k = 1; k <= whole; ++k) down.push_back(anchor - k * g);
        cut_courses(anchor - whole * g, rest, g, whole, down);
        return;
    }
    const double pitch = (w - cut) / whole;
    for (int k = 1; k <= whole; ++k) down.push_back(anchor - k * pitch);
    down.push_back(anchor - w);
}

}  // namespace

CourseGrid make_brick_grid(const Facade& facade, int face, const Options& o, bool set_out,
                           bool breaks, bool arched) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const double q = (o.brick_length + o.mortar) / 4, g = o.brick_height + o.mortar;
    const double tol = o.joint_tolerance;
    const double eps = 1e-9 * std::max({1.0, std::abs(f.bounds.x0), std::abs(f.bounds.x1),
                                        std::abs(f.bounds.y0), std::abs(f.bounds.y1)});
    CourseGrid grid;
    // A face that turns a building corner keeps the bond set from the corner (quoin_rows.hpp).
    if (has_building_corner(facade, face)) set_out = false;
    grid.xs =
        set_out ? set_out_lines(f.bounds.x0, f.bounds.x1, q, tol, jambs(facade, f, tol / 3, arched),
                                breaks, o.bond == Bond::header, grid.breaks)
                : unit_lines(f.bounds.x0, f.bounds.x1, q, tol);

    // Level edges, bottom first (SVG: larger y lower), closer than half a course merged.
    std::vector<double> level;
    for (int e : f.edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (!edge.arc && !edge.closed && edge.bounds.height() <= eps)
            level.push_back(edge.bounds.y0);
    }
    std::sort(level.rbegin(), level.rend());
    std::vector<double> kept;
    for (double y : level)
        if (kept.empty() || kept.back() - y >= g / 2) kept.push_back(y);
    // A level top closer than half a course to the line below it wins: the wall's top is laid to.
    if (kept.size() >= 2 && level.back() < kept.back() && level.back() <= f.bounds.y0 + eps)
        kept.back() = level.back();
    if (kept.empty()) kept.push_back(f.bounds.y1);

    // Courses on gauge from the bottom, as the mason's gauge rod runs. A level edge is a course
    // line when the courses since the last one reach it with no bed joint moved by more than the
    // tolerance; otherwise it falls within a course and the bricks there are cut to it (at that
    // opening only). A level top out of reach gets the one cut course, right under it, where
    // the wall plate or coping hides it.
    std::vector<double> down;  // course lines, bottom first
    double y = kept.front();
    while (y < f.bounds.y1 - eps) y += g;  // below the lowest level edge: whole courses
    for (double at = y; at > kept.front() + eps; at -= g) down.push_back(at);
    down.push_back(kept.front());
    double anchor = kept.front();
    const bool level_top = kept.back() <= f.bounds.y0 + eps && kept.size() >= 2;
    // At a building corner the courses turn onto the next elevation: both faces keep the pure
    // gauge from the ground (the mason's one gauge rod) up to their top course.
    const bool corner = has_building_corner(facade, face);
    for (std::size_t i = 1; i < kept.size(); ++i) {
        if (corner && !(level_top && i + 1 == kept.size())) continue;
        const double w = anchor - kept[i];
        if (corner) {
            const int whole = static_cast<int>(std::floor(w / g + 1e-9));
            const double rest = w - whole * g;
            const int n = rest <= tol ? whole : g - rest <= tol ? whole + 1 : -1;
            if (n >= 1) {  // the top course alone takes up the rest, within the tolerance
                for (int k = 1; k < n; ++k) down.push_back(anchor - k * g);
            } else {
                for (int k = 1; k <= whole; ++k) down.push_back(anchor - k * g);
                cut_courses(anchor - whole * g, rest, g, whole, down);
                down.pop_back();
            }
            down.push_back(anchor = kept[i]);
            continue;
        }
        const int n = static_cast<int>(std::lround(w / g));
        if (n >= 1 && std::abs(w - n * g) <= tol * n * (1 + 1e-9)) {
            for (int k = 1; k < n; ++k) down.push_back(anchor - w * k / n);
            down.push_back(anchor = kept[i]);
        } else if (level_top && i + 1 == kept.size()) {
            top_courses(anchor, w, g, tol, down);
            anchor = kept[i];
        }
    }
    for (double at = anchor; at > f.bounds.y0 + eps;) down.push_back(at -= g);  // to the top
    grid.ys.assign(down.rbegin(), down.rend());
    classify_units(facade, face, grid);
    return grid;
}

bool set_breaks(const Facade& facade, int face, const BondPattern& bond, int phase, CourseGrid& g) {
    if (g.breaks.empty()) return false;
    // Head joints on line i (mod the period) in `course`.
    const int period = bond.period();
    auto joint = [&](int course, int i) {
        const auto lengths = bond.lengths(course);
        int at = bond.offset(course) + phase;
        for (int k = 0; k < 2 * period; ++k) {
            if (((i - at) % period + period) % period == 0) return true;
            at += lengths[static_cast<std::size_t>(k) % lengths.size()];
        }
        return false;
    };
    // An odd unit narrower than a quarter brick keeps off lines i and i + 1 both holding a joint
    // in consecutive courses: a straight joint up its width.
    for (const CourseGrid::Break& b : g.breaks) {
        const double a = g.xs[static_cast<std::size_t>(b.first)];
        const double step = (g.xs[static_cast<std::size_t>(b.first + b.count)] - a - b.odd) /
                            std::max(1, b.count - 1);
        auto safe = [&](int u) {
            if (bond.bond == Bond::stack || b.odd >= step) return true;
            for (int c = 0; c < 4; ++c)
                if ((joint(c, u) && joint(c + 1, u + 1)) || (joint(c, u + 1) && joint(c + 1, u)))
                    return false;
            return true;
        };
        // The middle unit, or the nearest safe one.
        const int mid = b.count / 2;
        int at = -1;
        for (int d = 0; d < b.count && at < 0; ++d)
            for (int u : {mid - d, mid + d})
                if (at < 0 && u >= 0 && u < b.count && safe(b.first + u)) at = u;
        if (at < 0) at = mid;
        for (int t = 1; t < b.count; ++t)
            g.xs[static_cast<std::size_t>(b.first + t)] =
                a + t * step + (t > at ? b.odd - step : 0);
    }
    classify_units(facade, face, g);
    return true;
}

}  // namespace acanthus::cells::detail
