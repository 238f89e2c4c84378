#include "brick_grid.hpp"

#include <algorithm>
#include <cmath>

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

// Course heights, bottom first, filling the storey `w` with gauge `g`.
void storey(double w, double g, double tol, std::vector<double>& heights) {
    const int n = static_cast<int>(std::lround(w / g));
    if (n >= 1 && std::abs(w - n * g) <= tol * n * (1 + 1e-9)) {
        heights.insert(heights.end(), static_cast<std::size_t>(n), w / n);
        return;
    }
    const int whole = static_cast<int>(std::floor(w / g));
    const double rest = w - whole * g;
    if (rest >= g / 2 || whole == 0) {
        heights.push_back(rest);
        heights.insert(heights.end(), static_cast<std::size_t>(whole), g);
    } else {
        heights.insert(heights.end(), 2, (g + rest) / 2);
        heights.insert(heights.end(), static_cast<std::size_t>(whole - 1), g);
    }
}

}  // namespace

CourseGrid make_brick_grid(const Facade& facade, int face, const Options& o) {
    const Face& f = facade.faces()[static_cast<std::size_t>(face)];
    const double q = (o.brick_length + o.mortar) / 4, g = o.brick_height + o.mortar;
    const double tol = o.joint_tolerance;
    const double eps = 1e-9 * std::max({1.0, std::abs(f.bounds.x0), std::abs(f.bounds.x1),
                                        std::abs(f.bounds.y0), std::abs(f.bounds.y1)});
    CourseGrid grid;
    grid.xs = unit_lines(f.bounds.x0, f.bounds.x1, q, tol);

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

    std::vector<double> down;  // course lines, bottom first
    double y = kept.front();
    while (y < f.bounds.y1 - eps) y += g;  // below the lowest level edge: whole courses
    for (double at = y; at > kept.front() + eps; at -= g) down.push_back(at);
    down.push_back(kept.front());
    std::vector<double> heights;
    for (std::size_t i = 0; i + 1 < kept.size(); ++i) {
        heights.clear();
        storey(kept[i] - kept[i + 1], g, tol, heights);
        double at = kept[i];
        for (std::size_t k = 0; k + 1 < heights.size(); ++k) down.push_back(at -= heights[k]);
        down.push_back(kept[i + 1]);
    }
    for (double at = kept.back(); at > f.bounds.y0 + eps;) down.push_back(at -= g);  // to the top
    grid.ys.assign(down.rbegin(), down.rend());
    classify_units(facade, face, grid);
    return grid;
}

}  // namespace acanthus::cells::detail
