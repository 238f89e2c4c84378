#include "field/pending_blocks.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "field/tile_masks.hpp"
#include "field/witness.hpp"

namespace acanthus::detail {

static_assert(PendingBlocks::kShift - PendingBlocks::kTileShift == 3,
              "8 x 8 tiles a block: one bit each in a 64-bit mask");

void PendingBlocks::reset(int width, int height, const std::int32_t* d2, DistanceMetric metric) {
    manhattan_ = metric == DistanceMetric::manhattan;
    width_ = width;
    height_ = height;
    blocks_w_ = ((width - 1) >> kShift) + 1;
    blocks_h_ = ((height - 1) >> kShift) + 1;
    tiles_w_ = ((width - 1) >> kTileShift) + 1;
    tiles_h_ = ((height - 1) >> kTileShift) + 1;
    const std::size_t n = static_cast<std::size_t>(blocks_w_) * blocks_h_;
    pending_.assign(n, {});
    bound_.assign(n, 0);
    inexact_.assign(n, 0);
    untrusted_.assign(n, 0);
    reach_.assign(n, 0);
    in_raised_.assign(n, 0);
    raised_.clear();
    made_exact_.clear();
    blobs_.clear();
    free_blobs_.clear();
    absorbed_.assign(n << 6, 0);
    witness_.assign(n, -1);
    witness_d2_.assign(n, 0);
    tile_bound_.assign(n << 6, 0);
    kept_ = kept_tiles(width, height);
    // Tiles left out keep bound 0, so that defer() skips them.
    for (int t = 0; t < tiles_w_ * tiles_h_; ++t)
        if (kept_.empty() || kept_[static_cast<std::size_t>(t)])
            tile_bound_[slot_of(t % tiles_w_, t / tiles_w_)] = max_over(tile_rect(t), d2);
    groups_w_ = ((blocks_w_ - 1) >> kGroupShift) + 1;
    groups_h_ = ((blocks_h_ - 1) >> kGroupShift) + 1;
    group_bound_.assign(static_cast<std::size_t>(groups_w_) * groups_h_, 0);
    groups_.reset(group_bound_.size());
    live_ = {0, 0, -1, -1};
    for (int b = 0; b < count(); ++b) update_bound(b);
}

std::vector<std::uint8_t> PendingBlocks::kept_tiles(int width, int height) const {
    const int tw = ((width - 1) >> kTileShift) + 1, th = ((height - 1) >> kTileShift) + 1;
    std::vector<std::uint8_t> kept;
    if (centre_tiles_.size() != static_cast<std::size_t>(tw) * th) return kept;
    kept.assign(centre_tiles_.size(), 0);
    for (int tj = 0; tj < th; ++tj)
        for (int ti = 0; ti < tw; ++ti) {
            if (!centre_tiles_[static_cast<std::size_t>(tj * tw + ti)]) continue;
            for (int j = std::max(0, tj - 1); j <= std::min(th - 1, tj + 1); ++j)
                for (int i = std::max(0, ti - 1); i <= std::min(tw - 1, ti + 1); ++i)
                    kept[static_cast<std::size_t>(j * tw + i)] = 1;
        }
    return kept;
}

PendingBlocks::Rect PendingBlocks::square_at(int x0, int y0, int shift) const {
    return {x0, y0, std::min(width_, x0 + (1 << shift)) - 1,
            std::min(height_, y0 + (1 << shift)) - 1};
}

PendingBlocks::Rect PendingBlocks::block_rect(int block) const {
    return square_at(block % blocks_w_ << kShift, block / blocks_w_ << kShift, kShift);
}

PendingBlocks::Rect PendingBlocks::tile_rect(int tile) const {
    return square_at(tile % tiles_w_ << kTileShift, tile / tiles_w_ << kTileShift, kTileShift);
}

std::uint64_t PendingBlocks::tiles_in(int block) const {
    const int bi = block % blocks_w_, bj = block / blocks_w_;
    const int cols = std::min(8, tiles_w_ - (bi << 3)), rows = std::min(8, tiles_h_ - (bj << 3));
    const std::uint64_t row = (std::uint64_t{1} << cols) - 1;
    std::uint64_t m = 0;
    for (int r = 0; r < rows; ++r) m |= row << (8 * r);
    return m;
}

std::uint64_t PendingBlocks::untrusted_tiles(int block) const {
    const std::uint64_t near = tile_masks::dilate_in_grid(
        block % blocks_w_, block / blocks_w_, blocks_w_, blocks_h_,
        [&](int a, int b) { return inexact_[static_cast<std::size_t>(b) * blocks_w_ + a]; });
    return near & tiles_in(block);
}

std::int32_t PendingBlocks::max_over(const Rect& r, const std::int32_t* d2) const {
    std::int32_t m = 0;
    for (int j = r.y0; j <= r.y1; ++j) {
        const std::int32_t* row = d2 + static_cast<std::size_t>(j) * width_;
        for (int i = r.x0; i <= r.x1; ++i) m = std::max(m, row[i]);
    }
    return m;
}

void PendingBlocks::update_bound(int block) {
    std::int32_t m = 0;
    for (std::uint64_t bits = tiles_in(block); bits; bits &= bits - 1)
        m = std::max(m, tile_bound_[slot_at(block, std::countr_zero(bits))]);
    set_bound(block, m);
}

void PendingBlocks::set_bound(int block, std::int32_t m) {
    const std::int32_t old = bound_[block];
    bound_[block] = m;
    if (m > old) {  // a rise (from reset()'s 0; later bounds fall): the box only grows
        const Rect r =
            square_in_grid(block % blocks_w_ << kShift, block / blocks_w_ << kShift, kShift);
        if (live_.x0 > live_.x1) {
            live_ = r;
        } else {
            live_ = {std::min(live_.x0, r.x0), std::min(live_.y0, r.y0), std::max(live_.x1, r.x1),
                     std::max(live_.y1, r.y1)};
        }
    }
    const int group =
        (block / blocks_w_ >> kGroupShift) * groups_w_ + (block % blocks_w_ >> kGroupShift);
    if (m > group_bound_[group]) {
        group_bound_[group] = m;
        groups_.set(static_cast<std::size_t>(group), static_cast<std::uint64_t>(m));
    } else if (m < old && old == group_bound_[group]) {  // it may have been the group's largest
        update_group(group);
    }
}

void PendingBlocks::update_group(int group) {
    const int gi = group % groups_w_, gj = group / groups_w_;
    std::int32_t m = 0;
    for (int bj = gj << kGroupShift; bj < std::min(blocks_h_, (gj + 1) << kGroupShift); ++bj)
        for (int bi = gi << kGroupShift; bi < std::min(blocks_w_, (gi + 1) << kGroupShift); ++bi)
            m = std::max(m, bound_[static_cast<std::size_t>(bj) * blocks_w_ + bi]);
    group_bound_[group] = m;
    groups_.set(static_cast<std::size_t>(group), static_cast<std::uint64_t>(m));
}

void PendingBlocks::distrust(int block, const Blob& blob) {
    // A pixel the blob lowers gets at most its squared distance to the blob's first site; a
    // neighbour of it at most (that + sqrt 2)^2 (distances are 1-Lipschitz). Over the block
    // and its ring, with a margin for rounding; never above the block's own bound.
    const Rect r = block_rect(block);
    const int si = blob.first % width_, sj = blob.first / width_;
    const double dx = std::max(std::abs(r.x0 - 1 - si), std::abs(r.x1 + 1 - si));
    const double dy = std::max(std::abs(r.y0 - 1 - sj), std::abs(r.y1 + 1 - sj));
    // City-block: the far corner at dx + dy, a diagonal neighbour 2 farther.
    const double far = manhattan_ ? dx + dy + 2.5 : std::sqrt(dx * dx + dy * dy) + 1.5;
    const std::int64_t reach =
        std::min<std::int64_t>(static_cast<std::int64_t>(std::ceil(far * far)) + 2, bound_[block]);
    const bool raise = !untrusted_[block] || reach > reach_[block];
    untrusted_[block] = 1;
    if (!raise) return;
    reach_[block] = std::max(reach_[block], reach);
    if (!in_raised_[block]) {
        in_raised_[block] = 1;
        raised_.push_back(block);
    }
}

void PendingBlocks::defer(const std::vector<int>& sites) {
    if (sites.empty()) return;
    Blob blob{{}, width_, height_, -1, -1, sites.front(), 0};
    for (int p : sites) {
        const int i = p % width_, j = p / width_;
        blob.x0 = std::min(blob.x0, i);
        blob.x1 = std::max(blob.x1, i);
        blob.y0 = std::min(blob.y0, j);
        blob.y1 = std::max(blob.y1, j);
    }
    int id = -1;
    for_blocks_near(blob, [&](int b, const Rect& r) {
        // A site it already holds may outrank the blob over the whole block.
        if (witness_[b] >= 0 &&
            outranks(witness_[b] % width_, witness_[b] / width_,
                     {blob.x0, blob.y0, blob.x1, blob.y1}, r,
                     manhattan_ ? DistanceMetric::manhattan : DistanceMetric::euclidean))
            return false;
        const std::uint64_t lower = cap_tiles(b, blob);
        if (lower == 0) return false;
        if (id < 0) id = store(blob, sites);  // `blob` keeps its box for the tests
        hold(b, id, lower);
        return false;
    });
}

bool PendingBlocks::may_lower(const PixelBox& box) const {
    if (group_bound_.empty()) return true;
    // Every block with a bound above 0 lies in live_ (bounds only fall): a box no nearer to it
    // than the largest bound is no nearer to any block than its bound, as for_blocks_near()
    // would find block by block (most images far from a rosette's domain).
    if (live_.x0 > live_.x1 || gap2(box, live_) >= static_cast<std::int64_t>(groups_.max()))
        return false;
    return for_blocks_near(box, [](int, const Rect&) { return true; });
}

double PendingBlocks::centre_reach() const {
    if (group_bound_.empty() || kept_.empty() || manhattan_)
        return std::numeric_limits<double>::infinity();
    // A kept pixel is at most 2 tiles less a pixel from a centre tile's pixel on each axis.
    const double ring = ((2 << kTileShift) - 1) * std::sqrt(2.0);
    return std::sqrt(static_cast<double>(largest_bound())) + ring + 0.5;
}

PendingBlocks::Near PendingBlocks::near(const PixelBox& box) const {
    if (group_bound_.empty()) return Near::tile;
    if (live_.x0 > live_.x1 || gap2(box, live_) >= static_cast<std::int64_t>(groups_.max()))
        return Near::none;
    bool block = false;
    const bool tile = for_blocks_near(box, [&](int b, const Rect& r) {
        block = true;
        // The gap to a tile is separable in tile columns and rows (boxes may lie far beyond
        // the grid: 64 bits).
        std::int64_t gx[8], gy[8];
        for (int c = 0; c < 8; ++c) {
            // Tiles as tile_rect() clips them (those beyond the grid have bound 0).
            const int x0 = r.x0 + (c << kTileShift);
            const int x1 = std::min(x0 + (1 << kTileShift), width_) - 1;
            const int y0 = r.y0 + (c << kTileShift);
            const int y1 = std::min(y0 + (1 << kTileShift), height_) - 1;
            const std::int64_t dx = std::max({0, x0 - box.x1, box.x0 - x1});
            const std::int64_t dy = std::max({0, y0 - box.y1, box.y0 - y1});
            gx[c] = dx * dx;
            gy[c] = dy * dy;
        }
        // Only the tile rows and columns nearer than the block's bound (the largest of its
        // tiles') can hold one.
        const std::int64_t most = bound_[b];
        const std::int32_t* bound = tile_bound_.data() + slot_at(b, 0);
        for (int ty = 0; ty < 8; ++ty) {
            if (gy[ty] >= most) continue;
            for (int tx = 0; tx < 8; ++tx)
                if (gx[tx] + gy[ty] < bound[ty << 3 | tx]) return true;
        }
        return false;
    });
    return tile ? Near::tile : block ? Near::block : Near::none;
}

std::uint64_t PendingBlocks::cap_tiles(int block, const Blob& blob) {
    // The tiles it may lower: the gap to a tile is separable in tile columns and rows. So is
    // the distance from its first site to a tile's farthest pixel: one above it bounds the
    // tile once the blob is measured (a blob exactly as near as a bound may still be a
    // pixel's nearest, and bounds are strict limits for the blobs settle_tile() and measure()
    // skip).
    const Rect r = block_rect(block);
    const int si = blob.first % width_, sj = blob.first / width_;
    std::int32_t gx[8], gy[8], fx[8], fy[8];  // squares of grid sizes fit in 32 bits
    for (int c = 0; c < 8; ++c) {
        const int x0 = r.x0 + (c << kTileShift), x1 = x0 + (1 << kTileShift) - 1;
        const std::int32_t dx = std::max({0, x0 - blob.x1, blob.x0 - x1});
        const std::int32_t ex =
            std::max(std::abs(x0 - si), std::abs(std::min(x1, width_ - 1) - si));
        const int y0 = r.y0 + (c << kTileShift), y1 = y0 + (1 << kTileShift) - 1;
        const std::int32_t dy = std::max({0, y0 - blob.y1, blob.y0 - y1});
        const std::int32_t ey =
            std::max(std::abs(y0 - sj), std::abs(std::min(y1, height_ - 1) - sj));
        gx[c] = dx * dx;
        gy[c] = dy * dy;
        fx[c] = manhattan_ ? ex : ex * ex;
        fy[c] = manhattan_ ? ey : ey * ey;
    }
    // A row of 8 tiles is two vectors of 4 lanes. The tiles of a block beyond the grid's edge
    // keep bound 0 (reset()): nothing is below it, so they take no bit, no cap, no part in
    // the top.
    std::uint64_t lower = 0;
    unsigned capped = 0;
    const Lanes zero = {0, 0, 0, 0};
    Lanes top = zero;
    const Lanes gxl[2] = {load_lanes(gx), load_lanes(gx + 4)};
    const Lanes fxl[2] = {load_lanes(fx), load_lanes(fx + 4)};
    const int bj = block / blocks_w_;
    const int rows = std::min(8, tiles_h_ - (bj << 3));
    std::int32_t* bound = tile_bound_.data() + slot_at(block, 0);
    for (int row = 0; row < rows; ++row, bound += 8) {
        unsigned bits = 0;
        for (int h = 0; h < 2; ++h) {
            Lanes b = load_lanes(bound + 4 * h);
            bits |= lane_mask(gxl[h] + gy[row] < b) << (4 * h);
            const Lanes sum = fxl[h] + fy[row];
            const Lanes far = (manhattan_ ? sum * sum : sum) + 1;
            const Lanes cap = far < b;
            capped |= lane_mask(cap);
            b = cap ? far : b;
            store_lanes(bound + 4 * h, b);
            top = b > top ? b : top;
        }
        lower |= static_cast<std::uint64_t>(bits) << (8 * row);
    }
    if (capped) set_bound(block, std::max({top[0], top[1], top[2], top[3]}));
    return lower;
}

int PendingBlocks::store(Blob& blob, const std::vector<int>& sites) {
    int id;
    if (!free_blobs_.empty()) {
        id = free_blobs_.back();
        free_blobs_.pop_back();
    } else {
        id = static_cast<int>(blobs_.size());
        blobs_.emplace_back();
    }
    // By column, then row: (column, row) in one integer each.
    sorted_.clear();
    if (std::is_sorted(sites.begin(), sites.end())) {
        // Row by row already (most elements' sites): a counting sort by column keeps each
        // column's rows in order, the order std::sort gives.
        const int columns = blob.x1 - blob.x0 + 1;
        column_count_.assign(static_cast<std::size_t>(columns) + 1, 0);
        for (int p : sites) ++column_count_[static_cast<std::size_t>(p % width_ - blob.x0) + 1];
        for (int c = 0; c < columns; ++c)
            column_count_[static_cast<std::size_t>(c) + 1] +=
                column_count_[static_cast<std::size_t>(c)];
        sorted_.resize(sites.size());
        for (int p : sites) {
            const int c = p % width_;
            sorted_[static_cast<std::size_t>(
                column_count_[static_cast<std::size_t>(c - blob.x0)]++)] =
                static_cast<std::int64_t>(c) << 32 | p / width_;
        }
    } else {
        for (int p : sites)
            sorted_.push_back(static_cast<std::int64_t>(p % width_) << 32 | p / width_);
        std::sort(sorted_.begin(), sorted_.end());
    }
    for (const std::int64_t key : sorted_) {
        const int c = static_cast<int>(key >> 32);
        const int row = static_cast<int>(key & 0xffffffff);
        if (!blob.runs.empty() && blob.runs.back().column == c && blob.runs.back().hi + 1 == row)
            blob.runs.back().hi = static_cast<std::int16_t>(row);
        else
            blob.runs.push_back({static_cast<std::int16_t>(c), static_cast<std::int16_t>(row),
                                 static_cast<std::int16_t>(row)});
    }
    blobs_[id] = std::move(blob);
    return id;
}

void PendingBlocks::hold(int block, int id, std::uint64_t lower) {
    const Blob& blob = blobs_[id];
    Pending& p = pending_[block];
    // Tiles that were exact wait from this entry on; the others keep their place.
    for (std::uint64_t bits = lower & ~inexact_[block]; bits; bits &= bits - 1)
        absorbed_[slot_at(block, std::countr_zero(bits))] = p.end();
    inexact_[block] |= lower;
    p.entries.push_back({id, static_cast<std::int16_t>(blob.x0), static_cast<std::int16_t>(blob.y0),
                         static_cast<std::int16_t>(blob.x1), static_cast<std::int16_t>(blob.y1)});
    ++blobs_[id].refs;
    // The tiles it may lower are no longer trusted, nor the tiles round them.
    distrust(block, blob);
    // The site nearest to the block's centre is its best witness.
    const Rect r = block_rect(block);
    const int si = blob.first % width_, sj = blob.first / width_;
    const std::int64_t cx = 2 * si - (r.x0 + r.x1), cy = 2 * sj - (r.y0 + r.y1);
    const std::int64_t dc = cx * cx + cy * cy;
    if (witness_[block] < 0 || dc < witness_d2_[block]) {
        witness_[block] = blob.first;
        witness_d2_[block] = dc;
    }
    const int bi = block % blocks_w_, bj = block / blocks_w_;
    const bool left = bi > 0 && (lower & tile_masks::kColumn0);
    const bool right = bi < blocks_w_ - 1 && (lower & tile_masks::kColumn7);
    const bool up = bj > 0 && (lower & tile_masks::kRow0);
    const bool down = bj < blocks_h_ - 1 && (lower & tile_masks::kRow7);
    if (left) distrust(block - 1, blob);
    if (right) distrust(block + 1, blob);
    if (up) distrust(block - blocks_w_, blob);
    if (down) distrust(block + blocks_w_, blob);
    if (left && up && (lower & 1)) distrust(block - blocks_w_ - 1, blob);
    if (right && up && (lower & 0x80)) distrust(block - blocks_w_ + 1, blob);
    if (left && down && (lower >> 56 & 1)) distrust(block + blocks_w_ - 1, blob);
    if (right && down && (lower >> 63)) distrust(block + blocks_w_ + 1, blob);
}

void PendingBlocks::release(int k) {
    if (--blobs_[k].refs > 0) return;
    blobs_[k].runs.clear();
    free_blobs_.push_back(k);
}

bool PendingBlocks::tile_trusted(int ti, int tj) const {
    const int b = block_at(ti, tj);
    if (!untrusted_[b]) return true;  // distrust() marks the blocks round a lowered tile too
    const int c = ti & 7, r = tj & 7;
    if (c > 0 && c < 7 && r > 0 && r < 7)  // its 3 x 3 tiles within the block
        return (inexact_[b] & (std::uint64_t{0x070707} << ((r - 1) * 8 + c - 1))) == 0;
    for (int nj = std::max(0, tj - 1); nj <= std::min(tiles_h_ - 1, tj + 1); ++nj)
        for (int ni = std::max(0, ti - 1); ni <= std::min(tiles_w_ - 1, ti + 1); ++ni)
            if (!exact(ni, nj)) return false;
    return true;
}

void PendingBlocks::trust_tile(int tile, std::int32_t* d2, std::vector<TileChange>* changed) {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    for (int nj = std::max(0, tj - 1); nj <= std::min(tiles_h_ - 1, tj + 1); ++nj)
        for (int ni = std::max(0, ti - 1); ni <= std::min(tiles_w_ - 1, ti + 1); ++ni)
            if (!exact(ni, nj)) settle_tile(nj * tiles_w_ + ni, d2, changed);
}

void PendingBlocks::prefetch(int tile, const std::int32_t* d2) const {
    // A tile's rows lie far apart in the field: fetched together, before they are measured.
    const Rect r = tile_rect(tile);
    for (int j = r.y0; j <= r.y1; ++j)
        __builtin_prefetch(d2 + static_cast<std::size_t>(j) * width_ + r.x0, 1);
}

std::int32_t PendingBlocks::measure(int k, const Rect& r, std::int64_t limit, std::int32_t* d2,
                                    std::uint64_t* lowered_bits) {
    // A tile row is 8 pixels, two vectors of 4 lanes; an edge tile's missing pixels read as 0,
    // which nothing lowers.
    const Blob& b = blobs_[k];
    const int n = r.x1 - r.x0 + 1;
    const std::size_t runs = b.runs.size();
    // Per run, the column term of each lane: squared (Euclidean) or absolute (Manhattan).
    if (columns_.size() < 2 * runs) columns_.resize(2 * runs);
    const Lanes zero = {0, 0, 0, 0};
    const Lanes lane[2] = {{0, 1, 2, 3}, {4, 5, 6, 7}};
    for (std::size_t q = 0; q < runs; ++q)
        for (int h = 0; h < 2; ++h) {
            const Lanes dx = lane[h] + (r.x0 - b.runs[q].column);
            const Lanes cx = dx < zero ? -dx : dx;
            columns_[2 * q + h] = manhattan_ ? cx : cx * cx;
        }
    Lanes box[2];  // the column term of the distance to the blob's bounding box
    for (int h = 0; h < 2; ++h) {
        const Lanes x = lane[h] + r.x0;
        const Lanes left = b.x0 - x, right = x - b.x1;
        box[h] = left > zero ? left : right > zero ? right : zero;
    }
    Lanes top = zero;
    for (int j = r.y0; j <= r.y1; ++j) {
        std::int32_t* line = d2 + static_cast<std::size_t>(j) * width_ + r.x0;
        std::int32_t row[8] = {};
        const std::int32_t* from = line;
        if (n < 8) {
            for (int l = 0; l < n; ++l) row[l] = line[l];
            from = row;
        }
        Lanes v[2] = {load_lanes(from), load_lanes(from + 4)};
        const std::int32_t dy = std::max({0, b.y0 - j, j - b.y1});
        // Only rows nearer to the bounding box than `limit` (a bound of r) can change,
        // and only pixels nearer to the box than their value (it bounds the sites' distance).
        bool near = false;
        if (static_cast<std::int64_t>(dy) * dy < limit) {
            for (int h = 0; h < 2; ++h) {
                const Lanes g =
                    manhattan_ ? (box[h] + dy) * (box[h] + dy) : box[h] * box[h] + dy * dy;
                near = near || lane_mask(g < v[h]) != 0;
            }
        }
        if (near) {
            // The nearest of the blob's column runs: a placed element spans a few columns.
            // Squares of grid sizes fit in 32 bits.
            const std::int32_t big = std::numeric_limits<std::int32_t>::max();
            Lanes m[2] = {{big, big, big, big}, {big, big, big, big}};
            for (std::size_t q = 0; q < runs; ++q) {
                const Run& run = b.runs[q];
                const std::int32_t g = std::max({0, run.lo - j, j - run.hi});
                const std::int32_t gq = manhattan_ ? g : g * g;
                for (int h = 0; h < 2; ++h) {
                    const Lanes c = columns_[2 * q + h] + gq;
                    m[h] = c < m[h] ? c : m[h];
                }
            }
            unsigned lowered = 0;
            for (int h = 0; h < 2; ++h) {
                if (manhattan_) m[h] *= m[h];  // (|dx| + |dy|)^2 of the nearest run
                const Lanes lower = m[h] < v[h];
                v[h] = lower ? m[h] : v[h];
                lowered |= lane_mask(lower) << (4 * h);
            }
            if (lowered) {
                if (n == 8) {
                    store_lanes(line, v[0]);
                    store_lanes(line + 4, v[1]);
                } else {
                    for (int l = 0; l < n; ++l) line[l] = v[l >> 2][l & 3];
                }
                *lowered_bits |= static_cast<std::uint64_t>(lowered) << (8 * (j - r.y0));
            }
        }
        for (int h = 0; h < 2; ++h) top = v[h] > top ? v[h] : top;
    }
    return std::max({top[0], top[1], top[2], top[3]});
}

void PendingBlocks::settle_tile(int tile, std::int32_t* d2, std::vector<TileChange>* changed) {
    const int ti = tile % tiles_w_, tj = tile / tiles_w_;
    const int block = block_at(ti, tj);
    const std::uint64_t bit = std::uint64_t{1} << bit_of_tile(ti, tj);
    if (!(inexact_[block] & bit)) return;
    const std::size_t slot = slot_at(block, bit_of_tile(ti, tj));
    Pending& p = pending_[block];
    const Rect r = tile_rect(tile);
    prefetch(tile, d2);
    // Nearest blobs first: each lowers the tile's maximum, and a blob no nearer than that
    // lowers nothing.
    std::int64_t limit = tile_bound_[slot];
    order_.clear();
    for (int a = absorbed_[slot]; a < p.end(); ++a) {
        const std::int64_t g = gap2(p.at(a), r);
        if (g < limit) order_.emplace_back(g, a);
    }
    std::sort(order_.begin(), order_.end());
    std::uint64_t lowered = 0;
    for (const auto& [g, a] : order_) {
        if (g >= limit) break;
        // The bound may lie below values not measured yet (see defer()).
        limit = std::min<std::int64_t>(limit, measure(p.at(a).blob, r, limit, d2, &lowered));
    }
    if (changed && lowered) changed->push_back({tile, lowered});
    tile_bound_[slot] = static_cast<std::int32_t>(limit);
    inexact_[block] &= ~bit;
    made_exact_.push_back(tile);
}

void PendingBlocks::compact(int block) {
    Pending& p = pending_[block];
    if (p.entries.empty()) return;
    p.compacted = p.end();
    int lo = p.end();
    const Rect br = block_rect(block);
    const int t0 = (br.y0 >> kTileShift) * tiles_w_ + (br.x0 >> kTileShift);
    for (std::uint64_t bits = inexact_[block]; bits; bits &= bits - 1) {
        const int bit = std::countr_zero(bits);
        const int col = bit & 7, row = bit >> 3;
        const int t = t0 + row * tiles_w_ + col;
        // Blobs no nearer to the tile than its bound lower nothing in it.
        const Rect r =
            square_at(br.x0 + (col << kTileShift), br.y0 + (row << kTileShift), kTileShift);
        int& a = absorbed_[slot_at(block, bit)];
        const std::int32_t bound = tile_bound_[slot_at(block, bit)];
        while (a < p.end() && gap2(p.at(a), r) >= bound) ++a;
        if (a == p.end()) {
            inexact_[block] &= ~(std::uint64_t{1} << bit);
            made_exact_.push_back(t);
        } else
            lo = std::min(lo, a);
    }
    const int drop = lo - p.base;
    if (drop == 0 || 2 * drop < static_cast<int>(p.entries.size())) return;
    for (int k = 0; k < drop; ++k) release(p.entries[k].blob);
    p.entries.erase(p.entries.begin(), p.entries.begin() + drop);
    p.base = lo;
}

void PendingBlocks::tighten(int block, std::int64_t threshold, std::int32_t* d2,
                            std::vector<TileChange>* changed) {
    bool trusted_any = false;
    for (std::uint64_t bits = untrusted_tiles(block); bits; bits &= bits - 1) {
        const int bit = std::countr_zero(bits);
        const int t = tile_at(block, bit);
        if (tile_bound_[slot_at(block, bit)] >= threshold) {
            trust_tile(t, d2, changed);
            trusted_any = true;
        }
    }
    const std::uint64_t left = untrusted_tiles(block);
    std::int64_t top = 0;
    for (std::uint64_t bits = left; bits; bits &= bits - 1)
        top = std::max<std::int64_t>(top, tile_bound_[slot_at(block, std::countr_zero(bits))]);
    untrusted_[block] = left != 0;
    reach_[block] = left != 0 ? std::min(reach_[block], top) : 0;
    update_bound(block);
    // Only measuring frees entries often enough to be worth the scan.
    if (trusted_any && pending_[block].end() >= pending_[block].compacted + 16) compact(block);
}

}  // namespace acanthus::detail
