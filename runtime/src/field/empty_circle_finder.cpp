#include "field/empty_circle_finder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "field/tile_masks.hpp"

namespace acanthus::detail {

using namespace tile_masks;

static_assert(PendingBlocks::kTileShift == 3, "the lazy field trusts the finder's tiles");

std::vector<std::uint8_t> nonzero_tiles(const std::vector<std::uint8_t>& bytes, int width,
                                        int height) {
    constexpr int kTile = 8;
    const int tw = (width + kTile - 1) / kTile, th = (height + kTile - 1) / kTile;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(tw) * th, 0);
    const int whole = width / kTile;  // tiles whose eight columns lie in the row
    for (int j = 0; j < height; ++j) {
        const std::uint8_t* row = bytes.data() + static_cast<std::size_t>(j) * width;
        std::uint8_t* tiles = out.data() + static_cast<std::size_t>(j / kTile) * tw;
        for (int t = 0; t < whole; ++t) {
            std::uint64_t word;
            std::memcpy(&word, row + t * kTile, sizeof word);
            if (word) tiles[t] = 1;
        }
        for (int i = whole * kTile; i < width; ++i)
            if (row[i]) tiles[whole] = 1;
    }
    return out;
}

EmptyCircleFinder::EmptyCircleFinder(DistanceField& field, const GridFrame& grid, double min_radius)
    : field_(field),
      grid_(grid),
      min_radius_(min_radius),
      inv_width_(1.0 / grid.width),
      manhattan_(field.metric() == DistanceMetric::manhattan) {
    tiles_w_ = ((grid.width - 1) >> kTileShift) + 1;
    tiles_h_ = ((grid.height - 1) >> kTileShift) + 1;
    blocks_w_ = ((tiles_w_ - 1) >> 3) + 1;
    tiles_.reset(slot_of(tiles_w_ * tiles_h_ - 1) + 1);
    masks_.assign(static_cast<std::size_t>(tiles_w_) * tiles_h_, TileMasks{});
    deferred_.assign(static_cast<std::size_t>(blocks_w_) * (((tiles_h_ - 1) >> 3) + 1), 0);
    const int w = grid.width;
    offsets_[0] = 1;
    offsets_[1] = w;
    offsets_[2] = w + 1;
    offsets_[3] = 1 - w;
    // radius_ok() is monotone in d2: find its threshold once, for a cheap integer test.
    if (std::isnan(min_radius_)) min_radius_ = 0;
    const double want = std::max(0.0, min_radius_ / grid.pixel) + kMargin;
    if (want > 1e5) {  // beyond any squared distance of a grid
        min_d2_ = std::numeric_limits<std::int64_t>::max();
    } else {
        const double scale = manhattan_ ? 2 : 1;  // city-block d covers a circle of d / sqrt 2
        std::int64_t t =
            std::max<std::int64_t>(1, static_cast<std::int64_t>(scale * want * want) - 2);
        while (!radius_ok(t)) ++t;
        while (t > 1 && radius_ok(t - 1)) --t;
        min_d2_ = t;
    }
}

void EmptyCircleFinder::set_centres(std::vector<std::uint8_t> allowed) {
    centres_ = std::move(allowed);
    block_centres_.clear();
    tile_centres_.clear();
    if (centres_.empty()) return;
    tile_centres_ = nonzero_tiles(centres_, grid_.width, grid_.height);
    // Blocks of 8 x 8 tiles, numbered as PendingBlocks numbers them.
    block_centres_.assign(deferred_.size(), 0);
    for (int tj = 0; tj < tiles_h_; ++tj)
        for (int ti = 0; ti < tiles_w_; ++ti)
            if (tile_centres_[static_cast<std::size_t>(tj) * tiles_w_ + ti])
                block_centres_[static_cast<std::size_t>((tj >> 3) * blocks_w_ + (ti >> 3))] = 1;
}

std::vector<std::uint8_t> EmptyCircleFinder::tile_centres() const { return tile_centres_; }

double EmptyCircleFinder::radius_pixels(std::int64_t d2) const {
    const double d = std::sqrt(static_cast<double>(d2));
    // The nearest obstacle pixel centre at city-block distance d is at least d / sqrt 2 away.
    return (manhattan_ ? d * M_SQRT1_2 : d) - kMargin;
}

