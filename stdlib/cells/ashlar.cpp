// Random ashlar [5.2] on the grid tool's small units. By default (AshlarMethod::rules) convex
// corners get a stone two units long and the face's joint-rules layout (ashlar_rules.cpp) takes
// every other unit, the edges' too, so its rules hold against every stone. With
// AshlarMethod::merge, the paper's: corners one unit stone, edges stones of random length
// (alternating depth up vertical edges), the face a stone per free unit merged at random
// (ashlar_merge.cpp).
#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/head_joints.hpp>
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "ashlar_grid.hpp"
#include "ashlar_merge.hpp"
#include "ashlar_rules.hpp"
#include "clip.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

namespace {

using detail::CourseGrid;

bool inside(const std::vector<Point>& poly, Point p) {  // even-odd
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < poly[j].x + (p.y - poly[j].y) * (poly[i].x - poly[j].x) / (poly[i].y - poly[j].y))
            in = !in;
    return in;
}

// Along other edges: runs of units in a row cut into stones of random length (`shortest` and up).
void edge_runs(const std::vector<std::pair<int, int>>& cells, const CourseGrid& grid, int shortest,
               Context& c) {
    const int longest = std::max(1, c.options().ashlar_max_width);
    for (std::size_t i = 0; i < cells.size();) {
        int len = static_cast<int>(c.random().uniform_int(std::min(shortest, longest), longest));
        std::size_t j = i + 1;
        while (j < cells.size() && j - i < static_cast<std::size_t>(len) &&
               cells[j].first == cells[i].first &&
               std::abs(cells[j].second - cells[j - 1].second) == 1)
            ++j;
        int a = std::min(cells[i].second, cells[j - 1].second);
        int b = std::max(cells[i].second, cells[j - 1].second) + 1;
        c.place(detail::polygon_of(grid.cell(cells[i].first, a, b)), grid.course(cells[i].first));
        i = j;
    }
}

// The share of unit `r` still free wall.
double wall_part(const FaceOccupancy& occupancy, Rect r) {
    double a = 0;
    for (const std::vector<Point>& p : occupancy.free_part(detail::polygon_of(r)))
        for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
            a += (p[j].x - p[i].x) * (p[j].y + p[i].y) / 2;
    return std::abs(a) / ((r.x1 - r.x0) * (r.y1 - r.y0));
}

