// The reference engine's circle source: the whole field recomputed after every change and the
// grid scanned for C, against which the incremental engine is checked.
#include "field/circle_source.hpp"
#include "field/distance_field.hpp"

namespace acanthus::detail {
namespace {

class ReferenceCircleSource final : public CircleSource {
  public:
    ReferenceCircleSource(const RasterBuffer& raster, const CircleSourceOptions& options)
        : raster_(raster),
          field_(raster.grid().width, raster.grid().height, /*with_sites=*/false,
                 options.metric),
          finder_(field_, raster.grid(), options.min_radius) {}

    void start() override {
        field_.compute(raster_.occupancy());
        stale_ = false;
    }
    void add_sites(const std::vector<int>& fresh, std::size_t) override {
        if (!fresh.empty()) stale_ = true;
    }
    std::optional<EmptyCircle> find(const CircleBlocker& blocker) override {
        bring_up_to_date();
        return finder_.find_by_scan(blocker);
    }
    void discard(const EmptyCircle& c) override { finder_.discard(c); }
    void release(const std::vector<int>&) override {}  // the scan asks the blocker every time
    void release_all() override {}
    double boundary_radius_pixels(int pixel) const override {
        return finder_.radius_pixels(field_.boundary_squared_distance(pixel));
    }
    std::vector<Circle> candidate_circles(std::size_t limit) override {
        bring_up_to_date();
        std::vector<Circle> out;
        for (int p : finder_.best_candidates(limit)) out.push_back(finder_.circle_of(p));
        return out;
    }

  private:
    void bring_up_to_date() {
        if (!stale_) return;
        field_.compute(raster_.occupancy());
        stale_ = false;
    }

    const RasterBuffer& raster_;
    DistanceField field_;
    EmptyCircleFinder finder_;
    bool stale_ = true;
};

}  // namespace

std::unique_ptr<CircleSource> reference_circle_source(const RasterBuffer& raster,
                                                      const CircleSourceOptions& options) {
    return std::make_unique<ReferenceCircleSource>(raster, options);
}

}  // namespace acanthus::detail
