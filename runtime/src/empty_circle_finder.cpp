#include "empty_circle_finder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace acanthus {
EmptyCircleFinder::EmptyCircleFinder(const DistanceField& field, const GridFrame& grid,
                                     double min_radius)
    : field_(field), grid_(grid), min_radius_(min_radius), inv_width_(1.0 / grid.width) {
    const std::size_t n = static_cast<std::size_t>(grid.width) * grid.height;
    state_.assign(n, none);
    state_d2_.assign(n, 0);
    discarded_.assign(n, 0);
    tiles_w_ = ((grid.width - 1) >> kTileShift) + 1;
    tiles_h_ = ((grid.height - 1) >> kTileShift) + 1;
    tiles_.reset(static_cast<std::size_t>(tiles_w_) * tiles_h_);
    dirty_.assign(static_cast<std::size_t>(tiles_w_) * tiles_h_, 0);
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
}

Circle EmptyCircleFinder::circle_of(int pixel) const {
    const double d = std::sqrt(static_cast<double>(field_.squared_distance(pixel)));
    const int j = row_of(pixel);
    return {grid_.center_of(pixel - j * grid_.width, j), (d - kMargin) * grid_.pixel};
}

bool EmptyCircleFinder::radius_ok(std::int64_t d2) const {
    const double r = (std::sqrt(static_cast<double>(d2)) - kMargin) * grid_.pixel;
    return r > 0 && r >= min_radius_;
}

bool EmptyCircleFinder::crest(std::int64_t d, std::int64_t a, std::int64_t b) {
    if (a > d || b > d) return false;
    const double bend = 2 * std::sqrt(static_cast<double>(d)) - std::sqrt(static_cast<double>(a)) -
                        std::sqrt(static_cast<double>(b));
    return bend >= kBend;
}

bool EmptyCircleFinder::on_medial_axis(int pixel) const {
    const std::int64_t d = field_.squared_distance(pixel);
    if (d == 0) return false;  // an obstacle
    const int w = grid_.width, h = grid_.height;
    const int j = row_of(pixel), i = pixel - j * w;
    static constexpr int kLine[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    if (i > 0 && j > 0 && i < w - 1 && j < h - 1) {
        for (const auto& e : kLine) {
            const int off = e[1] * w + e[0];
            if (crest(d, field_.squared_distance(pixel + off),
                      field_.squared_distance(pixel - off)))
                return true;
        }
        return false;
    }
    // At the edge of the grid only the lines with both neighbours inside are tested.
    for (const auto& e : kLine) {
        const int ai = i + e[0], aj = j + e[1], bi = i - e[0], bj = j - e[1];
        if (ai < 0 || aj < 0 || ai >= w || aj >= h || bi < 0 || bj < 0 || bi >= w || bj >= h)
            continue;
        if (crest(d, field_.squared_distance(aj * w + ai), field_.squared_distance(bj * w + bi)))
            return true;
    }
    return false;
}

bool EmptyCircleFinder::shape_eligible(int pixel) const {
    const std::int64_t d2 = field_.squared_distance(pixel);
    if (d2 < min_d2_ || d2 == DistanceField::infinite) return false;
    return on_medial_axis(pixel) && field_.nearest_kind(pixel) == ObstacleKind::element;
}

int EmptyCircleFinder::tile_of(int pixel) const {
    const int j = row_of(pixel), i = pixel - j * grid_.width;
    return (j >> kTileShift) * tiles_w_ + (i >> kTileShift);
}

void EmptyCircleFinder::mark_dirty(int tile) {
    if (dirty_[tile]) return;
    dirty_[tile] = 1;
    dirty_list_.push_back(tile);
}

void EmptyCircleFinder::rescan(int tile) {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int i0 = ti << kTileShift, j0 = tj << kTileShift;
    const int i1 = std::min(grid_.width, i0 + (1 << kTileShift));
    const int j1 = std::min(grid_.height, j0 + (1 << kTileShift));
    Key best = 0;
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            const int p = j * grid_.width + i;
            if (state_[p] == candidate) best = std::max(best, key_of(p, state_d2_[p]));
        }
    tiles_.set(static_cast<std::size_t>(tile), best);
}

