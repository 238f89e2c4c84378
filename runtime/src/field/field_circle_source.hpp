// What both circle sources hold, and answer alike: the buffer they read, an exact distance field
// over it (no feature transform) and the empty-circle finder on that field.
#pragma once

#include <vector>

#include "field/circle_source.hpp"
#include "field/distance_field.hpp"
#include "field/empty_circle_finder.hpp"
#include "field/raster_buffer.hpp"

namespace acanthus::detail {

class FieldCircleSource : public CircleSource {
  public:
    void discard(const EmptyCircle& c) override { finder_.discard(c); }
    double boundary_radius_pixels(int pixel) const override {
        return finder_.radius_pixels(field_.boundary_squared_distance(pixel));
    }

  protected:
    FieldCircleSource(const RasterBuffer& raster, const CircleSourceOptions& options)
        : raster_(raster),
          field_(raster.grid().width, raster.grid().height, /*with_sites=*/false, options.metric),
          finder_(field_, raster.grid(), options.min_radius) {
        finder_.set_centres(options.centres);
    }

    // The best `limit` candidates of the field as it is, by scan.
    std::vector<Circle> scanned_candidates(std::size_t limit) const {
        std::vector<Circle> out;
        for (int p : finder_.best_candidates(limit)) out.push_back(finder_.circle_of(p));
        return out;
    }

    const RasterBuffer& raster_;
    DistanceField field_;
    EmptyCircleFinder finder_;
    bool stale_ = true;  // the buffer has sites the field does not reflect yet
};

}  // namespace acanthus::detail
