// The incremental engine's circle source, and its choice for a placement of many elements
// (docs/field.md, "Bulk placement").
#include <algorithm>
#include <cmath>
#include <limits>

#include "field/field_circle_source.hpp"

namespace acanthus::detail {
namespace {

// A placement's sites are measured as one blob: a tile that needs them reads every column run
// of it. A full transform and rebuild is taken to cost this many run readings per tile of the
// grid (about 1.5 us a tile at 2048 px here): an estimate that leans towards the incremental
// update, which is never wrong, only slow (docs/field.md, "Bulk placement").
constexpr double kFullCostPerTile = 256;

class IncrementalCircleSource final : public FieldCircleSource {
  public:
    IncrementalCircleSource(const RasterBuffer& raster, const CircleSourceOptions& options)
        : FieldCircleSource(raster, options) {
        const long long pixels = static_cast<long long>(raster.grid().width) * raster.grid().height;
        field_.set_lazy(pixels >= options.lazy_field_pixels);
        // The far field need not keep exact the blocks far from every allowed centre.
        if (field_.lazy()) field_.far_blocks().set_centre_tiles(finder_.tile_centres());
    }

    void start() override {
        field_.compute(raster_.occupancy());
        finder_.rebuild();
        stale_ = false;
    }

    void add_sites(const std::vector<int>& fresh, std::size_t elements) override {
        if (fresh.empty() || stale_) return;  // a stale field is recomputed by the next find()
        if (elements > 1 && cheaper_in_full(fresh)) {
            stale_ = true;
            return;
        }
        changed_.clear();
        field_.add_sites(fresh, ObstacleKind::element, &changed_);
        // A change in a block the far field leaves out is next to no pixel that may centre a
        // circle: nothing there needs deciding.
        if (field_.lazy()) {
            const PendingBlocks& far = field_.far_blocks();
            std::erase_if(changed_, [&](int p) { return !far.keeps(p); });
        }
        finder_.update(changed_);
    }

    std::optional<EmptyCircle> find(const CircleBlocker& blocker) override {
        bring_up_to_date();
        return finder_.find(blocker);
    }

    // The lazy far field's bounds: sites no nearer to a kept block than its largest distance
    // lower nothing (defer() would hold them nowhere). Bounds only fall, so such sites never
    // matter later either, nor to a recomputation of the kept blocks.
    bool may_change(const PixelBox& box) const override {
        return !field_.lazy() || field_.far_blocks().may_lower(box);
    }

    // Each tile's bound, not only its block's: sites no nearer to a kept tile than its bound
    // lower nothing there either (bounds are of the distances once measured, and only fall).
    Reach reach(const PixelBox& box) const override {
        if (!field_.lazy()) return Reach::tile;
        switch (field_.far_blocks().near(box)) {
            case PendingBlocks::Near::tile:
                return Reach::tile;
            case PendingBlocks::Near::block:
                return Reach::block;
            case PendingBlocks::Near::none:
                break;
        }
        return Reach::none;
    }

    double centre_reach_pixels() const override {
        return field_.lazy() ? field_.far_blocks().centre_reach()
                             : std::numeric_limits<double>::infinity();
    }

    void release(const std::vector<int>& ids) override { finder_.release(ids); }
    void release_all() override { finder_.release_all(); }

    std::vector<Circle> candidate_circles(std::size_t limit) override {
        bring_up_to_date();
        finder_.settle_all();  // the scan reads every pixel
        return scanned_candidates(limit);
    }

  private:
    void bring_up_to_date() {
        if (!stale_) return;
        field_.recompute_elements(raster_.occupancy());
        finder_.rebuild();
        stale_ = false;
    }

    // Whether updating the field for these sites would cost more than recomputing it. The
    // update's cost is estimated as the sites' column runs times the tiles within reach of
    // their box (the field's largest distance round it): with the lazy field each such tile
    // measures every run when it is needed, and an eager update visits them too.
    bool cheaper_in_full(const std::vector<int>& fresh) const {
        const int w = raster_.grid().width, h = raster_.grid().height;
        const auto& occ = raster_.occupancy();
        const auto element = static_cast<std::uint8_t>(ObstacleKind::element);
        long long runs = 0;
        int x0 = w, y0 = h, x1 = -1, y1 = -1;
        const double inv_w = 1.0 / w;
        for (int p : fresh) {
            int j = static_cast<int>(p * inv_w);  // the row without a division, corrected
            j -= j * w > p;
            j += (j + 1) * w <= p;
            const int i = p - j * w;
            x0 = std::min(x0, i);
            x1 = std::max(x1, i);
            y0 = std::min(y0, j);
            y1 = std::max(y1, j);
            // A run of a column starts where the pixel above is not one of these sites (they
            // are in the buffer already, not yet at distance 0 in the field).
            const int above = p - w;
            if (j == 0 || occ[above] != element || field_.squared_distance(above) == 0) ++runs;
        }
        const long long tiles_w = (w + 7) / 8, tiles_h = (h + 7) / 8;
        long long reach_tiles = tiles_w * tiles_h;
        if (field_.lazy()) {
            const int reach = static_cast<int>(
                std::ceil(std::sqrt(static_cast<double>(field_.far_blocks().largest_bound()))));
            const long long cols =
                (std::min(w - 1, x1 + reach) >> 3) - (std::max(0, x0 - reach) >> 3) + 1;
            const long long rows =
                (std::min(h - 1, y1 + reach) >> 3) - (std::max(0, y0 - reach) >> 3) + 1;
            reach_tiles = cols * rows;
        }
        return static_cast<double>(runs) * static_cast<double>(reach_tiles) >
               kFullCostPerTile * static_cast<double>(tiles_w * tiles_h);
    }

    std::vector<int> changed_;
};

}  // namespace

std::unique_ptr<CircleSource> incremental_circle_source(const RasterBuffer& raster,
                                                        const CircleSourceOptions& options) {
    return std::make_unique<IncrementalCircleSource>(raster, options);
}

}  // namespace acanthus::detail
