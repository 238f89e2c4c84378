#include "hole_finder.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <deque>
#include <iterator>

namespace acanthus::growth::detail {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

// The placed motifs' centres, packed once per search: a sample far from every motif then costs
// a logarithmic query, where the arrangement's grid would visit every cell out to the motif.
class HoleFinder::Placed {
  public:
    explicit Placed(const Arrangement& pattern) {
        std::vector<BPoint> points;
        for (const Node& n : pattern.nodes())
            if (n.placed()) points.emplace_back(n.position.x, n.position.y);
        tree_ = Tree(points.begin(), points.end());
    }
    // The distance to the nearest placed centre, or `cap` when none is nearer.
    double nearest(Point p, double cap) const {
        double best = cap;
        const BPoint q(p.x, p.y);
        for (auto it = tree_.qbegin(bgi::nearest(q, 1)); it != tree_.qend(); ++it)
            best = std::min(best, bg::distance(*it, q));
        return best;
    }

  private:
    using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;
    using Tree = bgi::rtree<BPoint, bgi::quadratic<16>>;
    Tree tree_;
};

HoleFinder::HoleFinder(const Panel& panel, const std::vector<Point>& starts, double spacing,
                       double motif_radius, double tolerance, double max_samples)
    : panel_(panel), spacing_(spacing), motif_radius_(motif_radius), tolerance_(tolerance) {
    Rect box = panel.bounds();
    if (!(spacing > 0) || !(box.width() > 0) || !(box.height() > 0)) return;
    // A quarter spacing finds a hole's radius within a fifth of a spacing; a huge panel gets a
    // coarser grid so that the search stays under `max_samples`.
    double step = std::max(spacing / 4, std::sqrt(box.width() * box.height() / max_samples));
    const long nx = static_cast<long>(std::ceil(box.width() / step));
    const long ny = static_cast<long>(std::ceil(box.height() / step));
    auto at = [&](long i, long j) {
        return Point{box.x0 + (static_cast<double>(i) + 0.5) * step,
                     box.y0 + (static_cast<double>(j) + 0.5) * step};
    };
    std::vector<signed char> state(static_cast<std::size_t>(nx * ny), 0);  // 1 in, -1 out
    auto inside = [&](long i, long j) {
        signed char& s = state[static_cast<std::size_t>(j * nx + i)];
        if (s == 0) s = panel.contains(at(i, j)) ? 1 : -1;
        return s > 0;
    };
    // Flood from the starts through samples inside, never across a boundary stroke.
    std::vector<bool> reached(state.size(), false);
    std::deque<std::pair<long, long>> todo;
    for (Point s : starts) {
        long i = std::clamp(static_cast<long>((s.x - box.x0) / step), 0L, nx - 1);
        long j = std::clamp(static_cast<long>((s.y - box.y0) / step), 0L, ny - 1);
        if (!inside(i, j) || reached[static_cast<std::size_t>(j * nx + i)]) continue;
        reached[static_cast<std::size_t>(j * nx + i)] = true;
        todo.push_back({i, j});
    }
    while (!todo.empty()) {
        auto [i, j] = todo.front();
        todo.pop_front();
        const long di[] = {1, -1, 0, 0}, dj[] = {0, 0, 1, -1};
        for (int k = 0; k < 4; ++k) {
            long a = i + di[k], b = j + dj[k];
            if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
            std::size_t n = static_cast<std::size_t>(b * nx + a);
            if (reached[n] || !inside(a, b) || !panel.reaches(at(i, j), at(a, b))) continue;
            reached[n] = true;
            todo.push_back({a, b});
        }
    }
    for (long j = 0; j < ny; ++j)
        for (long i = 0; i < nx; ++i)
            if (reached[static_cast<std::size_t>(j * nx + i)]) samples_.push_back({at(i, j)});
}

bool HoleFinder::fits(Sample& s) const {
    if (s.fits == 0) s.fits = panel_.admits({s.at, motif_radius_}, tolerance_) ? 1 : -1;
    return s.fits > 0;
}

double HoleFinder::depth(Sample& s) const {
    if (s.depth < 0) s.depth = panel_.clearance(s.at);
    return s.depth;
}

bool HoleFinder::find(const Arrangement& pattern, double at_least, Hole& hole) {
    // Beyond three spacings every sample is empty enough; depth then picks the middle of a lobe.
    const double cap = std::max(3 * spacing_, at_least);
    const Placed placed(pattern);
    double best_score = -1;
    for (Sample& s : samples_) {
        if (!s.open) continue;
        double free = placed.nearest(s.at, cap);
        if (free < at_least || !fits(s)) {
            s.open = false;  // until reopen_covered()
            continue;
        }
        double score = std::min(free, depth(s) + spacing_);
        if (score > best_score) {
            best_score = score;
            hole = {s.at, free};
            // Nothing scores above the cap, and ties go to the first sample: the search is over
            // (an empty panel would otherwise ask about every sample on every search).
            if (score >= cap) break;
        }
    }
    return best_score >= 0;
}

void HoleFinder::exclude(Point p, double radius) {
    for (Sample& s : samples_)
        if (distance(s.at, p) <= radius) s.open = false, s.excluded = true;
}

void HoleFinder::reopen_covered() {
    for (Sample& s : samples_)
        if (!s.excluded && s.fits >= 0) s.open = true;
}

double HoleFinder::largest(const Arrangement& pattern) {
    double best = 0;
    const double cap = 1e3 * spacing_;
    const Placed placed(pattern);
    for (Sample& s : samples_) {
        double free = placed.nearest(s.at, cap);
        if (free > best && fits(s)) best = free;
    }
    return best;
}

}  // namespace acanthus::growth::detail
