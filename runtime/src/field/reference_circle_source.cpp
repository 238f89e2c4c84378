// The reference engine's circle source: the whole field recomputed after every change and the
// grid scanned for C, against which the incremental engine is checked.
#include "field/field_circle_source.hpp"

namespace acanthus::detail {
namespace {

class ReferenceCircleSource final : public FieldCircleSource {
  public:
    ReferenceCircleSource(const RasterBuffer& raster, const CircleSourceOptions& options)
        : FieldCircleSource(raster, options) {}

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
    void release(const std::vector<int>&) override {}  // the scan asks the blocker every time
    void release_all() override {}
    std::vector<Circle> candidate_circles(std::size_t limit) override {
        bring_up_to_date();
        return scanned_candidates(limit);
    }

  private:
    void bring_up_to_date() {
        if (!stale_) return;
        field_.compute(raster_.occupancy());
        stale_ = false;
    }
};

}  // namespace

std::unique_ptr<CircleSource> reference_circle_source(const RasterBuffer& raster,
                                                      const CircleSourceOptions& options) {
    return std::make_unique<ReferenceCircleSource>(raster, options);
}

}  // namespace acanthus::detail
