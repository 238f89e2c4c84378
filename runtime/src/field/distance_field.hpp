// Exact Euclidean distance field over the render buffer with each pixel's nearest obstacle site
// and kind; computed in full or updated incrementally (docs/field.md, "The distance field").
#pragma once

#include <acanthus/distance_metric.hpp>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "field/pending_blocks.hpp"
#include "field/site_blob.hpp"

namespace acanthus::detail {

enum class ObstacleKind : std::uint8_t { none = 0, boundary = 1, element = 2 };

// An allocator that leaves new ints uninitialised (resize() without a pass over the memory):
// the field fills its grids itself, once.
template <class T>
struct UninitAllocator : std::allocator<T> {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = UninitAllocator<U>;
    };
    UninitAllocator() = default;
    template <class U>
    UninitAllocator(const UninitAllocator<U>&) noexcept {}
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};
using Grid32 = std::vector<std::int32_t, UninitAllocator<std::int32_t>>;

class DistanceField {
  public:
    // Squared distance of a pixel when there is no site at all.
    static constexpr std::int32_t infinite = std::numeric_limits<std::int32_t>::max();

    // `with_sites`: keep the feature transform (nearest_site()); without it the field costs
    // 4 bytes per pixel less (the growth engine never asks for it). With the Manhattan metric
    // the field holds the square of the city-block distance (so the same comparisons hold).
    DistanceField(int width, int height, bool with_sites = true,
                  DistanceMetric metric = DistanceMetric::euclidean);
    DistanceMetric metric() const { return metric_; }

    int width() const { return width_; }
    int height() const { return height_; }

    // Full recomputation from an occupancy grid (width*height, values of ObstacleKind).
    void compute(const std::vector<std::uint8_t>& occupancy);
    // The same after element sites were added to the occupancy grid without add_sites(): the
    // distances to boundary sites are kept (the boundary never changes after compute()).
    void recompute_elements(const std::vector<std::uint8_t>& occupancy);
    // Marks free pixels (indices j*width+i) as sites of `kind` and updates the field.
    // Pixels whose distance changed are appended to `changed` when it is not null.
    void add_sites(const std::vector<int>& pixels, ObstacleKind kind, std::vector<int>* changed);
    // Sites wider than 32 columns are measured from their row envelopes when these fit in this
    // many pieces, else by a window EDT (the tests set 0 to test the window's path too).
    void set_direct_pieces(std::size_t pieces) { direct_pieces_ = pieces; }

    // Lazy far field (docs/field.md, "The lazy far field"): element sites added later are not
    // measured when added; every block they may lower keeps them pending, and its values are
    // upper bounds (distances only decrease) until a tile of it is trusted. Set before
    // compute(); either metric, no feature transform. Off by default: every value is exact
    // after add_sites().
    void set_lazy(bool lazy) { lazy_ = lazy && site_.empty(); }
    bool lazy() const { return lazy_; }
    PendingBlocks& far_blocks() { return far_; }
    const PendingBlocks& far_blocks() const { return far_; }
    // Makes the 8 x 8 tile and its 8 neighbours exact; appends lowered pixels to `changed`.
    void trust_tile(int tile, std::vector<TileChange>* changed) {
        far_.trust_tile(tile, dist2_.data(), changed);
    }
    // PendingBlocks::tighten() on this field.
    void tighten(int block, std::int64_t threshold, std::vector<TileChange>* changed) {
        far_.tighten(block, threshold, dist2_.data(), changed);
    }

    // Squared distance in pixels from pixel index to its nearest site (0 on a site).
    std::int64_t squared_distance(int index) const { return dist2_[index]; }
    const std::int32_t* squared_distances() const { return dist2_.data(); }
    double distance(int i, int j) const;
    // Row j's columns [first, second) that may hold a finite distance: outside them a lazy
    // field with tiles left out holds infinity (whole tiles; every column without).
    std::pair<int, int> kept_columns(int j) const {
        if (spans_.empty()) return {0, width_};
        return {spans_[2 * static_cast<std::size_t>(j)],
                spans_[2 * static_cast<std::size_t>(j) + 1]};
    }
    // Squared distance from pixel index to its nearest boundary site.
    std::int64_t boundary_squared_distance(int index) const { return boundary2_[index]; }
    const std::int32_t* boundary_squared_distances() const { return boundary2_.data(); }
    // Index of the nearest site, or -1 when there is no site at all (or no feature transform).
    int nearest_site(int index) const { return site_.empty() ? -1 : site_[index]; }
    ObstacleKind nearest_kind(int index) const;
    // The kind of site at the pixel (a site is at distance 0), or none.
    ObstacleKind occupancy(int index) const {
        if (dist2_[index] != 0) return ObstacleKind::none;
        return boundary2_[index] == 0 ? ObstacleKind::boundary : ObstacleKind::element;
    }

