// The space a fill places shapes into: a panel's flattened rings, or the room a growing ornament
// leaves (through the Environment). Answers exact admission tests and rasterizes itself.
#pragma once

#include <acanthus/grid_frame.hpp>
#include <acanthus/region.hpp>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/spatial_index.hpp"
#include "placed_shape.hpp"

namespace acanthus {
class Environment;
}

namespace acanthus::dartfill {

// Pixel grid over `bounds` with `resolution` pixels on the longer side, plus a margin.
GridFrame make_grid(Rect bounds, int resolution);
// Indices (j * width + i) of the pixels whose centres lie inside the shape; at least the pixel
// under one interior point, so that a shape smaller than a pixel still shows.
void shape_pixels(const GridFrame& grid, const PlacedShape& shape, std::vector<int>& out);

class Container {
  public:
    virtual ~Container() = default;
    virtual Rect bounds() const = 0;
    virtual double area() const = 0;
    // True when the shape lies inside the space (touching its edge within `tolerance` is
    // allowed) and clear of its obstacles.
    virtual bool admits(const PlacedShape& shape, double tolerance) const = 0;
    // occupancy[j * width + i] = 1 where the pixel is outside the space or blocked, else 0.
    virtual std::vector<std::uint8_t> rasterize(const GridFrame& grid) const = 0;
};

// A panel given by closed rings (flattened region boundary) and its fill rule.
class RingContainer : public Container {
  public:
    RingContainer(std::vector<std::vector<Point>> rings, bool evenodd);
    static std::unique_ptr<RingContainer> from_region(const Region& region);

    Rect bounds() const override { return bounds_; }
    double area() const override { return area_; }
    bool admits(const PlacedShape& shape, double tolerance) const override;
    std::vector<std::uint8_t> rasterize(const GridFrame& grid) const override;
    bool contains(Point p) const;

  private:
    struct Edge {
        Point a, b;
    };
    std::vector<std::vector<Point>> rings_;
    std::vector<Edge> edges_;  // the rings' edges of non-zero length
    bool evenodd_;
    Rect bounds_;
    double area_ = 0;
    acanthus::detail::SpatialIndex index_;  // Entry::element is the index in edges_
};

// The space left in the panel of the running growth engine. When the Environment exposes its
// region, the panel is a RingContainer (fast screening, raster by pixel centres) and the
// engine is asked only for the exact final test of a candidate and for element distances while
// rasterizing; without it, every test goes through the Environment and the extent is found by
// flood-filling from `start`.
class EnvironmentContainer : public Container {
  public:
    EnvironmentContainer(Environment& env, Point start, double cell);
    ~EnvironmentContainer() override;

    Rect bounds() const override { return bounds_; }
    double area() const override;
    bool admits(const PlacedShape& shape, double tolerance) const override;
    std::vector<std::uint8_t> rasterize(const GridFrame& grid) const override;
    // True when the region's own rings screen candidates (Environment::region() was set).
    bool screens_with_region() const { return panel_ != nullptr; }

  private:
    // Pixels (of a free `occupancy`) within half a pixel of a placed element become blocked.
    long block_elements(const GridFrame& grid, std::vector<std::uint8_t>& occupancy) const;

    Environment& env_;
    std::unique_ptr<RingContainer> panel_;
    Rect bounds_;
    mutable double area_ = -1;  // measured when the first raster is made
};

}  // namespace acanthus::dartfill