Circle EmptyCircleFinder::circle_of(int pixel) const {
    const int j = row_of(pixel);
    return {grid_.center_of(pixel - j * grid_.width, j),
            radius_pixels(field_.squared_distance(pixel)) * grid_.pixel};
}

bool EmptyCircleFinder::radius_ok(std::int64_t d2) const {
    const double r = radius_pixels(d2) * grid_.pixel;
    return r > 0 && r >= min_radius_;
}

bool EmptyCircleFinder::bends(std::int64_t d, std::int64_t a, std::int64_t b) {
    // With a, b <= d the bend lies between s / (2 sqrt d) and s / sqrt d, s = 2d - a - b:
    // most pixels are decided by these bounds without a square root, with margins far wider
    // than the rounding of the exact test below (so the decisions are the same).
    const double s = static_cast<double>(2 * d - a - b), dd = static_cast<double>(d);
    if (s * s >= 1.21 * dd) return true;    // bend >= 0.55
    if (s * s < 0.2025 * dd) return false;  // bend < 0.45
    const double bend = 2 * std::sqrt(static_cast<double>(d)) - std::sqrt(static_cast<double>(a)) -
                        std::sqrt(static_cast<double>(b));
    return bend >= kBend;
}

bool EmptyCircleFinder::crest_at(int pixel, int i, int j, std::int64_t d) const {
    const int w = grid_.width, h = grid_.height;
    if (i > 0 && j > 0 && i < w - 1 && j < h - 1) return crest_inside(pixel, d);
    if (manhattan_) {  // every 4-neighbour inside the grid at most as far
        return (i == 0 || field_.squared_distance(pixel - 1) <= d) &&
               (i == w - 1 || field_.squared_distance(pixel + 1) <= d) &&
               (j == 0 || field_.squared_distance(pixel - w) <= d) &&
               (j == h - 1 || field_.squared_distance(pixel + w) <= d);
    }
    // At the edge of the grid only the lines with both neighbours inside are tested.
    static constexpr int kLine[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
    for (const auto& e : kLine) {
        const int ai = i + e[0], aj = j + e[1], bi = i - e[0], bj = j - e[1];
        if (ai < 0 || aj < 0 || ai >= w || aj >= h || bi < 0 || bj < 0 || bi >= w || bj >= h)
            continue;
        if (crest(d, field_.squared_distance(aj * w + ai), field_.squared_distance(bj * w + bi)))
            return true;
    }
    return false;
}

bool EmptyCircleFinder::on_medial_axis(int pixel) const {
    const std::int64_t d = field_.squared_distance(pixel);
    if (d == 0) return false;  // an obstacle
    const int j = row_of(pixel);
    return crest_at(pixel, pixel - j * grid_.width, j, d);
}

bool EmptyCircleFinder::shape_eligible(int pixel) const {
    const std::int64_t d2 = field_.squared_distance(pixel);
    if (d2 < min_d2_ || d2 == DistanceField::infinite || !may_centre(pixel)) return false;
    return on_medial_axis(pixel) && element_may_stop(pixel);
}

bool EmptyCircleFinder::is_discarded(int pixel, std::int64_t d2) const {
    const auto it = discarded_.find(pixel);
    return it != discarded_.end() && it->second == d2;
}

int EmptyCircleFinder::tile_of(int pixel) const {
    const int j = row_of(pixel), i = pixel - j * grid_.width;
    return (j >> kTileShift) * tiles_w_ + (i >> kTileShift);
}

int EmptyCircleFinder::bit_of(int pixel) const {
    constexpr int kMask = (1 << kTileShift) - 1;
    const int j = row_of(pixel), i = pixel - j * grid_.width;
    return ((j & kMask) << kTileShift) | (i & kMask);
}

void EmptyCircleFinder::mark_near(int tile, std::uint64_t bits) {
    if (masks_[tile].near == 0) dirty_list_.push_back(tile);
    masks_[tile].near |= bits;
}

void EmptyCircleFinder::rescan(int tile) {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int i0 = ti << kTileShift, j0 = tj << kTileShift;
    // A lazy tile's bound may be below distances it has not measured yet: those are stale.
    const std::int32_t bound = field_.lazy() ? field_.far_blocks().tile_bound(ti, tj)
                                             : std::numeric_limits<std::int32_t>::max();
    Key best = 0;
    for (std::uint64_t bits = masks_[tile].candidates; bits; bits &= bits - 1) {
        const int b = std::countr_zero(bits);
        const int p = (j0 + (b >> kTileShift)) * grid_.width + i0 + (b & 7);
        const std::int32_t d2 = field_.squared_distances()[p];
        if (d2 <= bound) best = std::max(best, key_of(p, d2));
    }
    // The tree's leaf lies far from the masks: touched only when the key moves.
    if (masks_[tile].key == best) return;
    masks_[tile].key = best;
    tiles_.set(slot_at(ti, tj), best);
}

template <bool kInside>
void EmptyCircleFinder::consider(int pixel, int i, int j, int tile, int bit) {
    const std::int32_t d2 = field_.squared_distances()[pixel];
    const std::uint64_t mask = std::uint64_t{1} << bit;
    TileMasks& m = masks_[tile];
    const bool changed = (m.changed & mask) != 0;
    if (changed && (m.discarded & mask)) {  // a discard holds for its distance only
        discarded_.erase(pixel);
        m.discarded &= ~mask;
    }
    const bool was_none = ((m.candidates | m.blocked) & mask) == 0;
    if (d2 < min_d2_ && was_none) return;  // too small to matter, already none
    // Same distance: a candidate stays one (neighbours only get lower), a blocked one stays
    // blocked; a non-candidate may have become one.
    if (!was_none && !changed) return;
    bool eligible = d2 >= min_d2_ && d2 != DistanceField::infinite && may_centre(pixel);
    if constexpr (kInside)
        eligible = eligible && crest_inside(pixel, d2);
    else
        eligible = eligible && crest_at(pixel, i, j, d2);
    // Nearer than the tile's nearest boundary pixel: the nearest obstacle is an element.
    eligible = eligible && (d2 < boundary_floor_[tile] || element_may_stop(pixel)) &&
               !((m.discarded & mask) && discarded_.at(pixel) == d2);
    m.candidates = eligible ? m.candidates | mask : m.candidates & ~mask;
    m.blocked &= ~mask;
}

template <bool kInside>
void EmptyCircleFinder::refresh_bits(int tile, std::uint64_t bits) {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int i0 = ti << kTileShift, j0 = tj << kTileShift;
    const int w = grid_.width, h = grid_.height;
    for (; bits; bits &= bits - 1) {
        const int b = std::countr_zero(bits);
        const int i = i0 + (b & 7), j = j0 + (b >> kTileShift);
        if (!kInside && (i >= w || j >= h)) continue;  // beyond the grid in an edge tile
        consider<kInside>(j * w + i, i, j, tile, b);
    }
}

std::uint64_t EmptyCircleFinder::maybe_crests(int tile, std::uint64_t bits) const {
    static_assert(kTileShift == 3, "rows of 8 pixels");
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int w = grid_.width;
    const std::int32_t* d2 = field_.squared_distances();
    const std::int32_t min_d2 =
        static_cast<std::int32_t>(std::min<std::int64_t>(min_d2_, DistanceField::infinite));
    std::uint64_t out = 0;
    for (int r = 0; r < 8; ++r) {
        if (((bits >> (8 * r)) & 0xff) == 0) continue;
        const int p0 = ((tj << kTileShift) + r) * w + (ti << kTileShift);
        const std::int32_t* mid = d2 + p0;
        const std::uint64_t want = (bits >> (8 * r)) & 0xff;
        const std::uint32_t row =
            ((want & 0x0f) ? crest_lanes(mid - w, mid, mid + w, min_d2) : 0u) |
            ((want & 0xf0) ? crest_lanes(mid - w + 4, mid + 4, mid + w + 4, min_d2) << 4 : 0u) |
            static_cast<std::uint32_t>(
                ((masks_[tile].candidates | masks_[tile].blocked) >> (8 * r)) & 0xff);
        out |= static_cast<std::uint64_t>(row) << (8 * r);
    }
    return out & bits;
}

void EmptyCircleFinder::refresh(int tile, std::uint64_t bits) {
    // A tile away from the grid's edge has every pixel's 8 neighbours inside the grid. There,
    // a pixel in state none that has no line with both neighbours at most as far as itself
    // (or is too near an obstacle) stays none: only the others are re-decided.
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const std::uint64_t before = masks_[tile].candidates;
    if (ti > 0 && tj > 0 && ti < tiles_w_ - 1 && tj < tiles_h_ - 1)
        refresh_bits<true>(tile, maybe_crests(tile, bits));
    else
        refresh_bits<false>(tile, bits);
    // The tile's best key moves only with its candidates or their distances.
    if (masks_[tile].candidates != before || (before & masks_[tile].changed) != 0) rescan(tile);
}

void EmptyCircleFinder::prefetch(int tile) const {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int j0 = std::max(0, (tj << kTileShift) - 1);
    const int j1 = std::min(grid_.height - 1, (tj << kTileShift) + (1 << kTileShift));
    const std::int32_t* d2 = field_.squared_distances() + (ti << kTileShift);
    for (int j = j0; j <= j1; ++j)
        __builtin_prefetch(d2 + static_cast<std::size_t>(j) * grid_.width);
}

void EmptyCircleFinder::rebuild() {
    blocked_.clear();
    for (TileMasks& m : masks_) {
        m.candidates = m.blocked = 0;
        m.key = 0;
        m.pending = m.stale = 0;
    }
    std::fill(deferred_.begin(), deferred_.end(), 0);
    tiles_.reset(slot_of(tiles_w_ * tiles_h_ - 1) + 1);
    boundary_floor_.assign(static_cast<std::size_t>(tiles_w_) * tiles_h_,
                           std::numeric_limits<std::int32_t>::max());
    for (int j = 0; j < grid_.height; ++j) {
        const std::int32_t* row =
            field_.boundary_squared_distances() + static_cast<std::size_t>(j) * grid_.width;
        std::int32_t* floor =
            boundary_floor_.data() + static_cast<std::size_t>(j >> kTileShift) * tiles_w_;
        // Beyond the kept columns every distance is infinite: those floors stay so.
        const auto [kept0, kept1] = field_.kept_columns(j);
        for (int ti = kept0 >> kTileShift; ti < std::min(tiles_w_, ((kept1 - 1) >> kTileShift) + 1);
             ++ti) {  // a tile's row at a time, in vector lanes
            const int i0 = ti << kTileShift, i1 = std::min(grid_.width, i0 + (1 << kTileShift));
            std::int32_t m = floor[ti];
            if (i1 - i0 == 8) {
                const Lanes a = load_lanes(row + i0), b = load_lanes(row + i0 + 4);
                const Lanes v = a < b ? a : b;
                m = std::min({m, v[0], v[1], v[2], v[3]});
            } else {
                for (int i = i0; i < i1; ++i) m = std::min(m, row[i]);
            }
            floor[ti] = m;
        }
    }
    // A tile the lazy field leaves out holds no pixel that may centre a circle: none to decide.
    for (int t = 0; t < tiles_w_ * tiles_h_; ++t)
        if (!field_.lazy() || field_.far_blocks().keeps_tile(t)) refresh(t, ~std::uint64_t{0});
    blocks_.reset(field_.lazy() ? static_cast<std::size_t>(field_.far_blocks().count()) : 0);
    if (field_.lazy()) {
        field_.far_blocks().clear_raised();
        field_.far_blocks().clear_made_exact();
    }
}

void EmptyCircleFinder::distrust_new_blocks() {
    if (!field_.lazy()) return;
    PendingBlocks& far = field_.far_blocks();
    for (int b : far.raised()) {
        // Settling the block changes only candidates of squared distance up to its reach; the
        // low word names the block.
        if (!far.trusted(b) && far.reach(b) >= min_d2_ && block_may_centre(b))
            blocks_.set(static_cast<std::size_t>(b), key_of(b, far.reach(b)));
    }
    far.clear_raised();
}

void EmptyCircleFinder::tighten(int block, std::int64_t threshold) {
    settled_.clear();
    field_.tighten(block, threshold, &settled_);
    const PendingBlocks& far = field_.far_blocks();
    // A block whose reach is below the smallest candidate's distance can hold none.
    const bool none = far.trusted(block) || far.reach(block) < min_d2_ || !block_may_centre(block);
    blocks_.set(static_cast<std::size_t>(block), none ? 0 : key_of(block, far.reach(block)));
    update(settled_);
}

void EmptyCircleFinder::trust_tile(int tile) {
    settled_.clear();
    field_.trust_tile(tile, &settled_);
    update(settled_);
}

void EmptyCircleFinder::settle_all() {
    if (!field_.lazy()) return;
    for (int b = 0; b < field_.far_blocks().count(); ++b)
        if (!field_.far_blocks().trusted(b)) tighten(b, 0);
}

void EmptyCircleFinder::update(const std::vector<int>& changed) {
    constexpr int kMask = (1 << kTileShift) - 1;
    // Changed pixels come mostly in runs along rows: marked a tile row segment at a time.
    const std::size_t n = changed.size();
    const int* c = changed.data();
    for (std::size_t k = 0; k < n;) {
        const int p = c[k];
        const int j = row_of(p), i = p - j * grid_.width;
        const std::size_t room = static_cast<std::size_t>(std::min((i | kMask) + 1, grid_.width) -
                                                          i);  // pixels left in this tile row
        std::size_t len = 1;
        while (len < room && k + len < n && c[k + len] == p + static_cast<int>(len)) ++len;
        mark_changed((j >> kTileShift) * tiles_w_ + (i >> kTileShift),
                     ((std::uint64_t{1} << len) - 1)
                         << (((j & kMask) << kTileShift) | (i & kMask)));
        k += len;
    }
    refresh_changed();
}

void EmptyCircleFinder::update(const std::vector<TileChange>& changed) {
    for (const TileChange& c : changed) mark_changed(c.tile, c.pixels);
    refresh_changed();
}

void EmptyCircleFinder::refresh_changed() {
    // A changed pixel can change its own state and its 8 neighbours': each tile gathers the
    // pixels next to a change, its own and its neighbours'.
    for (int t : changed_tiles_) {
        const std::uint64_t m = masks_[t].changed;
        const int ti = t % tiles_w_, tj = t / tiles_w_;
        const bool left = ti > 0, right = ti<tiles_w_ - 1, up = tj> 0, down = tj < tiles_h_ - 1;
        std::uint64_t own = m | ((m << 1) & ~kColumn0) | ((m >> 1) & ~kColumn7);
        mark_near(t, own | (own << 8) | (own >> 8));
        const auto column = [](std::uint64_t c) { return c | (c << 8) | (c >> 8); };
        const auto row = [](std::uint64_t r) { return (r | ((r << 1) & 0xfe) | (r >> 1)) & 0xff; };
        if (left && (m & kColumn0)) mark_near(t - 1, column((m & kColumn0) << 7));
        if (right && (m & kColumn7)) mark_near(t + 1, column((m & kColumn7) >> 7));
        if (up && (m & kRow0)) mark_near(t - tiles_w_, row(m & kRow0) << 56);
        if (down && (m & kRow7)) mark_near(t + tiles_w_, row(m >> 56));
        if (left && up && (m & 1)) mark_near(t - tiles_w_ - 1, std::uint64_t{1} << 63);
        if (right && up && (m & 0x80)) mark_near(t - tiles_w_ + 1, std::uint64_t{1} << 56);
        if (left && down && (m & (std::uint64_t{1} << 56))) mark_near(t + tiles_w_ - 1, 0x80);
        if (right && down && (m >> 63)) mark_near(t + tiles_w_ + 1, 1);
    }
    if (field_.lazy()) {
        wake_trusted();
        // A tile not trusted keeps its pixels to re-decide: find() uses no candidate of it
        // before it is trusted, and its block's reach covers the candidates it may gain.
        const PendingBlocks& far = field_.far_blocks();
        std::size_t kept = 0;
        for (const int t : dirty_list_) {
            const int ti = t % tiles_w_, tj = t / tiles_w_;
            if (far.tile_trusted(ti, tj)) {
                dirty_list_[kept++] = t;
                continue;
            }
            TileMasks& m = masks_[t];
            m.pending |= m.near;
            m.stale |= m.changed;
            m.near = 0;
            const std::size_t slot = slot_at(ti, tj);
            deferred_[slot >> 6] |= std::uint64_t{1} << (slot & 63);
        }
        dirty_list_.resize(kept);
    }
    // The tiles' rows lie far apart in the field: each fetched two tiles ahead.
    const std::size_t dirty = dirty_list_.size();
    for (std::size_t k = 0; k < std::min<std::size_t>(2, dirty); ++k) prefetch(dirty_list_[k]);
    for (std::size_t k = 0; k < dirty; ++k) {
        const int t = dirty_list_[k];
        if (k + 2 < dirty) prefetch(dirty_list_[k + 2]);
        const std::uint64_t near = masks_[t].near;
        masks_[t].near = 0;
        refresh(t, near);
    }
    dirty_list_.clear();
    for (int t : changed_tiles_) masks_[t].changed = 0;
    changed_tiles_.clear();
    distrust_new_blocks();
}

void EmptyCircleFinder::wake_trusted() {
    PendingBlocks& far = field_.far_blocks();
    for (const int s : far.made_exact()) {
        const int ti = s % tiles_w_, tj = s / tiles_w_;
        for (int nj = std::max(0, tj - 1); nj <= std::min(tiles_h_ - 1, tj + 1); ++nj)
            for (int ni = std::max(0, ti - 1); ni <= std::min(tiles_w_ - 1, ti + 1); ++ni) {
                const std::size_t slot = slot_at(ni, nj);
                std::uint64_t& deferred = deferred_[slot >> 6];
                const std::uint64_t bit = std::uint64_t{1} << (slot & 63);
                if (!(deferred & bit) || !far.tile_trusted(ni, nj)) continue;
                const int u = nj * tiles_w_ + ni;
                deferred &= ~bit;
                TileMasks& m = masks_[u];
                if (m.changed == 0) changed_tiles_.push_back(u);
                m.changed |= m.stale;
                mark_near(u, m.pending);
                m.pending = m.stale = 0;
            }
    }
    far.clear_made_exact();
}

void EmptyCircleFinder::release(const std::vector<int>& removed_ids) {
    for (int id : removed_ids) {
        if (id < 0 || static_cast<std::size_t>(id) >= blocked_.size()) continue;
        for (const auto& [p, d2] : blocked_[id]) {
            const int t = tile_of(p);
            const std::uint64_t mask = std::uint64_t{1} << bit_of(p);
            // Its distance changed since (distances only decrease), or it is no longer blocked.
            if (!(masks_[t].blocked & mask) || field_.squared_distance(p) != d2) continue;
            masks_[t].blocked &= ~mask;
            masks_[t].candidates |= mask;
            masks_[t].key = std::max(masks_[t].key, key_of(p, d2));
            tiles_.set(slot_of(t), masks_[t].key);
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

std::optional<EmptyCircle> EmptyCircleFinder::find(const CircleBlocker& blocker) {
    for (;;) {
        const Key k = tiles_.max();
        const Key b = blocks_.max();
        if (b != 0 && (k == 0 || d2_of(b) >= d2_of(k))) {
            // A block not trusted may hold a candidate as good: trust the tiles that may.
            tighten(pixel_of(b), k == 0 ? min_d2_ : d2_of(k));
            continue;
        }
        if (k == 0) return std::nullopt;
        const int p = pixel_of(k);
        if (field_.lazy() && !field_.far_blocks().tile_trusted(tile_of(p))) {
            // Its key may rest on a stale distance: above the tile's bound it does.
            if (d2_of(k) > field_.far_blocks().tile_bound(tile_of(p)))
                rescan(tile_of(p));
            else
                trust_tile(tile_of(p));
            continue;
        }
        const std::int64_t d2 = d2_of(k);
        const Circle c = circle_of(p);
        const int id = blocker.blocker_inside(c);
        if (id < 0) return EmptyCircle{p, d2, c};
        const std::uint64_t mask = std::uint64_t{1} << bit_of(p);
        masks_[tile_of(p)].blocked |= mask;
        masks_[tile_of(p)].candidates &= ~mask;
        if (static_cast<std::size_t>(id) >= blocked_.size()) blocked_.resize(id + 1);
        blocked_[id].emplace_back(p, static_cast<std::int32_t>(d2));
        rescan(tile_of(p));
    }
}

void EmptyCircleFinder::discard(const EmptyCircle& c) {
    const int t = tile_of(c.pixel);
    const std::uint64_t mask = std::uint64_t{1} << bit_of(c.pixel);
    discarded_[c.pixel] = static_cast<std::int32_t>(c.d2);
    masks_[t].discarded |= mask;
    if (masks_[t].candidates & mask) {
        masks_[t].candidates &= ~mask;
        rescan(t);
    }
}

std::optional<EmptyCircle> EmptyCircleFinder::find_by_scan(const CircleBlocker& blocker) const {
    const int n = grid_.width * grid_.height;
    Key best = 0;
    bool found = false;
    for (int p = 0; p < n; ++p) {
        const std::int64_t d2 = field_.squared_distance(p);
        if (d2 == DistanceField::infinite || field_.occupancy(p) != ObstacleKind::none) continue;
        const Key k = key_of(p, d2);
        if (found && k < best) continue;
        if (is_discarded(p, d2) || !shape_eligible(p) || blocker.blocker_inside(circle_of(p)) >= 0)
            continue;
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

}  // namespace acanthus::detail
