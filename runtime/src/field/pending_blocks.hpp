// The far field of a lazy DistanceField: new sites are not measured when they are added. Each
// 64 x 64 pixel block keeps the sites that may lower it pending, and each 8 x 8 tile of it
// measures them only when FindEmptyCircle needs that tile exact (docs/field.md,
// "The lazy far field").
#pragma once

#include <acanthus/distance_metric.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "field/lanes.hpp"
#include "field/max_tree.hpp"
#include "field/tile_change.hpp"
#include "field/witness.hpp"

namespace acanthus::detail {

class PendingBlocks {
  public:
    static constexpr int kShift = 6;      // 64 x 64 pixel blocks hold the pending sites
    static constexpr int kTileShift = 3;  // 8 x 8 pixel tiles measure them (the finder's tiles)

    // All tiles exact; their bounds from the field `d2` (width x height) of squared distances
    // in `metric` (city-block distances squared for Manhattan).
    void reset(int width, int height, const std::int32_t* d2, DistanceMetric metric);

    // Per tile (numbered as tile_of() numbers them), whether a pixel of it may centre a circle;
    // empty: all (symmetry/ allows only a fundamental domain). A tile more than one tile from
    // every such tile is left out from the next reset() on: its bound is 0, so nothing is
    // deferred to it, and its stored distances go stale (too large). No candidate there can be
    // chosen, and a crest test of a pixel that may centre one reads only its own and the
    // neighbouring tiles, which are kept.
    void set_centre_tiles(std::vector<std::uint8_t> tiles) { centre_tiles_ = std::move(tiles); }
    // Per tile of a width x height grid, whether it is kept: within one tile of a centre tile.
    // Empty when every tile is kept (no centre tiles set, or set for another grid).
    std::vector<std::uint8_t> kept_tiles(int width, int height) const;
    // False for a pixel of a tile left out (set_centre_tiles()).
    bool keeps(int pixel) const {
        return kept_.empty() || kept_[static_cast<std::size_t>(tile_of(pixel))] != 0;
    }
    bool keeps_tile(int tile) const {
        return kept_.empty() || kept_[static_cast<std::size_t>(tile)] != 0;
    }
    int count() const { return blocks_w_ * blocks_h_; }
    // >= every squared distance in the field.
    std::int64_t largest_bound() const { return static_cast<std::int64_t>(groups_.max()); }
    // Sites whose pixels' centres are all farther than this (pixels) from every pixel of a
    // centre tile lower no kept distance, now or later (near() is never `tile` for them): a
    // kept tile lies within one tile of a centre tile, the others' bounds are 0, and no bound
    // exceeds largest_bound(). Infinite when it cannot tell (before the first reset(), with
    // every tile kept, or with city-block distances).
    double centre_reach() const;
    int tile_of(int pixel) const {
        return (pixel / width_ >> kTileShift) * tiles_w_ + (pixel % width_ >> kTileShift);
    }

    // Keeps `sites` pending in every block they may lower (nearer to them than its bound).
    void defer(const std::vector<int>& sites);
    // Whether sites within the box (pixels, inclusive) could lower a distance kept here:
    // defer()'s tests of groups and blocks, on the box. False only when no site there could.
    // True before the first reset().
    bool may_lower(const PixelBox& box) const;
    // Finer: whether some tile is nearer to the box than its bound (sites there may lower a
    // distance kept here), else whether some block is (may_lower()), else neither. A block's
    // bound is the largest of its tiles': most boxes near a block's are far from every tile's.
    enum class Near { none, block, tile };
    Near near(const PixelBox& box) const;

    // A tile is trusted when it and its 8 neighbours hold exact distances: every pixel of it
    // and the pixels round it.
    bool tile_trusted(int tile) const { return tile_trusted(tile % tiles_w_, tile / tiles_w_); }
    bool tile_trusted(int ti, int tj) const;  // the tile in column ti, row tj
    // Makes the tile trusted; lowered pixels are appended to `changed`, a tile at a time.
    void trust_tile(int tile, std::int32_t* d2, std::vector<TileChange>* changed);

