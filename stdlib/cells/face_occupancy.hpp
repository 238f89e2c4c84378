// The data behind FaceOccupancy: the face's integer rings and the claims, bucketed on a grid
// so that a query touches only what lies near it.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <polyclipping/clipper.hpp>
#include <vector>

#include "clip.hpp"

namespace acanthus::cells::detail {

class FaceOccupancyData {
  public:
    FaceOccupancyData(const FacadeData& facade, int face);

    void claim(ClipperLib::Path path, Rect box);
    std::vector<std::vector<Point>> free_part(const std::vector<Point>& polygon) const;
    bool rect_is_free(Rect r) const;
    bool inside(Point p) const;  // in the face (even-odd over its rings)
    double claimed_area() const { return claimed_area_; }
    const IntScale& scale() const { return scale_; }

  private:
    template <class F>
    void for_buckets(Rect r, F&& f) const;

    IntScale scale_;
    Rect bounds_;
    int nx_ = 1, ny_ = 1;
    double cell_w_ = 1, cell_h_ = 1;
    std::vector<ClipperLib::Path> rings_;
    std::vector<Rect> ring_boxes_;
    struct RingEdge {
        Point a, b;
    };
    std::vector<RingEdge> ring_edges_;
    std::vector<std::vector<int>> edge_buckets_;
    std::vector<ClipperLib::Path> claims_;
    std::vector<Rect> claim_boxes_;
    std::vector<std::vector<int>> claim_buckets_;
    double claimed_area_ = 0;
};

}  // namespace acanthus::cells::detail
