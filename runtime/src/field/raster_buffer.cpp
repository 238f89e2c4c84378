#include "field/raster_buffer.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <string>

namespace acanthus::detail {

GridFrame RasterBuffer::grid_for(Rect bounds, int resolution) {
    GridFrame g;
    const double longer = std::max(bounds.width(), bounds.height());
    g.pixel = longer / resolution;
    // Pixel counts of the sides (the longer one is exactly `resolution`), then the frame.
    const int w = std::max(1, static_cast<int>(std::ceil(bounds.width() / g.pixel - 1e-9)));
    const int h = std::max(1, static_cast<int>(std::ceil(bounds.height() / g.pixel - 1e-9)));
    g.width = w + 2;
    g.height = h + 2;
    g.x0 = bounds.x0 - g.pixel;
    g.y0 = bounds.y0 - g.pixel;
    return g;
}

RasterBuffer::RasterBuffer(const Region& region, int resolution)
    : grid_([&] {
          if (resolution < kMinResolution || resolution > kMaxResolution)
              throw UsageError("--resolution must be between " + std::to_string(kMinResolution) +
                               " and " + std::to_string(kMaxResolution) + ", not " +
                               std::to_string(resolution));
          return grid_for(region.bounds(), resolution);
      }()),
      cover_(grid_) {
    const std::size_t n = static_cast<std::size_t>(grid_.width) * grid_.height;
    occ_.assign(n, static_cast<std::uint8_t>(ObstacleKind::boundary));
    // Flattened within a fraction of a pixel (the same margin as proxies' curves).
    const auto rings = region.rings(PixelCover::kFlatten * grid_.pixel);
    std::vector<PixelCover::Run> inside;
    cover_.center_runs_inside(rings, region.evenodd(), inside);
    for (const PixelCover::Run& r : inside) {
        std::uint8_t* row = occ_.data() + static_cast<std::size_t>(r.row) * grid_.width;
        std::fill(row + r.first, row + r.last + 1, static_cast<std::uint8_t>(ObstacleKind::none));
    }
    std::vector<int> pixels;
    for (const auto& ring : rings)
        for (std::size_t k = 0; k < ring.size(); ++k)
            cover_.segment(ring[k], ring[(k + 1) % ring.size()], pixels);
    for (int p : pixels) occ_[p] = static_cast<std::uint8_t>(ObstacleKind::boundary);
}

int RasterBuffer::pixel_of(Point p) const {
    const double u = std::floor((p.x - grid_.x0) / grid_.pixel);
    const double v = std::floor((p.y - grid_.y0) / grid_.pixel);
    if (!(u >= 0 && v >= 0 && u < grid_.width && v < grid_.height)) return -1;
    return static_cast<int>(v) * grid_.width + static_cast<int>(u);
}

void RasterBuffer::occupy(const std::vector<int>& pixels, ObstacleKind kind,
                          std::vector<int>& fresh) {
    for (int p : pixels) {
        if (occ_[p] != 0) continue;
        occ_[p] = static_cast<std::uint8_t>(kind);
        fresh.push_back(p);
    }
}

void RasterBuffer::add_proxy(const Proxy& p, ObstacleKind kind, std::vector<int>& fresh) {
    scratch_.clear();
    cover_.proxy(p, scratch_);
    occupy(scratch_, kind, fresh);
}

void RasterBuffer::add_boundary(const std::vector<int>& pixels) {
    for (int p : pixels)
        if (occ_[p] == static_cast<std::uint8_t>(ObstacleKind::none))
            occ_[p] = static_cast<std::uint8_t>(ObstacleKind::boundary);
}

void RasterBuffer::release() {
    std::vector<std::uint8_t>().swap(occ_);
    std::vector<int>().swap(scratch_);
}

void RasterBuffer::add_element(const Element& e, std::vector<int>& fresh) {
    for (std::size_t k = 0; k < e.proxy_count(); ++k)
        add_proxy(e.proxy(k), ObstacleKind::element, fresh);
}

}  // namespace acanthus::detail