    // A block is trusted when all its tiles are.
    bool trusted(int block) const { return !untrusted_[block]; }
    // Of a block not trusted: no pixel of it whose state measuring could change (it or a
    // neighbour lowered) has an exact squared distance above this.
    std::int64_t reach(int block) const { return reach_[block]; }
    // Trusts every tile of the block that may hold a squared distance of at least `threshold`;
    // after, the block is trusted or its reach is below `threshold`.
    void tighten(int block, std::int64_t threshold, std::int32_t* d2,
                 std::vector<TileChange>* changed);
    // >= every squared distance the tile will hold once measured.
    std::int32_t tile_bound(int tile) const { return tile_bound(tile % tiles_w_, tile / tiles_w_); }
    std::int32_t tile_bound(int ti, int tj) const { return tile_bound_[slot_of(ti, tj)]; }
    // Tiles that became exact since the last call (a tile trusted since is among them or
    // next to one of them).
    const std::vector<int>& made_exact() const { return made_exact_; }
    void clear_made_exact() { made_exact_.clear(); }
    // Blocks not trusted whose reach rose since the last call (each once).
    const std::vector<int>& raised() const { return raised_; }
    void clear_raised() {
        for (int b : raised_) in_raised_[b] = 0;
        raised_.clear();
    }

  private:
    // Columns of a blob's sites: in column `column`, rows lo..hi are sites (grids are at most
    // 30,000 pixels a side).
    struct Run {
        std::int16_t column, lo, hi;
    };
    // A blob's runs: a placed element spans a few columns, kept inline so that measuring reads
    // them with the blob.
    class Runs {
      public:
        static constexpr int kInline = 8;
        bool empty() const { return size_ == 0; }
        std::size_t size() const { return static_cast<std::size_t>(size_); }
        const Run& operator[](std::size_t k) const { return data()[k]; }
        Run& back() { return (more_.empty() ? inline_ : more_.data())[size_ - 1]; }
        void push_back(const Run& r) {
            if (more_.empty() && size_ < kInline) {
                inline_[size_++] = r;
                return;
            }
            if (more_.empty()) more_.assign(inline_, inline_ + size_);
            more_.push_back(r);
            ++size_;
        }
        void clear() {
            std::vector<Run>().swap(more_);
            size_ = 0;
        }

      private:
        const Run* data() const { return more_.empty() ? inline_ : more_.data(); }
        Run inline_[kInline];
        std::vector<Run> more_;
        int size_ = 0;
    };
    struct Blob {
        Runs runs;           // by column, then row
        int x0, y0, x1, y1;  // bounding box
        int first;           // one of its sites
        int refs;            // blocks holding it pending
    };
    using Rect = PixelBox;
    // A blob deferred to a block, with its bounding box: the gaps to tiles are read in order,
    // without visiting the blobs.
    struct Entry {
        int blob;
        std::int16_t x0, y0, x1, y1;
    };
    // Per block: the blobs deferred to it in order; entry k has the number base + k.
    struct Pending {
        std::vector<Entry> entries;
        int base = 0;
        int compacted = 0;  // end() at the last compact()
        int end() const { return base + static_cast<int>(entries.size()); }
        const Entry& at(int number) const { return entries[number - base]; }
    };

