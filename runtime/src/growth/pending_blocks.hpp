// The far field of a lazy DistanceField: 64 x 64 pixel blocks that new sites may still lower,
// each with the sites not yet measured over it and an upper bound of its squared distances
// (docs/engine.md, "Scale").
#pragma once

#include <cstdint>
#include <vector>

#include "growth/site_blob.hpp"

namespace acanthus::detail {

class PendingBlocks {
  public:
    static constexpr int kShift = 6;  // 64 x 64 pixel blocks
    static constexpr int kSize = 1 << kShift;

    // All blocks exact; their bounds from the field `d2` (width x height).
    void reset(int width, int height, const std::int32_t* d2);

    int count() const { return blocks_w_ * blocks_h_; }
    int block_of(int pixel) const {
        return (pixel / width_ >> kShift) * blocks_w_ + (pixel % width_ >> kShift);
    }
    // The pixel rectangle a fill of `sites` keeps exact: the blocks within one block of them.
    struct Rect {
        int x0, y0, x1, y1;  // inclusive
        bool contains(int i, int j) const { return i >= x0 && i <= x1 && j >= y0 && j <= y1; }
    };
    Rect near_rect(const std::vector<int>& sites) const;
    // After an exact fill of `sites` over `near`: the blocks beyond it that the sites may lower
    // (nearer to them than their bound) keep them pending.
    void defer(const std::vector<int>& sites, const Rect& near);

    // A block is trusted when its pixels and their 8 neighbours hold exact distances.
    bool trusted(int block) const { return !untrusted_[block]; }
    // Of a block not trusted: no pixel that settle() could lower, nor any of its neighbours,
    // has an exact squared distance above this.
    std::int64_t reach(int block) const { return reach_[block]; }
    // Blocks not trusted whose reach rose since the last call (each once).
    const std::vector<int>& raised() const { return raised_; }
    void clear_raised() {
        for (int b : raised_) in_raised_[b] = 0;
        raised_.clear();
    }
    // Measures the block's pending sites over it and its neighbours' over its one-pixel ring,
    // lowering `d2`; lowered pixels are appended to `changed`. The block is trusted after.
    void settle(int block, std::int32_t* d2, std::vector<int>* changed);

  private:
    struct Blob {
        std::vector<int> sites;
        int x0, y0, x1, y1;  // bounding box
        int refs;            // blocks holding it pending
    };
    Rect rect_of(int block) const;
    static std::int64_t gap2(const Blob& b, const Rect& r);
    // Lowers d2 over r to the distances to blob k's sites.
    // Returns the largest squared distance over r after.
    // `limit`: no value over r is above it.
    std::int32_t measure(int k, const Rect& r, std::int64_t limit, std::int32_t* d2,
                         std::vector<int>* changed);
    void release(int k);
    void distrust(int block, const Blob& blob);
    std::int32_t max_over(const Rect& r, const std::int32_t* d2) const;
    void update_group(int group);

    int width_ = 0, height_ = 0, blocks_w_ = 0, blocks_h_ = 0;
    std::vector<std::vector<int>> pending_;  // per block: blob ids
    std::vector<std::int32_t> bound_;        // per block: >= every squared distance in it
    std::vector<std::uint8_t> untrusted_;
    std::vector<std::int64_t> reach_;      // per block not trusted
    std::vector<std::uint8_t> in_raised_;  // per block: listed in raised_
    std::vector<int> raised_;
    // Groups of 8 x 8 blocks with the largest bound among them, to skip far groups at once.
    static constexpr int kGroupShift = 3;
    int groups_w_ = 0, groups_h_ = 0;
    std::vector<std::int32_t> group_bound_;
    std::vector<Blob> blobs_;
    std::vector<int> free_blobs_;  // ids of released blobs, reused
    SiteBlob blob_;
};

}  // namespace acanthus::detail
