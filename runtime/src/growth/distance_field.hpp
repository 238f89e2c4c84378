// Exact Euclidean distance field over the render buffer, with the nearest obstacle site and
// its kind for every pixel. Full computation is Felzenszwalb's separable EDT with a feature
// transform; add_sites() updates incrementally by propagating from the new sites only to the
// pixels whose nearest site changes.
//
// Exactness of add_sites(): the squared distance of a pixel q changes exactly when
// m(q) = min over new sites s of |q - s|^2 is below its old value D(q). m is computed exactly:
// for blobs spanning few columns (a placed element, usually) from the lower envelope, per row,
// of the parabolas of the new sites' columns (SiteBlob), else by an EDT of the new sites alone
// over a window around them (all new sites lie in the window, so the window EDT is exact). The
// wavefront visits every pixel with sqrt(m) < sqrt(D) + 1, as a scanline fill that writes
// each improvement as it evaluates the pixel.
// Along the straight segment from a changed pixel to its nearest new site, sqrt(m) - sqrt(D)
// only decreases, and the 8-connected (Bresenham) path of that segment stays within half a
// pixel of it, which raises sqrt(m) - sqrt(D) by less than 1; so every changed pixel is reached.
// The window is doubled whenever the wavefront steps outside it.
//
// Ties: nearest_site() is one of the nearest sites (which one may differ between compute() and
// add_sites()); nearest_kind() is canonical: boundary whenever a boundary site is among the
// nearest (a separate boundary-only field decides), so both paths agree exactly.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "growth/site_blob.hpp"

namespace acanthus::detail {

enum class ObstacleKind : std::uint8_t { none = 0, boundary = 1, element = 2 };

class DistanceField {
  public:
    // Squared distance of a pixel when there is no site at all.
    static constexpr std::int32_t infinite = std::numeric_limits<std::int32_t>::max();

    DistanceField(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Full recomputation from an occupancy grid (width*height, values of ObstacleKind).
    void compute(const std::vector<std::uint8_t>& occupancy);
    // Marks free pixels (indices j*width+i) as sites of `kind` and updates the field.
    // Pixels whose distance changed are appended to `changed` when it is not null.
    void add_sites(const std::vector<int>& pixels, ObstacleKind kind, std::vector<int>* changed);

    // Squared distance in pixels from pixel index to its nearest site (0 on a site).
    std::int64_t squared_distance(int index) const { return dist2_[index]; }
    const std::int32_t* squared_distances() const { return dist2_.data(); }
    double distance(int i, int j) const;
    // Squared distance from pixel index to its nearest boundary site.
    std::int64_t boundary_squared_distance(int index) const { return boundary2_[index]; }
    // Index of the nearest site, or -1 when there is no site at all.
    int nearest_site(int index) const { return site_[index]; }
    ObstacleKind nearest_kind(int index) const;
    ObstacleKind occupancy(int index) const { return static_cast<ObstacleKind>(occ_[index]); }
    const std::vector<std::uint8_t>& occupancy() const { return occ_; }

    // Buffers reused by the separable transform (exposed for the implementation only).
    struct Scratch {
        std::vector<std::int32_t>
            column_distance;  // phase 1: distance to the nearest site in the column
        std::vector<std::int32_t> column_site_row;  // phase 1: row of that site
        std::vector<int> last;                      // per column, last site row seen
        std::vector<int> hull_column;               // phase 2: lower envelope of parabolas
        std::vector<std::int64_t> hull_f, hull_num, hull_den;
    };

  private:
    // Updates `d2` (and `site` when not null) for the new sites; returns changed pixels in `out`.
    void propagate(const std::vector<int>& sites, std::vector<std::int32_t>& d2,
                   std::vector<std::int32_t>* site, std::vector<int>* out);
    // kCommit: write improvements as they are found (the measure covers the whole grid);
    // otherwise collect them in improved_, to be applied only when the fill did not escape.
    template <bool kCommit, class Measure, class Measurable>
    bool wavefront(const std::vector<int>& sites, std::vector<std::int32_t>& d2, std::int32_t* site,
                   std::vector<int>* out, Measure& measure, Measurable measurable);

    int width_;
    int height_;
    std::vector<std::uint8_t> occ_;
    std::vector<std::int32_t> dist2_;      // to the nearest site of any kind
    std::vector<std::int32_t> boundary2_;  // to the nearest boundary site
    std::vector<std::int32_t> site_;

    // Incremental update state.
    std::vector<std::uint32_t> visit_;  // fill state per pixel, relative to stamp_
    std::uint32_t stamp_ = 0;
    // A fill seed: pixel (x, y) reached from the span [pl, pr] of row y - dir (dir 0: a site).
    struct Seed {
        int x, y, dir, pl, pr;
    };
    std::vector<Seed> stack_;
    SiteBlob blob_;
    std::vector<std::uint8_t> window_sites_;
    std::vector<std::int32_t> window_d2_, window_site_;
    Scratch scratch_, window_scratch_;
    struct Improvement {
        int pixel;
        std::int32_t d2;
        std::int32_t site;
    };
    std::vector<Improvement> improved_;
};

}  // namespace acanthus::detail