    // Calls visit(block, its rect) for each block nearer to the box than the block's bound,
    // skipping groups of blocks no nearer than theirs, until visit returns true; returns
    // whether it did. defer() and may_lower() walk the same blocks.
    template <class Box, class Visit>
    bool for_blocks_near(const Box& box, Visit visit) const {
        const int reach_all = static_cast<int>(std::sqrt(static_cast<double>(groups_.max()))) + 1;
        constexpr int kGroupPixels = kShift + kGroupShift;
        const int gi0 = std::max(0, (box.x0 - reach_all) >> kGroupPixels);
        const int gi1 = std::min(groups_w_ - 1, (box.x1 + reach_all) >> kGroupPixels);
        const int gj0 = std::max(0, (box.y0 - reach_all) >> kGroupPixels);
        const int gj1 = std::min(groups_h_ - 1, (box.y1 + reach_all) >> kGroupPixels);
        for (int gj = gj0; gj <= gj1; ++gj)
            for (int gi = gi0; gi <= gi1; ++gi) {
                const int g = gj * groups_w_ + gi;
                const int bx0 = gi << kGroupShift, by0 = gj << kGroupShift;
                const int bx1 = std::min(blocks_w_, bx0 + (1 << kGroupShift)) - 1;
                const int by1 = std::min(blocks_h_, by0 + (1 << kGroupShift)) - 1;
                const Rect gr = square_in_grid(bx0 << kShift, by0 << kShift, kShift + kGroupShift);
                if (gap2(box, gr) >= group_bound_[g]) continue;
                // A band round the box as wide as the group's largest bound.
                const int reach =
                    static_cast<int>(std::sqrt(static_cast<double>(group_bound_[g]))) + 1;
                const int ix0 = std::max(bx0, (box.x0 - reach) >> kShift);
                const int ix1 = std::min(bx1, (box.x1 + reach) >> kShift);
                const int jy0 = std::max(by0, (box.y0 - reach) >> kShift);
                const int jy1 = std::min(by1, (box.y1 + reach) >> kShift);
                for (int bj = jy0; bj <= jy1; ++bj)
                    for (int bi = ix0; bi <= ix1; ++bi) {
                        const int b = bj * blocks_w_ + bi;
                        const Rect r = square_in_grid(bi << kShift, bj << kShift, kShift);
                        if (gap2(box, r) < bound_[b] && visit(b, r)) return true;
                    }
            }
        return false;
    }
    // The square of side 2^shift at (x0, y0), clipped to the grid.
    Rect square_at(int x0, int y0, int shift) const;
    // The same, inline (for_blocks_near() takes it for every block it visits).
    Rect square_in_grid(int x0, int y0, int shift) const {
        return {x0, y0, std::min(width_, x0 + (1 << shift)) - 1,
                std::min(height_, y0 + (1 << shift)) - 1};
    }
    Rect block_rect(int block) const;
    Rect tile_rect(int tile) const;
    // The block of the tile in column ti, row tj.
    int block_at(int ti, int tj) const {
        return (tj >> (kShift - kTileShift)) * blocks_w_ + (ti >> (kShift - kTileShift));
    }
    static int bit_of_tile(int ti, int tj) { return ((tj & 7) << 3) | (ti & 7); }
    // Per-tile data lies block by block, the 64 tiles of a block side by side: deferring and
    // tightening read a block's tiles together.
    std::size_t slot_of(int ti, int tj) const {
        return slot_at(block_at(ti, tj), bit_of_tile(ti, tj));
    }
    static std::size_t slot_at(int block, int bit) {
        return static_cast<std::size_t>(block) << 6 | static_cast<std::size_t>(bit);
    }
    bool exact(int ti, int tj) const {
        return ((inexact_[block_at(ti, tj)] >> bit_of_tile(ti, tj)) & 1) == 0;
    }
    // The tiles of the block (bits) that exist: a block at the grid's edge may have fewer.
    std::uint64_t tiles_in(int block) const;
    // The block's tiles that are not trusted.
    std::uint64_t untrusted_tiles(int block) const;
    int tile_at(int block, int bit) const {
        const int bi = block % blocks_w_, bj = block / blocks_w_;
        return ((bj << 3) + (bit >> 3)) * tiles_w_ + (bi << 3) + (bit & 7);
    }
    // Squared distance from a bounding box (a Blob or an Entry) to the rectangle's pixels.
    template <class Box>
    static std::int64_t gap2(const Box& b, const Rect& r) {
        const std::int64_t dx = std::max({0, r.x0 - b.x1, b.x0 - r.x1});
        const std::int64_t dy = std::max({0, r.y0 - b.y1, b.y0 - r.y1});
        return dx * dx + dy * dy;
    }
    // Lowers d2 over the tile r to the distances to blob k's sites; adds the lowered pixels to
    // `lowered` (tile bits). Returns the largest squared distance over r after. `limit`: a
    // bound of r, as tile_bound_ is of a tile.
    std::int32_t measure(int k, const Rect& r, std::int64_t limit, std::int32_t* d2,
                         std::uint64_t* lowered);
    void prefetch(int tile, const std::int32_t* d2) const;  // the tile's rows of the field
    // Measures the tile's pending blobs, nearest first.
    void settle_tile(int tile, std::int32_t* d2, std::vector<TileChange>* changed);
    // Skips the pending blobs that lower nothing in a tile and releases the blobs every tile
    // of the block has measured.
    void compact(int block);
    // defer(), block by block: the tiles of the block the blob may lower (bits), capping the
    // bounds of the tiles it reaches; the blob's runs kept under a new id; the blob pending in
    // the block for those tiles.
    std::uint64_t cap_tiles(int block, const Blob& blob);
    int store(Blob& blob, const std::vector<int>& sites);
    void hold(int block, int id, std::uint64_t lower);
    void release(int k);
    void distrust(int block, const Blob& blob);
    std::int32_t max_over(const Rect& r, const std::int32_t* d2) const;
    void update_bound(int block);
    void set_bound(int block, std::int32_t bound);  // of its tiles' bounds, the largest
    void update_group(int group);

