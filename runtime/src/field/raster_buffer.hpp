// The render buffer of Wong et al. section 4.1: occupancy of the region's pixels by the boundary
// and by placed elements (docs/field.md, "The render buffer").
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/grid_frame.hpp>
#include <acanthus/region.hpp>
#include <cstdint>
#include <vector>

#include "field/distance_field.hpp"
#include "field/pixel_cover.hpp"

namespace acanthus::detail {

class RasterBuffer {
  public:
    // Throws UsageError when `resolution` is out of range.
    RasterBuffer(const Region& region, int resolution);

    // `resolution` pixels on the longer side of `bounds`, plus a one-pixel frame all round.
    static GridFrame grid_for(Rect bounds, int resolution);
    static constexpr int kMinResolution = 8;
    static constexpr int kMaxResolution = 16384;

    const GridFrame& grid() const { return grid_; }
    const std::vector<std::uint8_t>& occupancy() const { return occ_; }
    const PixelCover& cover() const { return cover_; }
    int pixel_of(Point p) const;  // index of the pixel containing p, or -1 outside the grid

    // Marks the pixels the proxies of `e` touch as element obstacles and appends those that
    // were free to `fresh`.
    void add_element(const Element& e, std::vector<int>& fresh);
    void add_proxy(const Proxy& p, ObstacleKind kind, std::vector<int>& fresh);
    // Makes free pixels boundary obstacles (a symmetry's core of the region, symmetry/); only
    // before the field is computed.
    void add_boundary(const std::vector<int>& pixels);
    // Frees the pixels once the growth is over; grid() stays.
    void release();

  private:
    void occupy(const std::vector<int>& pixels, ObstacleKind kind, std::vector<int>& fresh);

    GridFrame grid_;
    PixelCover cover_;
    std::vector<std::uint8_t> occ_;
    std::vector<int> scratch_;
};

}  // namespace acanthus::detail
