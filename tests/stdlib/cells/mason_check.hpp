// A mason's reading of a laid wall, from its cells alone: straight joints between consecutive
// courses, whole bricks and courses against their nominal sizes, the smallest piece, voussoirs
// that are not whole, arches with a joint at the crown instead of a key, and openings without a
// head. The tests run it on every example facade in
// every bond and tree (test_cells_mason.cpp); it knows nothing of how the cells were laid.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <acanthus/stdlib/cells/head_joints.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "feature_walk.hpp"  // area_of: the library's own shoelace

namespace cells_test {

using acanthus::Point;
using acanthus::Rect;
using acanthus::cells::Cell;
using acanthus::cells::Facade;

struct MasonSpec {
    double length = 215, height = 65, mortar = 10;  // the nominal brick and joint
    double tolerance = 3;                           // a unit or course may be this far off
    bool stone = false;     // an ashlar wall: every rectangular cell is a stone
    double stone_unit = 0;  // the ashlar grid's unit; 0: height + mortar
};

struct MasonReport {
    long head_joints = 0;      // head joints with a joint in the course above to compare
    long straight_joints = 0;  // of those, closer than a quarter brick to one above
    std::vector<Point> straight_at;
    long whole_bricks = 0;   // stretchers and headers within a third of the tolerance
    long shaved_bricks = 0;  // within 12% of one but not whole: cuts no mason makes
    // Of those, the ones a run's room forces (room_forces_shaved): at most one a run.
    long shaved_forced = 0;
    std::vector<std::string> forcing_rooms;  // each: its width and place
    std::vector<std::string> shaved;         // each: its generator, size and place
    unsigned long long hash = 0;             // of every cell's corners: two builds' walls compared
    double length_deviation = 0;  // largest |length - nominal| of a whole or shaved brick
    double height_deviation = 0;  // largest |height - nominal| of a whole brick
    long courses = 0;
    long courses_off_gauge = 0;  // pitches between courses of whole height beyond the tolerance
    long cut_courses = 0;        // courses of cut height along half the wall's width or more
    double gauge_deviation = 0;  // largest |pitch - gauge|
    std::vector<Point> off_gauge_at;  // (pitch, the upper line) of each course off gauge
    double smallest_piece = 1e9;      // smallest cell's area over a brick face's
    long slivers = 0;                 // cells under 10% of a brick face
    // Brick pieces narrower than a queen closer: rectangles, and pieces of plumb and level sides
    // only (a quoin notched by a skewback) by the width of the rectangle round them (a lug cut
    // round a sill's horn is part of its brick); not those cut to a curve or rake.
    long narrow_pieces = 0;
    std::vector<Point> narrow_at;  // their extents' centres
    // The mason's rule for what goes in a course: every brick piece with plumb ends (rectangles:
    // not cut to a curve or rake) is a whole stretcher, a header or a standard bat or closer
    // (a quarter, half or three-quarter brick, or whole quarters past a stretcher in a quoin),
    // each within a third of the tolerance of its nominal; any other length is a brick cut to
    // what was left. Head joints between such pieces within the tolerance of the joint.
    long odd_pieces = 0;
    std::vector<std::string> odd;  // each: its generator, size and place
    // When the geometry forces an odd piece: a run of pieces in a course between two ends that
    // are not walling (a jamb, the wall's end, a head, a ring, a lintel, a piece cut to a curve)
    // whose width, reveal to reveal, is no whole number of quarter bricks within what its head
    // joints can take up (each by the tolerance), or which is narrower than a queen closer and
    // its joints: one piece in that course cut to what is left. Any other odd piece is not
    // forced: the run could have been laid in whole bricks and standard closers.
    long forced_runs = 0;  // runs where one odd piece is forced
    long unforced_odd = 0;
    std::vector<std::string> unforced;  // each: the run's width, pieces and place
    long joints_off = 0;  // head joints wider or narrower than the joint by more than the tolerance
    std::vector<Point> joints_off_at;
    double joint_deviation = 0;
    long voussoirs = 0;
    long voussoirs_clipped = 0;
    std::vector<Point> clipped_at;  // a vertex of each clipped voussoir off both arcs
    long crowns = 0;                // tops of arches and rings (a pointed arch's apex)
    long crowns_open = 0;           // of those, a joint at the crown instead of a key
    std::vector<Point> open_crowns;
    // Stone walls (MasonSpec::stone): every rectangular cell, jamb, sill and lintel too.
    long stones = 0;
    long four_way = 0;  // points where four stones meet
    std::vector<Point> four_way_at;
    long stones_on_end = 0;  // a tenth taller than wide (a square on a stretched grid is not),
                             // away from a jamb or the wall's end
    std::vector<Point> on_end_at;  // their top left corners
    long pier_stones = 0;          // of those not counted: a pier between two stones of another
                                   // generator (lintels' bearings, sills' lugs) of its height
    long unit_square_pairs = 0;    // two stones of about one grid unit sharing a side
    long unit_square_runs = 0;     // three or more in a line (counted by their middle ones)
    // King closers (Cell::piece): three quarters of a brick on the face, against a reveal (a
    // plumb side of the wall or an opening) or a quoin, a stretcher (or an opening's head) beside
    // them in the course.
    long king_closers = 0;
    long king_closers_misplaced = 0;
    std::vector<Point> misplaced_kings;
    // Lintels (generator "lintel") over straight heads: the shortest bearing past a jamb, and
    // those under 100 mm on a 215 mm brick (what a mason lets a lintel bear on).
    long lintels = 0;
    long short_bearings = 0;
    double shortest_bearing = 1e9;
    // Relieving arches (generator "relieving_arch"), per opening: voussoirs whole (every vertex
    // on the intrados or the extrados, found from the voussoirs alone, half a brick apart), an
    // odd count with a key over the crown, a skewback at each springing.
    long relieving_arches = 0;
    long relieving_voussoirs = 0;
    long relieving_clipped = 0;
    long relieving_even = 0;       // arches with an even count of voussoirs
    long relieving_open = 0;       // arches with no voussoir over the crown
    long relieving_skewbacks = 0;  // arches without two skewbacks
    // Soldiers (generator "soldier_course", bricks on end): each a brick's height wide within a
    // third of the tolerance (the head joints take up the span), a brick's length high or cut
    // shorter where the head falls off the course lines.
    long soldiers = 0;
    long soldiers_off = 0;  // of another width, or longer than a brick
    double soldier_deviation = 0;
    long openings = 0;
    long openings_without_head = 0;
    std::vector<std::string> headless;
    // Sills (window_bottom or sill_stones cells in the course under a straight bottom edge):
    // how much farther past one jamb the row runs than past the other.
    long sills = 0;
    long sills_off_centre = 0;  // by more than a quarter brick
    double sill_offset = 0;     // the largest difference
    // Pieces at an arris (a run's end at the wall's end, a jamb or a reveal): those narrower
    // than a header, and of those the ones the run forces (between two arrises, narrower than
    // two headers, a joint and the quarter brick a course must lap the one beside it).
    long arris_pieces = 0, arris_small = 0, arris_small_forced = 0;
    std::vector<Point> arris_small_at;  // the centres of the ones not forced
};

namespace mason_detail {

using acanthus::cells::is_rect;

inline bool contains(const std::vector<Point>& poly, Point p) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < poly[j].x + (p.y - poly[j].y) * (poly[i].x - poly[j].x) / (poly[i].y - poly[j].y))
            in = !in;
    return in;
}

