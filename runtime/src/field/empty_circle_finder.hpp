// FindEmptyCircle of Wong et al. section 4.1: the largest eligible circle on the medial axis of
// the distance field, kept up to date incrementally (docs/field.md, "FindEmptyCircle").
#pragma once

#include <acanthus/grid_frame.hpp>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "field/circle_blocker.hpp"
#include "field/distance_field.hpp"
#include "field/max_tree.hpp"
#include "field/tile_change.hpp"

namespace acanthus::detail {

// Per 8 x 8 tile of a width x height grid of bytes (tiles numbered row by row), 1 where a byte
// of the tile is non-zero. Reads the bytes eight at a time: a domain is mostly zeros.
std::vector<std::uint8_t> nonzero_tiles(const std::vector<std::uint8_t>& bytes, int width,
                                        int height);

struct EmptyCircle {
    int pixel = -1;
    std::int64_t d2 = 0;  // squared distance of the centre pixel to its nearest obstacle pixel
    Circle circle;        // conservative circle (see EmptyCircleFinder)
};

class EmptyCircleFinder {
  public:
    static constexpr double kMargin = 0.75;  // pixels, >= sqrt(1/2) + PixelCover::kFlatten
    static constexpr double kBend = 0.5;     // pixels: smallest bend of a medial-axis crest

    // `min_radius` in user units. With a lazy field, find() trusts the tiles it must.
    EmptyCircleFinder(DistanceField& field, const GridFrame& grid, double min_radius);

    // Pixels that may centre a circle (one byte each, non-zero: may); empty, the default: every
    // pixel. A symmetry's fundamental domain (symmetry/). Set before the first search.
    void set_centres(std::vector<std::uint8_t> allowed);
    // Per tile (numbered as tile_of() numbers them), whether a pixel of it may centre a
    // circle; empty: all.
    std::vector<std::uint8_t> tile_centres() const;
    bool may_centre(int pixel) const {
        return centres_.empty() || centres_[static_cast<std::size_t>(pixel)] != 0;
    }

    Circle circle_of(int pixel) const;
    // Radius in pixels of the conservative circle of a field value (squared distance, or
    // squared city-block distance with the Manhattan metric): it holds no obstacle.
    double radius_pixels(std::int64_t d2) const;
    bool on_medial_axis(int pixel) const;
    // On the medial axis, nearest obstacle an element, radius at least the minimum.
    bool shape_eligible(int pixel) const;

    // Incremental search. rebuild() scans the whole grid once; update() takes the pixels whose
    // distance changed; release() returns candidates blocked by removed blocker points.
    void rebuild();
    void update(const std::vector<int>& changed);
    void update(const std::vector<TileChange>& changed);  // the same, a tile at a time
    void release(const std::vector<int>& removed_ids);
    void release_all();
    // Trusts every tile of a lazy field (for scans such as best_candidates()).
    void settle_all();
    std::optional<EmptyCircle> find(const CircleBlocker& blocker);
    // Drops a candidate found by find() or find_by_scan() (the engine found the boundary nearer
    // than every element when measured exactly). It stays dropped, in both searches, until its
    // distance changes.
    void discard(const EmptyCircle& c);

    // Reference search: a full scan.
    std::optional<EmptyCircle> find_by_scan(const CircleBlocker& blocker) const;

    // The `limit` best shape-eligible candidates in choice order (for debug frames), by scan.
    std::vector<int> best_candidates(std::size_t limit) const;

  private:
    using Key = std::uint64_t;  // d2 in the high word, ~pixel in the low word: max is best
    static Key key_of(int pixel, std::int64_t d2) {
        return (static_cast<Key>(d2) << 32) | (0xffffffffu - static_cast<std::uint32_t>(pixel));
    }
    static int pixel_of(Key k) {
        return static_cast<int>(0xffffffffu - static_cast<std::uint32_t>(k));
    }
    static std::int64_t d2_of(Key k) { return static_cast<std::int64_t>(k >> 32); }
    static constexpr int kTileShift = 3;  // 8 x 8 pixel tiles