// Re-decides the state of a pixel whose distance, or a neighbour's, may have changed.
void EmptyCircleFinder::consider(int pixel) {
    const std::int32_t d2 = static_cast<std::int32_t>(field_.squared_distance(pixel));
    if (d2 < min_d2_ && state_[pixel] == none) return;  // too small to matter, already none
    // Same distance: a candidate stays one (neighbours only get lower), a blocked one stays
    // blocked; a non-candidate may have become one.
    if (state_[pixel] != none && state_d2_[pixel] == d2) return;
    state_[pixel] = shape_eligible(pixel) && discarded_[pixel] != d2 ? candidate : none;
    state_d2_[pixel] = d2;
}

void EmptyCircleFinder::refresh(int tile) {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int i0 = ti << kTileShift, j0 = tj << kTileShift;
    const int i1 = std::min(grid_.width, i0 + (1 << kTileShift));
    const int j1 = std::min(grid_.height, j0 + (1 << kTileShift));
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) consider(j * grid_.width + i);
    rescan(tile);
}

void EmptyCircleFinder::rebuild() {
    blocked_.clear();
    std::fill(state_.begin(), state_.end(), none);
    for (int t = 0; t < tiles_w_ * tiles_h_; ++t) refresh(t);
}

void EmptyCircleFinder::update(const std::vector<int>& changed) {
    // A changed pixel can change its own state and its 8 neighbours': refresh every tile that
    // holds one of them.
    constexpr int kMask = (1 << kTileShift) - 1;
    for (int p : changed) {
        const int j = row_of(p), i = p - j * grid_.width;
        const int ti = i >> kTileShift, tj = j >> kTileShift;
        const int di0 = (i & kMask) == 0 && ti > 0 ? -1 : 0;
        const int di1 = (i & kMask) == kMask && ti < tiles_w_ - 1 ? 1 : 0;
        const int dj0 = (j & kMask) == 0 && tj > 0 ? -1 : 0;
        const int dj1 = (j & kMask) == kMask && tj < tiles_h_ - 1 ? 1 : 0;
        for (int dj = dj0; dj <= dj1; ++dj)
            for (int di = di0; di <= di1; ++di) mark_dirty((tj + dj) * tiles_w_ + ti + di);
    }
    for (int t : dirty_list_) {
        dirty_[t] = 0;
        refresh(t);
    }
    dirty_list_.clear();
}

void EmptyCircleFinder::release(const std::vector<int>& removed_ids) {
    for (int id : removed_ids) {
        if (id < 0 || static_cast<std::size_t>(id) >= blocked_.size()) continue;
        for (const auto& [p, d2] : blocked_[id]) {
            if (state_[p] != blocked || state_d2_[p] != d2) continue;  // changed since
            state_[p] = candidate;
            const int t = tile_of(p);
            tiles_.set(static_cast<std::size_t>(t),
                       std::max(tiles_.get(static_cast<std::size_t>(t)), key_of(p, d2)));
        }
        blocked_[id].clear();
        blocked_[id].shrink_to_fit();
    }
}

void EmptyCircleFinder::release_all() {
    std::vector<int> ids(blocked_.size());
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(k);
    release(ids);
}

std::optional<EmptyCircle> EmptyCircleFinder::find(const ExcludeList& exclude) {
    for (;;) {
        const Key k = tiles_.max();
        if (k == 0) return std::nullopt;
        const int p = pixel_of(k);
        const std::int64_t d2 = d2_of(k);
        const Circle c = circle_of(p);
        const int id = exclude.find_inside(c);
        if (id < 0) return EmptyCircle{p, d2, c};
        state_[p] = blocked;
        if (static_cast<std::size_t>(id) >= blocked_.size()) blocked_.resize(id + 1);
        blocked_[id].emplace_back(p, static_cast<std::int32_t>(d2));
        rescan(tile_of(p));
    }
}

void EmptyCircleFinder::discard(const EmptyCircle& c) {
    discarded_[c.pixel] = static_cast<std::int32_t>(c.d2);
    if (state_[c.pixel] == candidate) {
        state_[c.pixel] = none;
        state_d2_[c.pixel] = static_cast<std::int32_t>(c.d2);
        rescan(tile_of(c.pixel));
    }
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
