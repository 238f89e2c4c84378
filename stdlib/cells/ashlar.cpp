// Random ashlar [5.2] on the grid tool's small units. Corners get one stone, edges stones of
// random length (alternating depth up vertical edges). Faces: by default the paper's method (a
// stone per free unit, random neighbours merged up to the maximum size: ashlar_merge.cpp);
// with AshlarMethod::rules, stones laid in reading order with a random size up to the maximum,
// chosen so that no four stones meet at a point and no straight joint runs along more than
// `ashlar_max_seam` stones where some size allows it (merging alone cannot promise either).
#include <acanthus/progress.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "ashlar_merge.hpp"
#include "context_data.hpp"
#include "course_grid.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

namespace {

using detail::Stone;

class AshlarFace {
  public:
    AshlarFace(const detail::CourseGrid& g, int max_w, int max_h, int max_seam)
        : g_(g),
          max_w_(max_w),
          max_h_(max_h),
          max_seam_(max_seam),
          owner_(static_cast<std::size_t>(g.rows() * g.units()), kBlocked) {}

    static constexpr int kBlocked = -2, kEmpty = -1;
    int& at(int r, int u) { return owner_[static_cast<std::size_t>(r * g_.units() + u)]; }
    int get(int r, int u) const {
        if (r < 0 || u < 0 || r >= g_.rows() || u >= g_.units()) return kBlocked;
        return owner_[static_cast<std::size_t>(r * g_.units() + u)];
    }
    const std::vector<Stone>& stones() const { return stones_; }

    // Whole rows of stones before any becomes a cell: each row is reported as progress.
    void lay(Random& random) {
        for (int r = 0; r < g_.rows(); ++r) {
            for (int u = 0; u < g_.units(); ++u)
                if (get(r, u) == kEmpty) lay_at(r, u, random);
            report_progress("ashlar rows", r + 1, g_.rows());
        }
    }

  private:
    bool fits(int r, int u, int h, int w) const {
        for (int i = r; i < r + h; ++i)
            for (int j = u; j < u + w; ++j)
                if (get(i, j) != kEmpty) return false;
        return true;
    }
    // Faults the stone would make: a four-way joint at its top-right corner, a bed joint under
    // it or a vertical joint right of it along more than max_seam stones.
    int faults(int r, int u, int h, int w) const {
        int f = 0;
        int x = u + w;
        if (get(r, x) == kEmpty && r > 0) {
            int a = get(r - 1, x - 1), b = get(r - 1, x);
            if (a >= 0 && b >= 0 && a != b) ++f;
        }
        int y = r + h, run = 1;
        for (int j = u - 1; j >= 0;) {  // stones left whose bottom is y too
            int s = get(y - 1, j);
            if (s < 0 ||
                stones_[static_cast<std::size_t>(s)].row + stones_[static_cast<std::size_t>(s)].h !=
                    y)
                break;
            ++run;
            j = stones_[static_cast<std::size_t>(s)].unit - 1;
        }
        for (int j = x; j < g_.units();) {
            int s = get(y - 1, j);
            if (s < 0 ||
                stones_[static_cast<std::size_t>(s)].row + stones_[static_cast<std::size_t>(s)].h !=
                    y)
                break;
            ++run;
            j = stones_[static_cast<std::size_t>(s)].unit + stones_[static_cast<std::size_t>(s)].w;
        }
        if (run > max_seam_ && y < g_.rows() && get(y, u) != kBlocked) ++f;
        run = 1;
        for (int i = r - 1; i >= 0;) {  // stones above whose right side is x too
            int s = get(i, x - 1);
            if (s < 0 || stones_[static_cast<std::size_t>(s)].unit +
                                 stones_[static_cast<std::size_t>(s)].w !=
                             x)
                break;
            ++run;
            i = stones_[static_cast<std::size_t>(s)].row - 1;
        }
        if (run > max_seam_ && get(r, x) != kBlocked) ++f;
        return f;
    }
    void lay_at(int r, int u, Random& random) {
        std::vector<std::pair<int, int>> sizes;
        for (int h = 1; h <= max_h_; ++h)
            for (int w = 1; w <= max_w_; ++w)
                if (fits(r, u, h, w)) sizes.emplace_back(h, w);
        for (std::size_t i = sizes.size(); i > 1; --i)  // Fisher-Yates with our own numbers
            std::swap(sizes[i - 1], sizes[static_cast<std::size_t>(
                                        random.uniform_int(0, static_cast<long long>(i) - 1))]);
        std::pair<int, int> best = sizes.front();
        int best_faults = 1 << 30;
        for (auto [h, w] : sizes) {
            int f = faults(r, u, h, w);
            if (f < best_faults) best_faults = f, best = {h, w};
            if (f == 0) break;
        }
        int id = static_cast<int>(stones_.size());
        stones_.push_back({r, u, best.first, best.second});
        for (int i = r; i < r + best.first; ++i)
            for (int j = u; j < u + best.second; ++j) at(i, j) = id;
    }