// The rules layout of a face: every unit its centre puts in a stone laid before is held by that
// stone; the free ones are laid by the rules; stones over units the face only partly holds, or
// others claimed in part, are clipped.
void rules_face(int face, const CourseGrid& grid, Context& c) {
    const Facade& facade = c.facade();
    const Options& o = c.options();
    FaceOccupancy& occupancy = c.face_occupancy(face);
    const std::vector<Cell>& laid = c.cells();
    const double h = o.mortar / 2;
    // Per unit: the rectangular cell k holding it (k), one of another shape (-2 - k), or -1.
    std::vector<int> owner(static_cast<std::size_t>(grid.rows() * grid.units()), -1);
    // Rectangular cells a mason reads as unit squares (under a unit and a half each way).
    const double square = 1.5 * detail::ashlar_unit(o);
    std::vector<char> small(laid.size(), 0);
    for (std::size_t k = 0; k < laid.size(); ++k) {
        const Cell& cell = laid[k];
        if (detail::face_of(facade, {cell.feature, cell.feature_index}) != face) continue;
        Rect b = detail::bounds_of(cell.polygon), r;
        // Read as the mason reads it: a stone clipped to a jamb keeps its rounding noise.
        const bool rect = is_rect(cell.polygon, r);
        b = {b.x0 - h, b.y0 - h, b.x1 + h, b.y1 + h};
        small[k] = rect && b.width() < square && b.height() < square;
        const int r0 = std::max(0, grid.row_at(b.y0)), u0 = std::max(0, grid.unit_at(b.x0));
        int r1 = grid.row_at(b.y1), u1 = grid.unit_at(b.x1);
        if (r1 < 0) r1 = grid.rows() - 1;
        if (u1 < 0) u1 = grid.units() - 1;
        for (int row = r0; row <= r1; ++row)
            for (int u = u0; u <= u1; ++u) {
                const Point m = grid.cell(row, u, u + 1).center();
                if (rect ? b.contains(m) : inside(cell.polygon, m))
                    owner[static_cast<std::size_t>(row * grid.units() + u)] =
                        rect ? static_cast<int>(k) : -2 - static_cast<int>(k);
            }
    }
    // A pier one unit wide between two stones laid before over the same rows (two lintels'
    // bearings, two sills' lugs): a stone of its full height, as a jamb stone, since any stone
    // there stands on end; its units are held like those of a stone laid before.
    const auto held_at = [&](int row, int u) {
        return u < 0 || u >= grid.units() ? -1
                                          : owner[static_cast<std::size_t>(row * grid.units() + u)];
    };
    const auto spans = [&](int k, int u, int r0, int r1) {  // stone k holds exactly rows r0..r1
        return k != -1 && (r0 == 0 || held_at(r0 - 1, u) != k) &&
               (r1 + 1 == grid.rows() || held_at(r1 + 1, u) != k);
    };
    std::vector<Rect> piers;
    for (int u = 1; u + 1 < grid.units(); ++u)
        for (int row = 0; row < grid.rows();) {
            const int left = held_at(row, u - 1), right = held_at(row, u + 1);
            int end = row;
            while (end < grid.rows() && held_at(end, u) == -1 && grid.at(end, u) == detail::kFull &&
                   held_at(end, u - 1) == left && held_at(end, u + 1) == right)
                ++end;
            if (end > row && left != -1 && right != -1 && left != right &&
                spans(left, u - 1, row, end - 1) && spans(right, u + 1, row, end - 1)) {
                const Rect r{grid.xs[static_cast<std::size_t>(u)],
                             grid.ys[static_cast<std::size_t>(row)],
                             grid.xs[static_cast<std::size_t>(u + 1)],
                             grid.ys[static_cast<std::size_t>(end)]};
                if (wall_part(occupancy, r) > 0.5) piers.push_back(r);
            }
            row = std::max(end, row + 1);
        }
    detail::AshlarRules rules(grid, o.ashlar_max_width, o.ashlar_max_height, o.ashlar_max_seam,
                              static_cast<int>(laid.size() + piers.size()) + 1, square);
    for (std::size_t i = 0; i < piers.size(); ++i) {
        const Point m = piers[i].center();
        const int u = grid.unit_at(m.x), pier = static_cast<int>(laid.size() + i);
        for (int row = grid.row_at(piers[i].y0 + 1e-6);
             row >= 0 && row < grid.rows() &&
             grid.ys[static_cast<std::size_t>(row)] < piers[i].y1 - 1e-6;
             ++row) {
            owner[static_cast<std::size_t>(row * grid.units() + u)] = pier;
        }
    }
    const double tiny = 1e-4 * std::min(grid.xs[1] - grid.xs[0], grid.ys[1] - grid.ys[0]);
    std::vector<std::pair<int, int>> lone;  // units laid as a clipped stone each
    for (int row = 0; row < grid.rows(); ++row)
        for (int u = 0; u < grid.units(); ++u) {
            const auto s = grid.at(row, u);
            const int held = owner[static_cast<std::size_t>(row * grid.units() + u)];
            if (s == detail::kOutside) continue;
            const Rect unit = grid.cell(row, u, u + 1);
            if (held <= -2) {
                // What a voussoir or skewback leaves of a unit holding its centre: a plumb strip
                // laid alone would stand on end, so one worth a stone joins one of the layout,
                // cut to the skewback, and counts as narrow as it is. Pieces cut to a curve are
                // laid alone, as before. A strip is read by its area against its box (a corner of
                // a voussoir's extrados may notch its top), also in a unit the opening reaches
                // into (beside a segmental arch's skewback at its springing, a strip 1.4 cm wide
                // stood on end).
                const std::vector<std::vector<Point>> left =
                    occupancy.free_part(detail::polygon_of(unit));
                const Rect strip = left.size() == 1 ? detail::bounds_of(left[0]) : Rect{};
                if (const double part = wall_part(occupancy, unit);
                    part > 0.1 && left.size() == 1 &&
                    std::abs(detail::area_of(left[0])) >= 0.8 * strip.width() * strip.height() &&
                    strip.y1 - strip.y0 > 1.1 * (strip.x1 - strip.x0)) {
                    rules.free(row, u);
                    rules.cut(row, u, part);
                    continue;
                }
            }
            if (held >= 0 || held <= -2) {
                rules.hold(row, u, held >= 0 ? held : -2 - held, held <= -2,
                           held >= 0 && static_cast<std::size_t>(held) < laid.size() &&
                               small[static_cast<std::size_t>(held)]);
                // What a voussoir leaves of the unit is cut to its extrados.
                if (held <= -2) lone.emplace_back(row, u);
                continue;
            }
            const Point m = unit.center();
            if (s == detail::kFull && occupancy.rect_is_free(unit)) {
                rules.free(row, u);
                continue;
            }
            const bool centre = !occupancy
                                     .free_part(detail::polygon_of(
                                         {m.x - tiny, m.y - tiny, m.x + tiny, m.y + tiny}))
                                     .empty();
            if (const double part = wall_part(occupancy, unit); centre || part > 0.01) {
                // A strip of wall beside a jamb or a skewback off the grid's lines: laid one
                // piece a row it would stand on end, its beds meeting the next column's four
                // ways; it joins a stone of the layout, cut to the jamb, and counts as narrow
                // as what is left of it.
                rules.free(row, u);
                rules.cut(row, u, std::min(1.0, part));
            } else
                lone.emplace_back(row, u);
        }
    for (auto [row, u] : lone)
        c.place(detail::polygon_of(grid.cell(row, u, u + 1)), grid.course(row));
    const double inset = 0.25 * std::min(grid.xs[1] - grid.xs[0], grid.ys[1] - grid.ys[0]);
    for (int e : facade.faces()[static_cast<std::size_t>(face)].edges) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (edge.arc || !edge.vertical()) continue;
        // Only a unit whose side is the jamb's joint: one beside a strip cut to the jamb would
        // stand on end away from it.
        const double x = edge.bounds.x0;
        detail::walk_edge(edge, inset, inset, [&](Point p, double) {
            const int row = grid.row_at(p.y), u = grid.unit_at(p.x);
            if (row >= 0 && u >= 0 &&
                std::min(std::abs(grid.xs[static_cast<std::size_t>(u)] - x),
                         std::abs(grid.xs[static_cast<std::size_t>(u + 1)] - x)) < o.mortar)
                rules.jamb(row, u);
        });
    }
    rules.lay(c.random());
    c.data().ashlar_rounds = std::max(c.data().ashlar_rounds, rules.rounds());
    for (const Rect& r : piers)
        c.place(detail::polygon_of(r), grid.course(grid.row_at(r.y1 - 1e-6)));
    for (const detail::Stone& s : rules.stones()) {
        const Rect r{grid.xs[s.unit], grid.ys[s.row], grid.xs[s.unit + s.w], grid.ys[s.row + s.h]};
        bool full = true;
        for (int row = s.row; row < s.row + s.h; ++row)
            for (int u = s.unit; u < s.unit + s.w; ++u) full &= grid.at(row, u) == detail::kFull;
        if (full && occupancy.rect_is_free(r))
            c.place_free_rect(r, grid.course(s.row + s.h - 1));
        else
            c.place(detail::polygon_of(r), grid.course(s.row + s.h - 1));
    }
}

}  // namespace

