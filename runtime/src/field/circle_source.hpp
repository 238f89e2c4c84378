// Where the growth loop gets its empty circle C (Wong et al. section 4.1, FindEmptyCircle): a
// distance field over the render buffer and the search for the largest eligible circle on its
// medial axis. Two implementations give the same circles: the incremental one keeps the field
// and its candidates up to date as sites arrive, the reference one recomputes the field and
// scans it (docs/field.md).
#pragma once

#include <acanthus/distance_metric.hpp>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "field/circle_blocker.hpp"
#include "field/empty_circle_finder.hpp"
#include "field/raster_buffer.hpp"
#include "field/witness.hpp"

namespace acanthus::detail {

class CircleSource {
  public:
    virtual ~CircleSource() = default;

    // The buffer holds the boundary and the seeds: compute the field in full.
    virtual void start() = 0;
    // Pixels of the buffer that one placement of `elements` elements made element sites (they
    // were free, and the buffer holds them now): one element's or those of thousands.
    virtual void add_sites(const std::vector<int>& fresh, std::size_t elements) = 0;
    // The largest eligible circle with no blocker point inside, or nothing.
    virtual std::optional<EmptyCircle> find(const CircleBlocker& blocker) = 0;
    // Drops a circle find() gave (measured exactly, the boundary is nearer than every element);
    // it stays dropped until its distance changes.
    virtual void discard(const EmptyCircle& c) = 0;
    // Circles blocked by these blocker points (now removed), or by any, may be chosen again.
    virtual void release(const std::vector<int>& ids) = 0;
    virtual void release_all() = 0;
    // Radius in pixels of the conservative circle about the pixel that holds no boundary pixel.
    virtual double boundary_radius_pixels(int pixel) const = 0;
    // Up to `limit` eligible circles, best first, blocked or not (debug frames).
    virtual std::vector<Circle> candidate_circles(std::size_t limit) = 0;
    // False when element sites within the box (pixels, inclusive, possibly beyond the grid)
    // could change no distance the source reads: under symmetry, an image far from the
    // fundamental domain need not enter the buffer. True when the source cannot tell.
    virtual bool may_change(const PixelBox& box) const {
        (void)box;
        return true;
    }
    // Finer than may_change(): `tile` when element sites within the box may change a distance
    // the source reads (or it cannot tell); `block` when they change none, though the coarse
    // test (may_change()) would not tell; `none` when may_change() is false.
    enum class Reach { none, block, tile };
    virtual Reach reach(const PixelBox& box) const {
        return may_change(box) ? Reach::tile : Reach::none;
    }
    // Sites whose pixels' centres all lie farther than this (pixels) from every pixel that may
    // centre a circle have reach() other than `tile`; infinite when the source cannot tell.
    virtual double centre_reach_pixels() const { return std::numeric_limits<double>::infinity(); }
};

struct CircleSourceOptions {
    DistanceMetric metric = DistanceMetric::euclidean;
    double min_radius = 0;  // user units
    // Buffers of at least this many pixels keep the field lazily (field/pending_blocks.hpp).
    long long lazy_field_pixels = 512LL * 512;
    // Pixels that may centre C (EmptyCircleFinder::set_centres); empty: every pixel.
    std::vector<std::uint8_t> centres;
};

// The incremental engine. Sites of one placement update the field where they change it; a
// placement of many elements whose update would cost more than a full exact transform marks the
// field stale instead, and the next find() recomputes it once (bulk placement).
std::unique_ptr<CircleSource> incremental_circle_source(const RasterBuffer& raster,
                                                        const CircleSourceOptions& options);
// The reference engine: the whole field recomputed before every search that follows a change,
// and the grid scanned for C.
std::unique_ptr<CircleSource> reference_circle_source(const RasterBuffer& raster,
                                                      const CircleSourceOptions& options);

}  // namespace acanthus::detail