// Laid in courses of bricks: the library's own reading (head_joints.hpp), so that the
// straight-joint map shows what this checker counts.
using acanthus::cells::coursed;

// The smallest rectangle round a polygon, sides plumb and level.
inline Rect extent(const std::vector<Point>& poly) {
    Rect r{1e300, 1e300, -1e300, -1e300};
    for (Point p : poly)
        r.x0 = std::min(r.x0, p.x), r.y0 = std::min(r.y0, p.y), r.x1 = std::max(r.x1, p.x),
        r.y1 = std::max(r.y1, p.y);
    return r;
}

// Sides plumb or level only.
inline bool rectilinear(const std::vector<Point>& poly) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Point a = poly[i], b = poly[(i + 1) % poly.size()];
        if (std::abs(a.x - b.x) > 1e-9 && std::abs(a.y - b.y) > 1e-9) return false;
    }
    return true;
}

inline bool is_head(const std::string& generator) {
    static const std::set<std::string> heads{"lintel",         "arch_stones", "arch_bricks",
                                             "soldier_course", "flat_arch",   "relieving_arch"};
    return heads.count(generator) > 0;
}

// The circle nearest to `pts` in the algebraic sense (Kasa's fit): exact for points on one
// circle.
inline bool fit_circle(const std::vector<Point>& pts, Point& center, double& radius) {
    // Least squares of x^2 + y^2 + D x + E y + F = 0: the normal equations, by Cramer's rule.
    double m[3][4] = {};
    for (Point p : pts) {
        const double row[3] = {p.x, p.y, 1}, rhs = -(p.x * p.x + p.y * p.y);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
            m[i][3] += row[i] * rhs;
        }
    }
    auto det = [&](int col) {
        double a[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) a[i][j] = m[i][j == col ? 3 : j];
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
               a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det(-1);
    if (pts.size() < 3 || std::abs(d) < 1e-300) return false;
    const double D = det(0) / d, E = det(1) / d, F = det(2) / d;
    center = {-D / 2, -E / 2};
    radius = std::sqrt(std::max(0.0, center.x * center.x + center.y * center.y - F));
    return true;
}

// Whether a room `width` wide in a course (reveal to reveal: half a joint at each end) forces a
// shaved brick: every way to fill it, and the same room in the course over it, with pieces no
// narrower than a queen closer, head joints within the tolerance and no straight joint between
// the two courses, has a piece within 12% of a brick or header that is not one. Ways of up to
// three pieces a course (a room wider than two bricks and a header is never taken as forcing);
// joints are compared on a grid of a sixteenth of a quarter brick, and a pair of ways counts as
// clear when its joints are a quarter brick less twice the tolerance and that grid apart, so a
// room is called forcing only when no way nearly clears.
inline bool room_forces_shaved(double width, const MasonSpec& s) {
    const double L = s.length, m = s.mortar, tol = s.tolerance;
    const double header = (L - m) / 2, closer = (L + m) / 4 - m - tol;
    if (width > 2 * L + header + 4 * m) return false;
    auto clean = [&](double w) {  // a piece a mason cuts or lays whole, not a shaved one
        if (w < closer - 1e-9 || w > L + tol / 3 + 1e-9) return false;
        for (double n : {L, header})
            if (std::abs(w - n) <= 0.12 * n && std::abs(w - n) > tol / 3) return false;
        return true;
    };
    // Whether some piece in [lo, hi] is clean: the interval's ends and the clean set's edges.
    auto clean_in = [&](double lo, double hi) {
        if (hi < lo) return false;
        std::vector<double> at{lo, hi};
        for (double n : {L, header})
            for (double e : {0.88 * n, n - tol / 3, n + tol / 3, 1.12 * n}) at.push_back(e);
        at.push_back(closer), at.push_back(L + tol / 3);
        for (double x : at)
            for (double e : {-1e-7, 0.0, 1e-7})
                if (x + e >= lo && x + e <= hi && clean(x + e)) return true;
        return false;
    };
    const double U = width - m;        // the pieces and the head joints between them
    if (clean_in(U, U)) return false;  // one piece a course: no head joint to be straight
    const double step = tol / 6, g = (L + m) / 64, clear = L / 4 - 2 * tol - g;
    std::vector<double> ones;                     // joints of the ways of two pieces
    std::vector<std::pair<double, double>> twos;  // of three
    for (double p1 = closer; p1 <= L + tol / 3; p1 += step) {
        if (!clean(p1)) continue;
        const double r2 = U - m - p1;
        if (clean_in(r2 - tol, r2 + tol)) ones.push_back(std::round((p1 + m) / g));
        for (double p2 = closer; p2 <= L + tol / 3; p2 += step) {
            if (!clean(p2)) continue;
            const double r3 = U - 2 * m - p1 - p2;
            if (clean_in(r3 - 2 * tol, r3 + 2 * tol))
                twos.push_back({std::round((p1 + m) / g), std::round((p1 + p2 + 2 * m) / g)});
        }
    }
    std::sort(ones.begin(), ones.end());
    ones.erase(std::unique(ones.begin(), ones.end()), ones.end());
    std::sort(twos.begin(), twos.end());
    twos.erase(std::unique(twos.begin(), twos.end()), twos.end());
    auto apart = [&](double a, double b) { return std::abs(a - b) * g >= clear; };
    if (!ones.empty() && apart(ones.front(), ones.back())) return false;
    for (const auto& t : twos) {
        for (double a : ones)
            if (apart(a, t.first) && apart(a, t.second)) return false;
        for (const auto& u : twos)
            if (apart(t.first, u.first) && apart(t.first, u.second) && apart(t.second, u.first) &&
                apart(t.second, u.second))
                return false;
    }
    return true;
}

}  // namespace mason_detail