    // Buffers reused by the separable transform (exposed for the implementation only).
    // Phase 1 writes its column distances and site rows into the output arrays; phase 2 copies
    // one row of them at a time, so the transform needs no grid-sized scratch.
    struct Scratch {
        std::vector<std::int32_t> column_distance;  // phase 2: row j of phase 1's distances
        std::vector<std::int32_t> column_site_row;  // phase 2: row j of phase 1's site rows
        std::vector<int> last;                      // per column, last site row seen
        std::vector<int> hull_column;               // phase 2: lower envelope of parabolas
        std::vector<std::int64_t> hull_f, hull_num, hull_den;
        // By columns: phase 1's distances, column-major, and how many it holds.
        std::unique_ptr<std::int32_t[]> across;
        std::size_t across_size = 0;
    };

  private:
    // Lowers the distances to those to the site at column si, row sj. `chunk_max` holds the
    // largest distance of each run of kChunk pixels of a row (row by row): a run no pixel of
    // which the site comes nearer to than that is left alone, and the others' maxima updated.
    static constexpr int kChunk = 64;
    void nearer_site(int si, int sj, std::vector<std::int32_t>& chunk_max);
    // Columns [first, second) of run `chunk` of row j that are kept exact.
    std::pair<int, int> kept_run(int j, int chunk) const;
    const int* kept_spans() const { return spans_.empty() ? nullptr : spans_.data(); }
    // Updates `d2` (and `site` when not null) for the new sites; returns changed pixels in `out`.
    void propagate(const std::vector<int>& sites, Grid32& d2, std::vector<std::int32_t>* site,
                   std::vector<int>* out);
    // kCommit: write improvements as they are found (the measure covers the whole grid);
    // otherwise collect them in improved_, to be applied only when the fill did not escape.
    template <bool kCommit, class Measure, class Measurable>
    bool wavefront(const std::vector<int>& sites, Grid32& d2, std::int32_t* site,
                   std::vector<int>* out, Measure& measure, Measurable measurable);

    int width_;
    int height_;
    DistanceMetric metric_;
    bool lazy_ = false;
    PendingBlocks far_;
    // Lazy, with tiles left out: per row, the columns [2j], [2j + 1] kept exact. Empty: all.
    std::vector<int> spans_;
    Grid32 dist2_;                    // to the nearest site of any kind
    Grid32 boundary2_;                // to the nearest boundary site
    std::vector<std::int32_t> site_;  // empty without a feature transform

    // Incremental update state: 16-bit stamps (cleared every ~21,000 fills) keep it at 2 bytes
    // per pixel.
    std::vector<std::uint16_t> visit_;  // fill state per pixel, relative to stamp_
    std::uint16_t stamp_ = 0;
    // A fill seed: pixel (x, y) reached from the span [pl, pr] of row y - dir (dir 0: a site).
    struct Seed {
        int x, y, dir, pl, pr;
    };
    std::vector<Seed> stack_;
    std::vector<int> fresh_;  // add_sites() scratch: the pixels not sites yet
    SiteBlob blob_;
    std::size_t direct_pieces_ = std::size_t{1} << 20;
    std::vector<std::uint8_t> window_sites_;
    std::vector<std::int32_t> window_d2_, window_site_;
    Scratch scratch_, other_scratch_, window_scratch_;
    struct Improvement {
        int pixel;
        std::int32_t d2;
        std::int32_t site;
    };
    std::vector<Improvement> improved_;
    std::vector<std::pair<int, std::int32_t>> queue_;  // brushfire: (pixel, city-block distance)
};

}  // namespace acanthus::detail