    const detail::CourseGrid& g_;
    int max_w_, max_h_, max_seam_;
    std::vector<int> owner_;
    std::vector<Stone> stones_;
};

}  // namespace

Generator ashlar() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        const Options& o = c.options();
        int face = detail::face_of(facade, f);
        double unit = o.ashlar_unit > 0 ? o.ashlar_unit : o.brick_height + o.mortar;
        auto& grid = c.data().layout<detail::CourseGrid>("ashlar:" + std::to_string(face), [&] {
            return detail::make_grid(facade, face, unit, unit);
        });
        const double inset = 0.25 * unit;
        if (f.kind == FeatureKind::corner) {
            Point p =
                detail::inside_corner(facade.corners()[static_cast<std::size_t>(f.index)], inset);
            int row = grid.row_at(p.y), u = grid.unit_at(p.x);
            if (row >= 0 && u >= 0)
                c.place(detail::polygon_of(grid.cell(row, u, u + 1)), grid.course(row));
            return;
        }
        if (f.kind == FeatureKind::edge) {
            const Edge& e = facade.edges()[static_cast<std::size_t>(f.index)];
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
            // Along other edges: runs of cells in a row cut into stones of random length.
            for (std::size_t i = 0; i < cells.size();) {
                int len = static_cast<int>(c.random().uniform_int(1, o.ashlar_max_width));
                std::size_t j = i + 1;
                while (j < cells.size() && j - i < static_cast<std::size_t>(len) &&
                       cells[j].first == cells[i].first &&
                       std::abs(cells[j].second - cells[j - 1].second) == 1)
                    ++j;
                int a = std::min(cells[i].second, cells[j - 1].second);
                int b = std::max(cells[i].second, cells[j - 1].second) + 1;
                c.place(detail::polygon_of(grid.cell(cells[i].first, a, b)),
                        grid.course(cells[i].first));
                i = j;
            }
            return;
        }
        FaceOccupancy& occupancy = c.face_occupancy(face);
        AshlarFace layout(grid, o.ashlar_max_width, o.ashlar_max_height, o.ashlar_max_seam);
        for (int row = 0; row < grid.rows(); ++row)
            for (int u = 0; u < grid.units(); ++u) {
                auto s = grid.at(row, u);
                if (s == detail::kOutside) continue;
                Rect r = grid.cell(row, u, u + 1);
                if (s == detail::kFull && occupancy.rect_is_free(r))
                    layout.at(row, u) = AshlarFace::kEmpty;
            }
        // Units the face only partly holds, or that others claimed in part: a stone each,
        // clipped.
        for (int row = 0; row < grid.rows(); ++row)
            for (int u = 0; u < grid.units(); ++u)
                if (grid.at(row, u) != detail::kOutside &&
                    layout.get(row, u) == AshlarFace::kBlocked)
                    c.place(detail::polygon_of(grid.cell(row, u, u + 1)), grid.course(row));
        std::vector<Stone> stones;
        if (o.ashlar_method == AshlarMethod::merge) {
            std::vector<char> free(static_cast<std::size_t>(grid.rows() * grid.units()));
            for (int row = 0; row < grid.rows(); ++row)
                for (int u = 0; u < grid.units(); ++u)
                    free[static_cast<std::size_t>(row * grid.units() + u)] =
                        layout.get(row, u) == AshlarFace::kEmpty;
            stones = detail::merge_ashlar(free, grid.rows(), grid.units(), o.ashlar_max_width,
                                          o.ashlar_max_height, c.random());
        } else {
            layout.lay(c.random());
            stones = layout.stones();
        }
        for (const Stone& s : stones)
            c.place_free_rect(
                Rect{grid.xs[s.unit], grid.ys[s.row], grid.xs[s.unit + s.w], grid.ys[s.row + s.h]},
                grid.course(s.row + s.h - 1));
    };
}

}  // namespace acanthus::cells