inline MasonReport mason_check(const Facade& facade, const std::vector<Cell>& cells,
                               const MasonSpec& s) {
    using namespace mason_detail;
    MasonReport r;
    const double face = s.length * s.height, gauge = s.height + s.mortar;
    const double header = (s.length - s.mortar) / 2;
    const double closer = (s.length + s.mortar) / 4 - s.mortar - s.tolerance;
    // The brick or header a piece of whole height is within 12% of (0: none), and whether it is
    // shaved: that far off it, but more than a third of the tolerance.
    auto nominal_of = [&](const Rect& b) {
        const double w = b.width();
        return std::abs(w - s.length) <= 0.12 * s.length ? s.length
               : std::abs(w - header) <= 0.12 * header   ? header
                                                         : 0.0;
    };
    auto is_shaved = [&](const Rect& b) {
        const double n = nominal_of(b);
        return n > 0 && std::abs(b.height() - s.height) <= s.tolerance + 1e-9 &&
               std::abs(b.width() - n) > s.tolerance / 3;
    };

    // Pieces, whole units, and the head joints between neighbours in a course.
    std::vector<double> bottoms;      // of bricks of whole height: the course lines
    std::map<long long, double> cut;  // pieces of cut height: their width by bottom line
    for (const Cell& c : cells)
        for (const Point& p : c.polygon)
            for (double v : {p.x, p.y})
                r.hash =
                    r.hash * 1000003ULL ^ static_cast<unsigned long long>(std::llround(v * 1e6));
    for (const Cell& c : cells) {
        double a = acanthus::cells::detail::area_of(c.polygon) / face;
        r.smallest_piece = std::min(r.smallest_piece, a);
        r.slivers += a < 0.1;
        Rect b;
        if (!coursed(c)) continue;
        if (!is_rect(c.polygon, b)) {
            const Rect e = extent(c.polygon);
            if (rectilinear(c.polygon) && std::abs(e.height() - s.height) <= 0.2 * s.height &&
                e.width() < closer)
                ++r.narrow_pieces, r.narrow_at.push_back(e.center());
            continue;
        }
        const double w = b.width(), h = b.height();
        // A lintel as deep as whole courses (less a joint) spans them: no cut course. Counted
        // as one, the shop front's 4.1 m lintel read as a cut course over the window's head.
        // Each course it spans may be off gauge by the tolerance (the corner shop's lintel spans
        // two of 7.73 cm where the courses meet its head on a course line).
        const double courses = std::round((h + s.mortar) / gauge);
        const bool whole_lintel =
            c.generator == "lintel" && courses >= 1 &&
            std::abs(h + s.mortar - courses * gauge) <= courses * s.tolerance + 1e-9;
        if (std::abs(h - s.height) <= s.tolerance + 1e-9)
            bottoms.push_back(b.y1);
        else if (!whole_lintel)
            cut[std::llround(b.y1 / (0.05 * s.mortar + 1e-9))] += w + s.mortar;
        if (std::abs(h - s.height) > 0.2 * s.height) continue;  // a cut course
        if (w < closer) ++r.narrow_pieces, r.narrow_at.push_back(b.center());
        const double nominal = nominal_of(b);
        if (nominal == 0) continue;                                 // a bat or closer
        if (std::abs(h - s.height) > s.tolerance + 1e-9) continue;  // cut in height
        r.length_deviation = std::max(r.length_deviation, std::abs(w - nominal));
        if (is_shaved(b)) {
            ++r.shaved_bricks;
            // Asked for by MASON_TAG: the other generators within about a brick and a course of
            // it (a sill row, an arch's stones), to sort what is left by what it stands beside.
            std::string tag;
            if (std::getenv("MASON_TAG"))
                for (const Cell& o : cells) {
                    if (o.generator == "bricks" || o.generator == "quoins") continue;
                    const Rect e = extent(o.polygon);
                    if (e.x1 > b.x0 - s.length && e.x0 < b.x1 + s.length && e.y1 > b.y0 - gauge &&
                        e.y0 < b.y1 + gauge && tag.find(o.generator) == std::string::npos)
                        tag += "/" + o.generator;
                }
            r.shaved.push_back(c.generator + " " + std::to_string(w) + " x " + std::to_string(h) +
                               " at (" + std::to_string(b.x0) + ", " + std::to_string(b.y0) + ")" +
                               tag);
            continue;
        }
        ++r.whole_bricks;
        r.height_deviation = std::max(r.height_deviation, std::abs(h - s.height));
    }
    // Standard pieces: k quarters of a brick less a joint, for k = 1..12 (bricks to 3/4, quoins
    // longer); the lintel is a stone, not a brick.
    if (!s.stone) {
        const double quarter = (s.length + s.mortar) / 4;
        std::vector<Rect> pieces;
        std::vector<char> odd;     // per piece, before sorting
        std::vector<char> shaved;  // as counted above
        for (const Cell& c : cells) {
            Rect b;
            if (!coursed(c) || c.generator == "lintel" || !is_rect(c.polygon, b)) continue;
            if (b.height() > 1.2 * s.height) continue;  // on end or a soldier: not a coursed unit
            pieces.push_back(b);
            shaved.push_back(is_shaved(b));
            const double k = std::round((b.width() + s.mortar) / quarter);
            odd.push_back(k < 1 || k > 12 ||
                          std::abs(b.width() - (k * quarter - s.mortar)) > s.tolerance / 3 + 1e-9);
            if (odd.back()) {
                ++r.odd_pieces;
                r.odd.push_back(c.generator + " " + std::to_string(b.width()) + " x " +
                                std::to_string(b.height()) + " at (" + std::to_string(b.x0) + ", " +
                                std::to_string(b.y0) + ")");
            }
        }
        const double same = 0.05 * s.mortar + 1e-9;
        auto row = [&](const Rect& b) { return std::llround(b.y1 / same); };
        std::vector<std::size_t> order(pieces.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
            const Rect &a = pieces[i], &b = pieces[j];
            return row(a) != row(b) ? row(a) < row(b) : a.x0 < b.x0;
        });
        // Runs: pieces of one course a joint apart (up to two), whatever their height.
        for (std::size_t i = 0; i < order.size();) {
            std::size_t j = i + 1;
            while (j < order.size() && row(pieces[order[j]]) == row(pieces[order[i]]) &&
                   pieces[order[j]].x0 - pieces[order[j - 1]].x1 > 0 &&
                   pieces[order[j]].x0 - pieces[order[j - 1]].x1 <= 2 * s.mortar)
                ++j;
            long n_odd = 0, n_shaved = 0;
            for (std::size_t k = i; k < j; ++k)
                n_odd += odd[order[k]], n_shaved += shaved[order[k]];
            const Rect &a = pieces[order[i]], &b = pieces[order[j - 1]];
            const double width = b.x1 - a.x0 + s.mortar;  // reveal to reveal
            if (n_shaved > 0 && room_forces_shaved(width, s)) {
                ++r.shaved_forced;
                r.forcing_rooms.push_back(std::to_string(width) + " at (" + std::to_string(a.x0) +
                                          ", " + std::to_string(a.y0) + ")");
            }
            const double k = std::round(width / quarter);
            const double joints = static_cast<double>(j - i - 1);
            const bool forced =
                k < 1 || std::abs(width - k * quarter) > joints * s.tolerance + 1e-9;
            r.forced_runs += forced && n_odd > 0;
            const long over = n_odd - (forced ? 1 : 0);
            if (over > 0) {
                r.unforced_odd += over;
                r.unforced.push_back(std::to_string(over) + " in a run " + std::to_string(width) +
                                     " wide of " + std::to_string(j - i) + " pieces at (" +
                                     std::to_string(a.x0) + ", " + std::to_string(a.y0) + ")");
            }
            i = j;
        }
        std::vector<Rect> sorted;
        for (std::size_t i : order) sorted.push_back(pieces[i]);
        pieces = std::move(sorted);
        for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
            const Rect &a = pieces[i], &b = pieces[i + 1];
            const double gap = b.x0 - a.x1;
            if (row(a) != row(b) || std::abs(a.y0 - b.y0) > same || gap <= 0 || gap > 2 * s.mortar)
                continue;
            r.joint_deviation = std::max(r.joint_deviation, std::abs(gap - s.mortar));
            if (std::abs(gap - s.mortar) > s.tolerance + 1e-9)
                ++r.joints_off, r.joints_off_at.push_back({(a.x1 + b.x0) / 2, a.center().y});
        }
    }
    // Straight joints by the library's rule, the one the straight-joint map draws.
    const acanthus::cells::HeadJoints hj =
        acanthus::cells::straight_joints(cells, s.length, s.mortar);
    r.head_joints = hj.compared;
    r.straight_joints = static_cast<long>(hj.straight.size());
    for (const auto& j : hj.straight) r.straight_at.push_back({j.lower.x, j.lower.y0});
    const double same = 0.05 * s.mortar + 1e-9;
    for (const auto& [line, width] : cut) r.cut_courses += width >= 0.5 * facade.bounds().width();
    // Course pitches from the bottoms of bricks of whole height (pieces cut under a sill or over
    // a head that falls within a course are the opening's; cut courses are counted above).
    std::sort(bottoms.begin(), bottoms.end());
    std::vector<double> lines;
    for (double y : bottoms)
        if (lines.empty() || y - lines.back() > same) lines.push_back(y);
    r.courses = static_cast<long>(lines.size());
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        double pitch = lines[i + 1] - lines[i];
        if (pitch > 1.5 * gauge) continue;  // a storey of openings or another face between
        double dev = std::abs(pitch - gauge);
        r.gauge_deviation = std::max(r.gauge_deviation, dev);
        if (dev > s.tolerance + 1e-9) {
            ++r.courses_off_gauge;
            r.off_gauge_at.push_back({pitch, lines[i]});
        }
    }
    // Voussoirs: whole when every vertex lies on the inner or the outer arc, a brick apart (or
    // half).
    for (const Cell& c : cells) {
        if ((c.generator != "arch_stones" && c.generator != "arch_bricks") ||
            c.feature != acanthus::cells::FeatureKind::edge || c.feature_index < 0)
            continue;
        const auto& e = facade.edges()[static_cast<std::size_t>(c.feature_index)];
        if (!e.arc) continue;
        ++r.voussoirs;
        const Point o = e.segments.front().center;
        double lo = 1e300, hi = -1e300;
        for (Point p : c.polygon) {
            double d = std::hypot(p.x - o.x, p.y - o.y);
            lo = std::min(lo, d), hi = std::max(hi, d);
        }
        const double tol = 0.25 * s.mortar + 1e-6;
        // A ring a brick deep, or one half-brick ring (turned where a brick-deep one would
        // reach past the wall).
        const double half_ring = (s.length - s.mortar) / 2;
        bool whole = hi - lo >= s.length - tol || std::abs(hi - lo - half_ring) < tol;
        for (Point p : c.polygon) {
            double d = std::hypot(p.x - o.x, p.y - o.y);
            whole &= std::abs(d - lo) < tol || std::abs(d - hi) < tol;
        }
        if (!whole) {
            ++r.voussoirs_clipped;
            const std::size_t before = r.clipped_at.size();
            for (Point p : c.polygon) {
                double d = std::hypot(p.x - o.x, p.y - o.y);
                if (std::abs(d - lo) >= tol && std::abs(d - hi) >= tol) {
                    r.clipped_at.push_back(p);
                    break;
                }
            }
            if (r.clipped_at.size() == before) r.clipped_at.push_back(c.polygon.front());
        }
    }
    // Crowns: just into the wall above the top of every arc of an opening (a pointed arch's two
    // arcs share theirs, the apex), an arch cell and not the mortar of a joint.
    std::vector<Point> crowns;
    for (const auto& e : facade.edges()) {
        if (!e.arc || !e.opening) continue;
        double best = 0, top = 1e300;
        const int n = 720;
        for (int i = 0; i <= n; ++i) {
            const double at = e.length * i / n;
            if (e.at(at).y < top) top = e.at(at).y, best = at;
        }
        if (!e.closed && best > 0 && best < e.length && e.part != acanthus::cells::Part::top)
            continue;
        // The top at an end of an arc is a crown only at a corner (a pointed apex): where a
        // circle split into arcs runs on smoothly, it is no crown.
        if (!e.closed && (best == 0 ? e.corner_start : best == e.length ? e.corner_end : 0) < 0)
            continue;
        const Point p = e.at(best);
        bool seen_before = false;
        for (Point q : crowns) seen_before |= std::hypot(q.x - p.x, q.y - p.y) < s.mortar;
        if (seen_before) continue;
        crowns.push_back(p);
        const Point probe{p.x, p.y - 0.25 * s.height};  // up, into the ring
        bool key = false;
        for (const Cell& c : cells)
            if (is_head(c.generator) && contains(c.polygon, probe)) key = true;
        ++r.crowns;
        if (!key) {
            ++r.crowns_open;
            r.open_crowns.push_back(p);
        }
    }
    // Stones: the claims' corners (the drawn rect grown by half a joint) where four meet.
    if (s.stone) {
        const double unit = s.stone_unit > 0 ? s.stone_unit : s.height + s.mortar;
        const double m = s.mortar / 2;
        std::vector<Rect> stones;
        std::vector<const std::string*> laid_by;  // the generator of each
        for (const Cell& c : cells) {
            Rect b;
            if (!is_rect(c.polygon, b)) continue;
            stones.push_back({b.x0 - m, b.y0 - m, b.x1 + m, b.y1 + m});
            laid_by.push_back(&c.generator);
        }
        r.stones = static_cast<long>(stones.size());
        const double key = 0.01 * unit;
        std::map<std::pair<long, long>, int> corners;
        for (const Rect& b : stones)
            for (double x : {b.x0, b.x1})
                for (double y : {b.y0, b.y1})
                    ++corners[{std::llround(x / key), std::llround(y / key)}];
        for (const auto& [p, n] : corners)
            if (n >= 4) {
                ++r.four_way;
                r.four_way_at.push_back(
                    {static_cast<double>(p.first) * key, static_cast<double>(p.second) * key});
            }
        const double near = s.mortar + 1e-6;
        for (std::size_t i = 0; i < stones.size(); ++i) {
            const Rect& b = stones[i];
            if (b.height() <= b.width() * 1.1) continue;
            bool jamb = false;
            for (const auto& e : facade.edges())
                if (e.vertical() && !e.arc && e.bounds.y0 < b.y1 && e.bounds.y1 > b.y0 &&
                    (std::abs(e.bounds.x0 - b.x0) < near || std::abs(e.bounds.x0 - b.x1) < near))
                    jamb = true;
            // A pier: each side a joint from a plumb end of a stone of another generator
            // (a lintel's bearing, a sill's lug) as tall as it (within a micron).
            bool left = false, right = false;
            for (const Cell& c : cells) {
                if (c.generator == *laid_by[i]) continue;
                for (std::size_t e = 0, f = c.polygon.size() - 1; e < c.polygon.size(); f = e++) {
                    const Point p = c.polygon[f], q = c.polygon[e];
                    if (std::abs(p.x - q.x) > 1e-4 ||
                        std::abs(std::min(p.y, q.y) - (b.y0 + m)) > 1e-4 ||
                        std::abs(std::max(p.y, q.y) - (b.y1 - m)) > 1e-4)
                        continue;
                    left |= std::abs(p.x - (b.x0 - m)) < 1e-4;
                    right |= std::abs(p.x - (b.x1 + m)) < 1e-4;
                }
            }
            r.pier_stones += !jamb && left && right;
            r.stones_on_end += !jamb && !(left && right);
            if (!jamb && !(left && right)) r.on_end_at.push_back({b.x0, b.y0});
        }
        auto unit_square = [&](const Rect& b) {
            return b.width() < 1.5 * unit && b.height() < 1.5 * unit;
        };
        std::vector<Rect> squares;
        for (const Rect& b : stones)
            if (unit_square(b)) squares.push_back(b);
        const double eps = 0.05 * s.mortar + 1e-6;
        std::vector<int> left(squares.size()), right(squares.size()), up(squares.size()),
            down(squares.size());
        for (std::size_t i = 0; i < squares.size(); ++i)
            for (std::size_t j = 0; j < squares.size(); ++j) {
                const Rect &a = squares[i], &b = squares[j];
                const bool rows = std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > eps;
                const bool cols = std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > eps;
                if (rows && std::abs(a.x1 - b.x0) < eps) ++r.unit_square_pairs, right[i] = 1;
                if (rows && std::abs(b.x1 - a.x0) < eps) left[i] = 1;
                if (cols && std::abs(a.y1 - b.y0) < eps) ++r.unit_square_pairs, down[i] = 1;
                if (cols && std::abs(b.y1 - a.y0) < eps) up[i] = 1;
            }
        for (std::size_t i = 0; i < squares.size(); ++i)
            r.unit_square_runs += (left[i] && right[i]) || (up[i] && down[i]);
    }
    // King closers: their face, their place at a reveal or quoin, the stretcher beside them.
    for (const Cell& c : cells) {
        if (c.piece != "king closer") continue;
        ++r.king_closers;
        Rect b;
        bool ok = is_rect(c.polygon, b) &&
                  std::abs(b.width() - (3 * (s.length + s.mortar) / 4 - s.mortar)) <= s.tolerance &&
                  std::abs(b.height() - s.height) <= s.tolerance;
        // Each side (0 left, 1 right): a reveal there, and the bond going on there.
        bool reveal[2] = {false, false}, goes_on[2] = {false, false};
        const double near = s.mortar + s.tolerance;
        // A plumb side of the facade (a jamb, the wall's end) at x, over the rows y0..y1.
        auto plumb = [&](double x, double y0, double y1) {
            for (const auto& e : facade.edges())
                if (e.vertical() && !e.arc && e.bounds.y0 < y1 && e.bounds.y1 > y0 &&
                    std::abs(e.bounds.x0 - x) < near)
                    return true;
            return false;
        };
        reveal[0] = plumb(b.x0, b.y0, b.y1), reveal[1] = plumb(b.x1, b.y0, b.y1);
        // The head of an opening, an arch's voussoir or a skewback at x (walling is cut to it):
        // by its extent, or by a plumb side over the rows (a skewback stepped with the bond has
        // steps inside its extent).
        auto head_at = [&](double x, double y0, double y1) {
            const double by = near + s.mortar;
            for (const Cell& d : cells) {
                if (!mason_detail::is_head(d.generator)) continue;
                Rect n;
                if (!is_rect(d.polygon, n)) n = extent(d.polygon);  // a voussoir or skewback
                if (n.y0 > y1 || n.y1 < y0) continue;
                if (std::abs(n.x1 - x) < by || std::abs(n.x0 - x) < by) return true;
                for (std::size_t i = 0, j = d.polygon.size() - 1; i < d.polygon.size(); j = i++) {
                    const Point p = d.polygon[j], q = d.polygon[i];
                    if (std::abs(p.x - q.x) < 1e-6 && std::abs(p.x - x) < by &&
                        std::min(p.y, q.y) < y1 && std::max(p.y, q.y) > y0)
                        return true;
                }
            }
            return false;
        };
        goes_on[0] |= head_at(b.x0, b.y0, b.y1), goes_on[1] |= head_at(b.x1, b.y0, b.y1);
        for (const Cell& d : cells) {
            if (&d == &c || !coursed(d)) continue;
            // Its neighbours in the course: pieces cut to an arch or a notch by their extent.
            Rect n;
            const bool whole = is_rect(d.polygon, n);
            if (!whole) n = extent(d.polygon);
            if (std::min(n.y1, b.y1) - std::max(n.y0, b.y0) < s.height / 2) continue;
            const int side = std::abs(n.x1 - b.x0) < near   ? 0
                             : std::abs(b.x1 - n.x0) < near ? 1
                                                            : -1;
            if (side < 0) continue;
            const double far = side == 0 ? n.x0 : n.x1;
            if (d.generator == "quoins") {  // the jamb's dressing: the reveal of the walling
                reveal[side] = true;
                continue;
            }
            // A piece between it and a plumb side, whatever laid it: a quoin (the wall's top
            // corner is laid by its corner), or the rest of a pier's course cut at the jamb.
            const bool at_plumb =
                whole && n.width() <= s.length + s.tolerance && plumb(far, n.y0, n.y1);
            reveal[side] |= at_plumb;
            // A stretcher; one cut to an arch's extrados or a rake; or the rest of the course
            // cut at the next reveal or head: the king closer laps its own reveal by a quarter.
            goes_on[side] |= at_plumb || !whole || std::abs(n.width() - s.length) <= s.tolerance ||
                             head_at(far, n.y0, n.y1);
        }
        const bool reveal_any = reveal[0] || reveal[1];
        const bool stretcher = (reveal[0] && goes_on[1]) || (reveal[1] && goes_on[0]);
        if (!ok || !reveal_any || !stretcher) {
            ++r.king_closers_misplaced;
            r.misplaced_kings.push_back(b.center());
        }
    }
    // Lintel bearings: each lintel over the straight head it spans (the head's middle under it,
    // within a joint and a half of its bottom), measured from each jamb to the lintel's end.
    for (const Cell& c : cells) {
        Rect b;
        if (c.generator != "lintel" || !is_rect(c.polygon, b)) continue;
        for (const auto& e : facade.edges()) {
            if (!e.opening || e.arc || e.part != acanthus::cells::Part::top) continue;
            const double mid = (e.bounds.x0 + e.bounds.x1) / 2;
            if (mid < b.x0 || mid > b.x1 || std::abs(e.bounds.y0 - b.y1) > 1.5 * s.mortar) continue;
            ++r.lintels;
            // A lintel run out to the wall's end bears on the whole pier (an opening nearer the
            // end than a bearing forces it): only ends within the wall are counted.
            const Rect wall = facade.bounds();
            double bearing = 1e9;
            if (b.x0 > wall.x0 + s.mortar) bearing = std::min(bearing, e.bounds.x0 - b.x0);
            if (b.x1 < wall.x1 - s.mortar) bearing = std::min(bearing, b.x1 - e.bounds.x1);
            r.shortest_bearing = std::min(r.shortest_bearing, bearing);
            r.short_bearings += bearing < 100.0 / 215.0 * s.length - 1e-6;
        }
    }
    // Relieving arches: the intrados fitted to the inner vertices of all voussoirs of one arch,
    // found from the voussoirs alone.
    std::map<std::string, std::vector<const Cell*>> relief_voussoirs;
    std::map<std::string, int> relief_skewbacks;
    for (const Cell& c : cells) {
        if (c.generator != "relieving_arch") continue;
        if (c.piece == "skewback")
            ++relief_skewbacks[c.label];
        else
            relief_voussoirs[c.label].push_back(&c);
    }
    for (const auto& [label, vs] : relief_voussoirs) {
        ++r.relieving_arches;
        r.relieving_voussoirs += static_cast<long>(vs.size());
        r.relieving_even += vs.size() % 2 == 0;
        r.relieving_skewbacks += relief_skewbacks[label] != 2;
        std::vector<Point> all;
        for (const Cell* c : vs) all.insert(all.end(), c->polygon.begin(), c->polygon.end());
        // A first centre where the springing joints meet: the outer of the two longest sides of
        // the leftmost and of the rightmost voussoir (each a half joint off its radial line, so
        // the centre is off by under a joint; a shallow arch's band fits no circle well).
        auto springing_joint = [&](bool right, Point& a, Point& b) {
            const Cell* end = vs.front();
            for (const Cell* c : vs)
                if ((extent(c->polygon).center().x > extent(end->polygon).center().x) == right)
                    end = c;
            const auto& poly = end->polygon;
            const std::size_t n = poly.size();
            auto side = [&](std::size_t i) {
                return std::hypot(poly[(i + 1) % n].x - poly[i].x, poly[(i + 1) % n].y - poly[i].y);
            };
            std::size_t s1 = 0, s2 = 1 % n;
            if (side(s2) > side(s1)) std::swap(s1, s2);
            for (std::size_t i = 2; i < n; ++i)
                if (side(i) > side(s1))
                    s2 = s1, s1 = i;
                else if (side(i) > side(s2))
                    s2 = i;
            auto mid_x = [&](std::size_t i) { return (poly[i].x + poly[(i + 1) % n].x) / 2; };
            const std::size_t k = (mid_x(s1) > mid_x(s2)) == right ? s1 : s2;
            a = poly[k], b = poly[(k + 1) % n];
        };
        Point a1, b1, a2, b2, o;
        springing_joint(false, a1, b1);
        springing_joint(true, a2, b2);
        const double den = (b1.x - a1.x) * (b2.y - a2.y) - (b1.y - a1.y) * (b2.x - a2.x);
        if (vs.size() < 2 || std::abs(den) < 1e-12) {
            r.relieving_clipped += static_cast<long>(vs.size());
            continue;
        }
        const double t = ((a2.x - a1.x) * (b2.y - a2.y) - (a2.y - a1.y) * (b2.x - a2.x)) / den;
        o = {a1.x + t * (b1.x - a1.x), a1.y + t * (b1.y - a1.y)};
        double lo = 1e300, hi = 0;
        for (Point p : all) {
            const double d = std::hypot(p.x - o.x, p.y - o.y);
            lo = std::min(lo, d), hi = std::max(hi, d);
        }
        // Then the circle through the inner vertices, fitted again to those near it so that a
        // notched voussoir's vertices do not pull it off the others.
        const double tol = 0.25 * s.mortar + 1e-6,
                     depth = s.stone ? s.length : (s.length - s.mortar) / 2;
        double rad = (lo + hi) / 2;
        bool fitted = true;
        for (int pass = 0; pass < 3 && fitted; ++pass) {
            std::vector<Point> inner;
            for (Point p : all) {
                const double d = std::hypot(p.x - o.x, p.y - o.y);
                if (pass == 0 ? d < rad : std::abs(d - rad) < tol) inner.push_back(p);
            }
            fitted = fit_circle(inner, o, rad);
        }
        if (!fitted) {
            r.relieving_clipped += static_cast<long>(vs.size());
            continue;
        }
        for (const Cell* c : vs) {
            bool whole = true;
            for (Point p : c->polygon) {
                const double d = std::hypot(p.x - o.x, p.y - o.y);
                whole &= std::abs(d - rad) < tol || std::abs(d - rad - depth) < tol;
            }
            r.relieving_clipped += !whole;
        }
        const Point probe{o.x, o.y - rad - 0.25 * s.height};
        bool key = false;
        for (const Cell* c : vs) key |= contains(c->polygon, probe);
        r.relieving_open += !key;
    }
    for (const Cell& c : cells) {
        Rect b;
        if (c.generator != "soldier_course" || !is_rect(c.polygon, b) ||
            b.height() < 1.2 * s.height)
            continue;  // the bedding beside the jambs under a head within a course
        ++r.soldiers;
        const double off = std::max(std::abs(b.width() - s.height), b.height() - s.length);
        r.soldier_deviation = std::max(r.soldier_deviation, std::abs(b.width() - s.height));
        r.soldiers_off += off > s.tolerance / 3 + 1e-9;
    }
    // Heads: above the middle of every top edge of an opening, a lintel, arch or soldier cell.
    std::set<std::string> seen, headless;
    for (const auto& e : facade.edges()) {
        if (!e.opening || e.part != acanthus::cells::Part::top) continue;
        std::string name;
        for (const std::string& l : e.labels) name += (name.empty() ? "" : " ") + l;
        seen.insert(name);
        // Three points a little apart, as the middle may fall on a joint between soldiers.
        bool head = false;
        for (double off : {0.0, -0.3 * s.height, 0.3 * s.height}) {
            const double at = std::clamp(e.length / 2 + off, 0.0, e.length);
            const Point p = e.at(at) + e.inward(at) * (s.mortar + 0.25 * s.height);
            for (const Cell& c : cells)
                if (is_head(c.generator) && contains(c.polygon, p)) head = true;
        }
        if (!head) headless.insert(name);
    }
    // Sills: the row of sill cells under each straight bottom edge, joined across its joints.
    for (const auto& e : facade.edges()) {
        if (!e.opening || e.part != acanthus::cells::Part::bottom || e.arc) continue;
        const double x0 = std::min(e.bounds.x0, e.bounds.x1),
                     x1 = std::max(e.bounds.x0, e.bounds.x1);
        const double y = e.bounds.y0;
        std::vector<Rect> row;
        for (const Cell& c : cells) {
            if (c.generator != "window_bottom" && c.generator != "sill_stones") continue;
            const Rect b = extent(c.polygon);
            if (b.y0 < y - 1e-6 || b.y0 > y + s.height + 2 * s.mortar) continue;
            row.push_back(b);
        }
        std::sort(row.begin(), row.end(), [](const Rect& a, const Rect& b) { return a.x0 < b.x0; });
        double lo = 0, hi = 0;
        bool found = false;
        for (const Rect& b : row) {  // the stretch joined to the one under the edge's middle
            if (!found || b.x0 > hi + 2 * s.mortar) {
                if (found && lo <= (x0 + x1) / 2 && (x0 + x1) / 2 <= hi) break;
                lo = b.x0, hi = b.x1, found = true;
            } else
                hi = std::max(hi, b.x1);
        }
        if (!found || lo > (x0 + x1) / 2 || hi < (x0 + x1) / 2) continue;
        bool shared = false;  // one row under two openings close together: no middle to keep
        for (const auto& o : facade.edges())
            if (&o != &e && o.opening && o.part == acanthus::cells::Part::bottom &&
                std::abs(o.bounds.y0 - y) < s.height && o.bounds.x1 > lo && o.bounds.x0 < hi)
                shared = true;
        // A row that runs on to the wall's end or a reveal has no horn there to match.
        double y0 = 1e300, y1 = -1e300;
        for (const Rect& b : row)
            if (b.x0 >= lo - 1e-9 && b.x1 <= hi + 1e-9)
                y0 = std::min(y0, b.y0), y1 = std::max(y1, b.y1);
        bool left = false, right = false;
        for (const Cell& c : cells) {
            const Rect b = extent(c.polygon);
            if (b.y1 <= y0 + 1e-6 || b.y0 >= y1 - 1e-6) continue;
            left |= b.x1 < lo + 1e-6 && b.x1 > lo - 2 * s.mortar;
            right |= b.x0 > hi - 1e-6 && b.x0 < hi + 2 * s.mortar;
        }
        if (shared || !left || !right) continue;
        ++r.sills;
        const double off = std::abs((x0 - lo) - (hi - x1));
        r.sill_offset = std::max(r.sill_offset, off);
        r.sills_off_centre += off > (s.length + s.mortar) / 4;
    }
    // Arrises: a mason keeps closers and cut pieces back from a quoin or a reveal (a queen
    // closer goes beside the header there; a small piece at the arris is weak and shows on the
    // return). A piece is at one where nothing lies within a joint and the tolerance of its end.
    if (!s.stone) {
        std::map<long long, std::pair<Rect, std::vector<std::pair<double, double>>>> bands;
        for (const Cell& c : cells) {
            Rect b;
            if (!coursed(c) || !is_rect(c.polygon, b) || c.generator == "lintel") continue;
            if (std::abs(b.height() - s.height) > s.tolerance + 1e-9) continue;
            auto& band = bands[std::llround(b.y0 / (0.05 * s.mortar))];
            band.first = b;
        }
        for (const Cell& c : cells) {
            const Rect e = extent(c.polygon);
            for (auto& [key, band] : bands)
                if (e.y0 < band.first.y1 - 1e-6 && e.y1 > band.first.y0 + 1e-6)
                    band.second.push_back({e.x0, e.x1});
        }
        const double gap = s.mortar + s.tolerance + 1e-6;
        for (const Cell& c : cells) {
            Rect b;
            if (!coursed(c) || !is_rect(c.polygon, b) || c.generator == "lintel") continue;
            if (std::abs(b.height() - s.height) > s.tolerance + 1e-9) continue;
            const auto& spans = bands[std::llround(b.y0 / (0.05 * s.mortar))].second;
            // The nearest neighbour on each side, and how far the run goes past the piece.
            bool left = false, right = false;
            for (auto [x0, x1] : spans) {
                left |= x1 <= b.x0 + 1e-6 && b.x0 - x1 <= gap;
                right |= x0 >= b.x1 - 1e-6 && x0 - b.x1 <= gap;
            }
            if (left && right) continue;
            ++r.arris_pieces;
            if (b.width() >= header - s.tolerance) continue;
            ++r.arris_small;
            // The run's other end: where the pieces beside it stop.
            double lo = b.x0, hi = b.x1;
            const double quarter = (s.length + s.mortar) / 4;
            for (bool grew = true; grew;) {
                grew = false;
                for (auto [x0, x1] : spans) {
                    if (x1 <= lo + 1e-6 && lo - x1 <= gap && x0 < lo) lo = x0, grew = true;
                    if (x0 >= hi - 1e-6 && x0 - hi <= gap && x1 > hi) hi = x1, grew = true;
                }
            }
            if (hi - lo < 5 * quarter - s.mortar - s.tolerance)
                ++r.arris_small_forced;
            else
                r.arris_small_at.push_back(b.center());
        }
    }
    r.openings = static_cast<long>(seen.size());
    r.openings_without_head = static_cast<long>(headless.size());
    r.headless.assign(headless.begin(), headless.end());
    if (cells.empty()) r.smallest_piece = 0;
    return r;
}