    int width_ = 0, height_ = 0, blocks_w_ = 0, blocks_h_ = 0, tiles_w_ = 0, tiles_h_ = 0;
    bool manhattan_ = false;
    std::vector<std::uint8_t> centre_tiles_;  // set_centre_tiles()
    std::vector<std::uint8_t> kept_;          // per tile, after reset(); empty: all
    std::vector<Pending> pending_;            // per block
    std::vector<std::int32_t> bound_;         // per block: >= every squared distance in it
    std::vector<std::uint64_t> inexact_;      // per block: its tiles with blobs to measure
    std::vector<std::uint8_t> untrusted_;     // per block
    std::vector<std::int64_t> reach_;         // per block not trusted
    std::vector<std::uint8_t> in_raised_;     // per block: listed in raised_
    std::vector<int> raised_;
    std::vector<int> made_exact_;
    // Per tile slot: above every squared distance it will hold once measured, or equal to the
    // largest; pixels not measured yet may hold more.
    std::vector<std::int32_t> tile_bound_;
    std::vector<int> absorbed_;  // per inexact tile slot: the number of its first unmeasured entry
    // Per block: a site near it (-1: none yet) and 4 x its squared distance to the centre. A
    // new blob no nearer than it to every pixel of the block lowers nothing there.
    std::vector<int> witness_;
    std::vector<std::int64_t> witness_d2_;
    // Groups of 8 x 8 blocks with the largest bound among them, to skip far groups at once.
    static constexpr int kGroupShift = 3;
    int groups_w_ = 0, groups_h_ = 0;
    std::vector<std::int32_t> group_bound_;
    MaxTree groups_;  // the same bounds, for the largest of all
    // Holds every block that has had a bound above 0 since reset() (x0 > x1: none): a box no
    // nearer to it than the largest bound is near no block's bound.
    Rect live_{0, 0, -1, -1};
    std::vector<Blob> blobs_;
    std::vector<int> free_blobs_;                      // ids of released blobs, reused
    std::vector<std::pair<std::int64_t, int>> order_;  // settle_tile() scratch: (gap, entry)
    std::vector<std::int64_t> sorted_;                 // defer() scratch: sites by column
    std::vector<int> column_count_;                    // defer() scratch: sites per column
    std::vector<Lanes> columns_;                       // measure() scratch: 2 per run
};

}  // namespace acanthus::detail
