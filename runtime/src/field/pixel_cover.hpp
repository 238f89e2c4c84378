// Conservative scan conversion onto the render buffer's grid: every pixel whose closed square
// meets the shape is reported (curves flattened within kFlatten pixels first).
#pragma once

#include <acanthus/grid_frame.hpp>
#include <acanthus/proxy.hpp>
#include <vector>

namespace acanthus::detail {

class PixelCover {
  public:
    // Largest distance, in pixels, between a flattened curve and its chords.
    static constexpr double kFlatten = 0.02;

    explicit PixelCover(const GridFrame& grid) : grid_(grid) {}

    // Appends the pixels the proxy touches (areas filled, curves as their pixel trail, a point
    // as the pixel containing it). Pixels may repeat. Non-finite proxies cover nothing.
    void proxy(const Proxy& p, std::vector<int>& out) const;
    // Closed segment a-b (user units).
    void segment(Point a, Point b, std::vector<int>& out) const;
    // Filled disc.
    void disc(Point center, double radius, std::vector<int>& out) const;
    // Filled polygon (nonzero rule) including its edges.
    void polygon(const std::vector<Point>& points, std::vector<int>& out) const;
    // Pixels whose centre lies inside closed rings under the given fill rule.
    void centers_inside(const std::vector<std::vector<Point>>& rings, bool evenodd,
                        std::vector<int>& out) const;
    // The same pixels as runs of a row: columns [first, last] of `row`, disjoint.
    struct Run {
        int row, first, last;
    };
    void center_runs_inside(const std::vector<std::vector<Point>>& rings, bool evenodd,
                            std::vector<Run>& out) const;

    // Flattening of curves into polylines (user units) within kFlatten pixels.
    std::vector<Point> flatten_arc(const ArcProxy& a) const;
    std::vector<Point> flatten_bezier(const BezierProxy& b) const;

  private:
    // Pixel coordinates: u = (x - x0) / pixel.
    double u(double x) const { return (x - grid_.x0) / grid_.pixel; }
    double v(double y) const { return (y - grid_.y0) / grid_.pixel; }
    // Columns [ceil(ua) - 1, floor(ub)] of row j, clamped: the closed squares meeting [ua, ub].
    void span(int j, double ua, double ub, std::vector<int>& out) const;
    void segment_px(double u0, double v0, double u1, double v1, std::vector<int>& out) const;

    GridFrame grid_;
};

}  // namespace acanthus::detail
