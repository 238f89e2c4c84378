#include "empty_circle_finder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace acanthus {
namespace {
// 8-neighbourhood.
constexpr int kDi[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kDj[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
}  // namespace

EmptyCircleFinder::EmptyCircleFinder(const DistanceField& field, const GridFrame& grid,
                                     double min_radius)
    : field_(field), grid_(grid), min_radius_(min_radius) {
    const std::size_t n = static_cast<std::size_t>(grid.width) * grid.height;
    registered_.assign(n, 0);
    discarded_.assign(n, 0);
    // radius_ok() is monotone in d2: find its threshold once, for a cheap integer test.
    if (std::isnan(min_radius_)) min_radius_ = 0;
    const double want = std::max(0.0, min_radius_ / grid.pixel) + kMargin;
    if (want > 1e5) {  // beyond any squared distance of a grid
        min_d2_ = std::numeric_limits<std::int64_t>::max();
    } else {
        std::int64_t t = std::max<std::int64_t>(1, static_cast<std::int64_t>(want * want) - 2);
        while (!radius_ok(t)) ++t;
        while (t > 1 && radius_ok(t - 1)) --t;
        min_d2_ = t;
    }
    seen_.assign(n, 0);
}

Circle EmptyCircleFinder::circle_of(int pixel) const {
    const double d = std::sqrt(static_cast<double>(field_.squared_distance(pixel)));
    return {grid_.center_of(pixel % grid_.width, pixel / grid_.width), (d - kMargin) * grid_.pixel};
}

bool EmptyCircleFinder::radius_ok(std::int64_t d2) const {
    const double r = (std::sqrt(static_cast<double>(d2)) - kMargin) * grid_.pixel;
    return r > 0 && r >= min_radius_;
}

bool EmptyCircleFinder::on_medial_axis(int pixel) const {
    if (field_.occupancy(pixel) != ObstacleKind::none) return false;
    const std::int64_t d = field_.squared_distance(pixel);
    const int w = grid_.width, h = grid_.height;
    const int i = pixel % w, j = pixel / w;
    // A crest along one of the four lines through the pixel; a neighbour beyond the grid is no
    // higher.
    auto at_most = [&](int ni, int nj) {
        return ni < 0 || nj < 0 || ni >= w || nj >= h || field_.squared_distance(nj * w + ni) <= d;
    };
    static constexpr int kLine[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    for (const auto& e : kLine)
        if (at_most(i + e[0], j + e[1]) && at_most(i - e[0], j - e[1])) return true;
    return false;
}

bool EmptyCircleFinder::shape_eligible(int pixel) const {
    const std::int64_t d2 = field_.squared_distance(pixel);
    if (d2 < min_d2_ || d2 == DistanceField::infinite) return false;
    return field_.nearest_kind(pixel) == ObstacleKind::element && on_medial_axis(pixel);
}

void EmptyCircleFinder::consider(int pixel) {
    if (!shape_eligible(pixel)) return;
    const std::int64_t d2 = field_.squared_distance(pixel);
    if (registered_[pixel] == d2) return;  // already waiting in the heap or blocked
    registered_[pixel] = static_cast<std::int32_t>(d2);
    heap_.push(key_of(pixel, d2));
}

void EmptyCircleFinder::rebuild() {
    heap_ = {};
    blocked_.clear();
    std::fill(registered_.begin(), registered_.end(), 0);
    const int n = grid_.width * grid_.height;
    for (int p = 0; p < n; ++p) consider(p);
}

void EmptyCircleFinder::update(const std::vector<int>& changed) {
    if (++stamp_ == 0) {
        std::fill(seen_.begin(), seen_.end(), 0);
        stamp_ = 1;
    }
    const int w = grid_.width, h = grid_.height;
    for (int p : changed) {
        const int i = p % w, j = p / w;
        for (int k = -1; k < 8; ++k) {
            const int ni = k < 0 ? i : i + kDi[k], nj = k < 0 ? j : j + kDj[k];
            if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
            const int q = nj * w + ni;
            if (seen_[q] == stamp_) continue;
            seen_[q] = stamp_;
            consider(q);
        }
    }
}

void EmptyCircleFinder::release(const std::vector<int>& removed_ids) {
    for (int id : removed_ids) {
        if (id < 0 || static_cast<std::size_t>(id) >= blocked_.size()) continue;
        for (Key k : blocked_[id]) heap_.push(k);
        blocked_[id].clear();
        blocked_[id].shrink_to_fit();
    }
}

void EmptyCircleFinder::release_all() {
    for (auto& keys : blocked_) {
        for (Key k : keys) heap_.push(k);
        keys.clear();
        keys.shrink_to_fit();
    }
}

std::optional<EmptyCircle> EmptyCircleFinder::find(const ExcludeList& exclude) {
    while (!heap_.empty()) {
        const Key k = heap_.top();
        const int p = pixel_of(k);
        const std::int64_t d2 = d2_of(k);
        if (field_.squared_distance(p) != d2 || discarded_[p] == d2 || !shape_eligible(p)) {
            heap_.pop();
            if (registered_[p] == d2 && discarded_[p] != d2) registered_[p] = 0;
            continue;
        }
        const Circle c = circle_of(p);
        const int id = exclude.find_inside(c);
        if (id >= 0) {
            heap_.pop();
            if (static_cast<std::size_t>(id) >= blocked_.size()) blocked_.resize(id + 1);
            blocked_[id].push_back(k);
            continue;
        }
        // Stays in the heap: if nothing changes here it is the answer again next time.
        return EmptyCircle{p, d2, c};
    }
    return std::nullopt;
}

void EmptyCircleFinder::discard(const EmptyCircle& c) {
    discarded_[c.pixel] = static_cast<std::int32_t>(c.d2);
    // Its live entry, if any, is popped as invalid; consider() will not push it again while
    // registered_ still holds this distance.
    registered_[c.pixel] = static_cast<std::int32_t>(c.d2);
}

std::optional<EmptyCircle> EmptyCircleFinder::find_by_scan(const ExcludeList& exclude) const {
    const int n = grid_.width * grid_.height;
    Key best = 0;
    bool found = false;
    for (int p = 0; p < n; ++p) {
        const std::int64_t d2 = field_.squared_distance(p);
        if (d2 == DistanceField::infinite || field_.occupancy(p) != ObstacleKind::none) continue;
        const Key k = key_of(p, d2);
        if (found && k < best) continue;
        if (discarded_[p] == d2 || !shape_eligible(p) || exclude.any_inside(circle_of(p))) continue;
        best = k;
        found = true;
    }
    if (!found) return std::nullopt;
    const int p = pixel_of(best);
    return EmptyCircle{p, d2_of(best), circle_of(p)};
}

std::vector<int> EmptyCircleFinder::best_candidates(std::size_t limit) const {
    std::vector<Key> keys;
    const int n = grid_.width * grid_.height;
    for (int p = 0; p < n; ++p)
        if (shape_eligible(p)) keys.push_back(key_of(p, field_.squared_distance(p)));
    const std::size_t m = std::min(limit, keys.size());
    std::partial_sort(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(m), keys.end(),
                      [](Key a, Key b) { return a > b; });
    std::vector<int> out;
    out.reserve(m);
    for (std::size_t k = 0; k < m; ++k) out.push_back(pixel_of(keys[k]));
    return out;
}

}  // namespace acanthus