// One line of a table: the numbers a mason would look at first.
// The trees the checker reads: the ready ones and the rowlock tree of rules/facade.acr.
inline std::map<std::string, acanthus::cells::Node> mason_trees() {
    using namespace acanthus::cells;
    Node b = generator("bricks", bricks());
    Node wb = generator("window_bottom", window_bottom());
    Node heads = by_label(
        "relieving", generator("relieving_arch", relieving_arch(), generator("lintel", lintel())),
        generator("soldier_course", soldier_course()));
    Node sills = by_part(heads, wb, b);
    Node rowlock = by_kind(by_curve(generator("arch_bricks", arch_bricks()), sills),
                           by_curve(generator("arch_bricks", arch_bricks()), sills), b);
    return {{"bricks", brick_tree()}, {"framed", framed_tree()}, {"rowlock", rowlock}};
}

inline std::ostream& operator<<(std::ostream& out, const MasonReport& r) {
    out << "straight " << r.straight_joints << "/" << r.head_joints << ", whole " << r.whole_bricks
        << " shaved " << r.shaved_bricks << " (forced " << r.shaved_forced << ") dev L "
        << r.length_deviation << " H " << r.height_deviation << ", courses " << r.courses
        << " off-gauge " << r.courses_off_gauge << " (max " << r.gauge_deviation << ") cut "
        << r.cut_courses << ", smallest " << r.smallest_piece << " slivers " << r.slivers
        << " narrow " << r.narrow_pieces << ", voussoirs clipped " << r.voussoirs_clipped << "/"
        << r.voussoirs << ", crowns open " << r.crowns_open << "/" << r.crowns << ", headless "
        << r.openings_without_head << "/" << r.openings << ", stones " << r.stones << " four-way "
        << r.four_way << " on end " << r.stones_on_end << " piers " << r.pier_stones
        << " unit-square pairs " << r.unit_square_pairs << " runs " << r.unit_square_runs
        << ", king closers " << r.king_closers << " misplaced " << r.king_closers_misplaced
        << ", odd pieces " << r.odd_pieces << " (not forced " << r.unforced_odd << ", forced runs "
        << r.forced_runs << ")"
        << ", head joints off " << r.joints_off << " (max " << r.joint_deviation << ")"
        << ", relieving arches " << r.relieving_arches << " (voussoirs " << r.relieving_voussoirs
        << ", clipped " << r.relieving_clipped << ", even " << r.relieving_even << ", open "
        << r.relieving_open << ", skewbacks wrong " << r.relieving_skewbacks << "), soldiers "
        << r.soldiers << " off " << r.soldiers_off << " (max " << r.soldier_deviation << "), sills "
        << r.sills << " off centre " << r.sills_off_centre << " (max " << r.sill_offset
        << "), arris pieces " << r.arris_pieces << " small " << r.arris_small << " (forced "
        << r.arris_small_forced << ")";
    // Asked for by odd_sweep.py: the cells' hash, each shaved brick and forcing room; each run
    // with an odd piece the geometry does not force.
    if (std::getenv("MASON_HASH")) out << " hash " << r.hash;
    if (std::getenv("MASON_SHAVED"))
        for (const std::string& s : r.shaved) out << " | " << s;
    if (std::getenv("MASON_SHAVED"))
        for (const std::string& s : r.forcing_rooms) out << " | room " << s;
    if (std::getenv("MASON_SHAVED"))
        for (const Point& p : r.narrow_at) out << " | narrow at (" << p.x << ", " << p.y << ")";
    if (std::getenv("MASON_UNFORCED"))
        for (const std::string& s : r.unforced) out << " | unforced " << s;
    return out;
}

}  // namespace cells_test
