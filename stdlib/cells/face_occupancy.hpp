// The data behind FaceOccupancy: the face's integer rings and the claims, bucketed on a grid
// so that a query touches only what lies near it. Claims that are axis-aligned rectangles (nearly
// all of them) are kept as their boxes, without a Clipper path.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <cstddef>
#include <memory>
#include <polyclipping/clipper.hpp>
#include <span>
#include <utility>
#include <vector>

#include "clip.hpp"

namespace acanthus::cells::detail {

// An append-only array in fixed blocks: growing never moves or re-touches what it holds (a
// vector's doubling copies, and on a fresh mapping faults every page in again).
template <class T>
class Blocks {
  public:
    void push_back(const T& v) {
        if (size_ == blocks_.size() * kSize) blocks_.push_back(std::make_unique<T[]>(kSize));
        blocks_.back()[size_ % kSize] = v;
        ++size_;
    }
    const T& operator[](std::size_t i) const { return blocks_[i / kSize][i % kSize]; }
    std::size_t size() const { return size_; }

  private:
    static constexpr std::size_t kSize = 4096;
    std::vector<std::unique_ptr<T[]>> blocks_;
    std::size_t size_ = 0;
};

// Fixed lists per bucket, built once: one array of items, sliced by bucket (no vector each).
class BucketLists {
  public:
    void add(int bucket, int item) { pairs_.emplace_back(bucket, item); }
    void finish(int buckets);  // items keep the order they were added in
    std::span<const int> operator[](std::size_t b) const {
        return {items_.data() + start_[b], items_.data() + start_[b + 1]};
    }

  private:
    std::vector<std::pair<int, int>> pairs_;
    std::vector<int> start_, items_;
};

class FaceOccupancyData {
  public:
    FaceOccupancyData(const FacadeData& facade, int face);

    void claim(ClipperLib::Path path, Rect box);
    void claim(Rect rect);
    std::vector<std::vector<Point>> free_part(const std::vector<Point>& polygon) const;
    bool rect_is_free(Rect r) const;
    // For `r` on the integer grid: true when the booleans of free_part() would give back r
    // itself (no ring edge crosses it, its centre is in the face, no claim overlaps it on the
    // grid). Only decides what it can decide exactly; false sends the caller to free_part().
    bool snapped_rect_is_free(Rect r) const;
    bool inside(Point p) const;  // in the face (even-odd over its rings)
    double claimed_area() const { return claimed_area_; }
    const IntScale& scale() const { return scale_; }
    // The face's edges (facade indices) whose bounds may overlap `r`, ascending.
    void edges_near(Rect r, std::vector<int>& out) const;

  private:
    template <class F>
    void for_buckets(Rect r, F&& f) const;
    int bucket_of(Point p) const;
    void link_claim(int bucket, int claim);
    const auto& link(int l) const { return claim_links_[static_cast<std::size_t>(l)]; }
    bool inside_rings(Point p) const;

    IntScale scale_;
    Rect bounds_;
    int nx_ = 1, ny_ = 1;
    double cell_w_ = 1, cell_h_ = 1;
    std::vector<ClipperLib::Path> rings_;
    std::vector<Rect> ring_boxes_;
    BucketLists ring_buckets_;  // rings whose box reaches the bucket
    struct RingEdge {
        Point a, b;
    };
    std::vector<RingEdge> ring_edges_;
    BucketLists edge_buckets_;
    std::vector<RingEdge> int_edges_;  // the integer rings' edges, in user units
    BucketLists int_edge_buckets_;
    // Buckets no ring edge reaches are all inside or all outside: 1, 0, or -1 not yet known.
    // A cache filled by const queries; a FaceOccupancy belongs to one Context, one thread.
    mutable std::vector<signed char> bucket_inside_;
    BucketLists feature_edge_buckets_;
    struct Claim {
        Rect box;
        int path = -1;  // index into claim_paths_, or -1: the box is the claim
    };
    Blocks<Claim> claims_;
    std::vector<ClipperLib::Path> claim_paths_;
    // Claims per bucket, newest first: a list threaded through one append-only array.
    struct Link {
        int claim, next;
    };
    std::vector<int> claim_head_;
    Blocks<Link> claim_links_;
    double claimed_area_ = 0;
};

}  // namespace acanthus::cells::detail