Generator ashlar() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        const Options& o = c.options();
        const bool rules = o.ashlar_method == AshlarMethod::rules;
        int face = detail::face_of(facade, f);
        const CourseGrid& grid = detail::ashlar_grid(c, face);
        const double inset = 0.25 * detail::ashlar_unit(o);
        if (f.kind == FeatureKind::corner) {
            const Corner& k = facade.corners()[static_cast<std::size_t>(f.index)];
            if (rules && !k.convex) return;  // the face's layout takes it
            // A corner's stone: its row and units, two long along the course into the wall
            // with the joint rules.
            auto corner_stone = [&](const Corner& at, int& row, int& u0, int& u1) {
                const Point p = detail::inside_corner(at, inset);
                row = grid.row_at(p.y);
                const int u = grid.unit_at(p.x);
                if (row < 0 || u < 0) return false;
                u0 = u, u1 = u + 1;
                const int v = p.x >= at.position.x ? u + 1 : u - 1;
                if (rules && v >= 0 && v < grid.units() && grid.at(row, v) != detail::kOutside)
                    u0 = std::min(u, v), u1 = std::max(u, v) + 1;
                return true;
            };
            int row = 0, u0 = 0, u1 = 0;
            if (!corner_stone(k, row, u0, u1)) return;
            // One unit left between this stone and another corner's to its right in the row
            // (the wall's end and a door's jamb at the ground): that unit alone would stand on
            // end, so this stone takes it.
            if (rules && u1 - u0 < std::max(1, o.ashlar_max_width) && u1 < grid.units() &&
                grid.at(row, u1) == detail::kFull)
                for (int j : facade.faces()[static_cast<std::size_t>(face)].corners) {
                    const Corner& other = facade.corners()[static_cast<std::size_t>(j)];
                    int r2 = 0, a = 0, b = 0;
                    if (j != f.index && other.convex && corner_stone(other, r2, a, b) &&
                        r2 == row && a == u1 + 1) {
                        ++u1;
                        break;
                    }
                }
            c.place(detail::polygon_of(grid.cell(row, u0, u1)), grid.course(row));
            return;
        }
        if (f.kind == FeatureKind::edge) {
            const Edge& e = facade.edges()[static_cast<std::size_t>(f.index)];
            if (rules) return;  // the face's layout takes the edges' units (see rules_face)
            std::set<std::pair<int, int>> seen;
            std::vector<std::pair<int, int>> cells;
            detail::walk_edge(e, inset, inset, [&](Point p, double s) {
                int row = grid.row_at(p.y), u = grid.unit_at(p.x);
                if (row < 0 || u < 0) return;
                if (e.vertical()) {  // one stone per course, two units deep and one by turns
                    if (!seen.insert({row, -1}).second) return;
                    int depth = grid.course(row) % 2 == 0 ? 2 : 1;
                    bool right = e.inward(s).x > 0;
                    int u0 = std::max(0, right ? u : u - depth + 1);
                    int u1 = std::min(grid.units(), right ? u + depth : u + 1);
                    c.place(detail::polygon_of(grid.cell(row, u0, u1)), grid.course(row));
                } else if (seen.insert({row, u}).second) {
                    cells.emplace_back(row, u);
                }
            });
            edge_runs(cells, grid, rules ? 2 : 1, c);
            return;
        }
        if (rules) {
            rules_face(face, grid, c);
            return;
        }
        // The paper's: a stone per free unit merged at random; units the face only partly
        // holds, or that others claimed in part, a stone each, clipped.
        FaceOccupancy& occupancy = c.face_occupancy(face);
        std::vector<char> free(static_cast<std::size_t>(grid.rows() * grid.units()));
        for (int row = 0; row < grid.rows(); ++row)
            for (int u = 0; u < grid.units(); ++u) {
                auto s = grid.at(row, u);
                if (s == detail::kOutside) continue;
                Rect r = grid.cell(row, u, u + 1);
                if (s == detail::kFull && occupancy.rect_is_free(r))
                    free[static_cast<std::size_t>(row * grid.units() + u)] = 1;
                else
                    c.place(detail::polygon_of(r), grid.course(row));
            }
        std::vector<detail::Stone> stones = detail::merge_ashlar(
            free, grid.rows(), grid.units(), o.ashlar_max_width, o.ashlar_max_height, c.random());
        for (const detail::Stone& s : stones)
            c.place_free_rect(
                Rect{grid.xs[s.unit], grid.ys[s.row], grid.xs[s.unit + s.w], grid.ys[s.row + s.h]},
                grid.course(s.row + s.h - 1));
    };
}

}  // namespace acanthus::cells