    bool radius_ok(std::int64_t d2) const;
    // Whether an element may stop the pixel's circle. Euclidean: the nearest obstacle is an
    // element. Manhattan: city-block ties are everywhere (whole plateaus), so as in the paper
    // the circle's inflation decides (the engine's exact refinement discards it when the
    // boundary is nearer).
    bool element_may_stop(int pixel) const {
        return manhattan_ || field_.nearest_kind(pixel) == ObstacleKind::element;
    }
    // d2 of a pixel between neighbours of d2 a and b on a line: a crest that bends enough.
    static bool crest(std::int64_t d, std::int64_t a, std::int64_t b) {
        return a <= d && b <= d && bends(d, a, b);
    }
    static bool bends(std::int64_t d, std::int64_t a, std::int64_t b);  // a, b <= d
    // on_medial_axis() of pixel (i, j) of squared distance d > 0.
    bool crest_at(int pixel, int i, int j, std::int64_t d) const;
    // The same for a pixel with all 8 neighbours inside the grid.
    bool crest_inside(int pixel, std::int64_t d) const {
        const std::int32_t* d2 = field_.squared_distances() + pixel;
        if (manhattan_)  // the paper's MAT: at least as far as each of the 4 neighbours
            return d2[1] <= d && d2[-1] <= d && d2[offsets_[1]] <= d && d2[-offsets_[1]] <= d;
        for (const int off : offsets_)
            if (crest(d, d2[off], d2[-off])) return true;
        return false;
    }
    // Re-decides the state of pixel (i, j); keeps the tile's candidate bit in step. kInside:
    // the tile does not touch the edge of the grid.
    template <bool kInside>
    void consider(int pixel, int i, int j, int tile, int bit);
    template <bool kInside>
    void refresh_bits(int tile, std::uint64_t bits);
    // The `bits` of an inner tile's pixels that could be candidates or are not in state none.
    std::uint64_t maybe_crests(int tile, std::uint64_t bits) const;
    bool is_discarded(int pixel, std::int64_t d2) const;
    int tile_of(int pixel) const;
    // The tile's slot in tiles_: the 64 tiles of a 64 x 64 pixel block side by side, so that
    // the tiles a placement changes share cache lines and subtrees.
    std::size_t slot_of(int tile) const { return slot_at(tile % tiles_w_, tile / tiles_w_); }
    std::size_t slot_at(int ti, int tj) const {
        return (static_cast<std::size_t>(tj >> 3) * blocks_w_ + (ti >> 3)) << 6 |
               static_cast<std::size_t>((tj & 7) << 3 | (ti & 7));
    }
    int bit_of(int pixel) const;
    // Adds pixels of the tile to re-decide at the end of update().
    void mark_near(int tile, std::uint64_t bits);
    void mark_changed(int tile, std::uint64_t bits) {
        if (masks_[tile].changed == 0) changed_tiles_.push_back(tile);
        masks_[tile].changed |= bits;
    }
    // update() after marking the changed pixels: re-decides them and the pixels next to them.
    void refresh_changed();
    void prefetch(int tile) const;               // the field's rows a refresh of the tile reads
    void rescan(int tile);                       // tile maximum from the candidate bits
    void refresh(int tile, std::uint64_t bits);  // re-decides those pixels, then rescans
    // Lazy field: the tiles trusted since the last update() mark what they put off.
    void wake_trusted();
    // Lazy field: bounds of the blocks that stopped being trusted enter blocks_.
    void distrust_new_blocks();
    // Lazy field: trusts the block's tiles that may hold a candidate of at least `threshold`.
    void tighten(int block, std::int64_t threshold);
    void trust_tile(int tile);
    // Row of a pixel index without a division (a multiply and a correction).
    int row_of(int pixel) const {
        int j = static_cast<int>(pixel * inv_width_);
        if (j * grid_.width > pixel)
            --j;
        else if ((j + 1) * grid_.width <= pixel)
            ++j;
        return j;
    }

    DistanceField& field_;
    GridFrame grid_;
    double min_radius_;
    double inv_width_;
    bool manhattan_;
    std::int64_t min_d2_ = 1;                 // smallest d2 whose radius is at least min_radius_
    std::vector<std::uint8_t> centres_;       // set_centres()
    std::vector<std::uint8_t> tile_centres_;  // tile_centres(), found by set_centres()
    // Per lazy-field block, whether a pixel of it may centre a circle (all, without centres_):
    // a block that may not is never tightened for a candidate.
    std::vector<std::uint8_t> block_centres_;
    bool block_may_centre(int block) const {
        return block_centres_.empty() || block_centres_[static_cast<std::size_t>(block)] != 0;
    }
    int tiles_w_ = 0, tiles_h_ = 0, blocks_w_ = 0;
    int offsets_[4] = {};  // pixel index steps along the four lines of the crest test

    // Pixel -> d2 at which it was discarded; few pixels ever are, so a map, not a grid.
    std::unordered_map<int, std::int32_t> discarded_;
    std::vector<std::vector<std::pair<int, std::int32_t>>> blocked_;  // by blocker id: (pixel, d2)
    MaxTree tiles_;
    // Lazy field: per block not trusted, a key above every candidate it may hold; 0 otherwise.
    MaxTree blocks_;
    std::vector<TileChange> settled_;  // pixels lowered by tighten() and trust_tile()
    // Per 8 x 8 tile, one bit per pixel (bit 8 * row + column within the tile).
    // A pixel's state is in these masks: candidate, blocked (by a blocker point) or none. A
    // pixel not in state none was decided at its current distance.
    // Side by side: a refresh reads them together.
    struct TileMasks {
        std::uint64_t candidates = 0;  // pixels in state candidate
        std::uint64_t blocked = 0;     // pixels in state blocked
        std::uint64_t discarded = 0;   // pixels with an entry in discarded_
        std::uint64_t changed = 0;     // pixels changed since the last update()
        Key key = 0;                   // the tile's key in tiles_
        std::uint64_t near = 0;        // pixels next to a change, in update()
        // Lazy field: a tile not trusted puts off re-deciding its pixels until it is.
        std::uint64_t pending = 0;  // pixels to re-decide then
        std::uint64_t stale = 0;    // of those, the pixels whose distance changed
    };
    std::vector<TileMasks> masks_;
    // Lazy field, per 64 x 64 pixel block: its tiles with pixels to re-decide once trusted.
    std::vector<std::uint64_t> deferred_;
    // Per tile, the smallest squared distance to a boundary pixel (boundary sites all come
    // before rebuild()): below it, the nearest obstacle is an element.
    std::vector<std::int32_t> boundary_floor_;
    std::vector<int> changed_tiles_;
    std::vector<int> dirty_list_;  // tiles with pixels near a change, in update()
};

}  // namespace acanthus::detail
