#include "growth/pending_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace acanthus::detail {

void PendingBlocks::reset(int width, int height, const std::int32_t* d2) {
    width_ = width;
    height_ = height;
    blocks_w_ = ((width - 1) >> kShift) + 1;
    blocks_h_ = ((height - 1) >> kShift) + 1;
    const std::size_t n = static_cast<std::size_t>(blocks_w_) * blocks_h_;
    pending_.assign(n, {});
    bound_.assign(n, 0);
    untrusted_.assign(n, 0);
    reach_.assign(n, 0);
    in_raised_.assign(n, 0);
    raised_.clear();
    blobs_.clear();
    free_blobs_.clear();
    for (int b = 0; b < count(); ++b) bound_[b] = max_over(rect_of(b), d2);
    groups_w_ = ((blocks_w_ - 1) >> kGroupShift) + 1;
    groups_h_ = ((blocks_h_ - 1) >> kGroupShift) + 1;
    group_bound_.assign(static_cast<std::size_t>(groups_w_) * groups_h_, 0);
    for (int g = 0; g < groups_w_ * groups_h_; ++g) update_group(g);
}

PendingBlocks::Rect PendingBlocks::rect_of(int block) const {
    const int bi = block % blocks_w_, bj = block / blocks_w_;
    return {bi << kShift, bj << kShift, std::min(width_, (bi + 1) << kShift) - 1,
            std::min(height_, (bj + 1) << kShift) - 1};
}

std::int32_t PendingBlocks::max_over(const Rect& r, const std::int32_t* d2) const {
    std::int32_t m = 0;
    for (int j = r.y0; j <= r.y1; ++j) {
        const std::int32_t* row = d2 + static_cast<std::size_t>(j) * width_;
        for (int i = r.x0; i <= r.x1; ++i) m = std::max(m, row[i]);
    }
    return m;
}

void PendingBlocks::update_group(int group) {
    const int gi = group % groups_w_, gj = group / groups_w_;
    std::int32_t m = 0;
    for (int bj = gj << kGroupShift; bj < std::min(blocks_h_, (gj + 1) << kGroupShift); ++bj)
        for (int bi = gi << kGroupShift; bi < std::min(blocks_w_, (gi + 1) << kGroupShift); ++bi)
            m = std::max(m, bound_[static_cast<std::size_t>(bj) * blocks_w_ + bi]);
    group_bound_[group] = m;
}

PendingBlocks::Rect PendingBlocks::near_rect(const std::vector<int>& sites) const {
    int x0 = width_, y0 = height_, x1 = -1, y1 = -1;
    for (int p : sites) {
        const int i = p % width_, j = p / width_;
        x0 = std::min(x0, i);
        x1 = std::max(x1, i);
        y0 = std::min(y0, j);
        y1 = std::max(y1, j);
    }
    // Whole blocks, so that a block is either inside (exact) or beyond (pending).
    const int bx0 = std::max(0, (x0 >> kShift) - 1), by0 = std::max(0, (y0 >> kShift) - 1);
    const int bx1 = std::min(blocks_w_ - 1, (x1 >> kShift) + 1);
    const int by1 = std::min(blocks_h_ - 1, (y1 >> kShift) + 1);
    return {bx0 << kShift, by0 << kShift, std::min(width_, (bx1 + 1) << kShift) - 1,
            std::min(height_, (by1 + 1) << kShift) - 1};
}

// Squared distance from the blob's bounding box to the rectangle's pixel centres: no pixel of
// the rectangle is nearer to a site of the blob.
std::int64_t PendingBlocks::gap2(const Blob& b, const Rect& r) {
    const std::int64_t dx = std::max({0, r.x0 - b.x1, b.x0 - r.x1});
    const std::int64_t dy = std::max({0, r.y0 - b.y1, b.y0 - r.y1});
    return dx * dx + dy * dy;
}

void PendingBlocks::distrust(int block, const Blob& blob) {
    // A pixel the blob lowers gets at most its squared distance to the blob's first site; a
    // neighbour of it at most (that + sqrt 2)^2 (distances are 1-Lipschitz). Over the block
    // and its ring, with a margin for rounding; never above the block's own bound.
    const Rect r = rect_of(block);
    const int s = blob.sites.front(), si = s % width_, sj = s / width_;
    const double dx = std::max(std::abs(r.x0 - 1 - si), std::abs(r.x1 + 1 - si));
    const double dy = std::max(std::abs(r.y0 - 1 - sj), std::abs(r.y1 + 1 - sj));
    const double far = std::sqrt(dx * dx + dy * dy) + 1.5;
    const std::int64_t reach =
        std::min<std::int64_t>(static_cast<std::int64_t>(std::ceil(far * far)) + 2, bound_[block]);
    const bool raise = !untrusted_[block] || reach > reach_[block];
    untrusted_[block] = 1;
    if (!raise) return;
    reach_[block] = std::max(reach_[block], reach);
    if (!in_raised_[block]) {
        in_raised_[block] = 1;
        raised_.push_back(block);
    }
}

void PendingBlocks::defer(const std::vector<int>& sites, const Rect& near) {
    Blob blob{{}, width_, height_, -1, -1, 0};
    for (int p : sites) {
        const int i = p % width_, j = p / width_;
        blob.x0 = std::min(blob.x0, i);
        blob.x1 = std::max(blob.x1, i);
        blob.y0 = std::min(blob.y0, j);
        blob.y1 = std::max(blob.y1, j);
    }
    int id = -1;
    for (int g = 0; g < groups_w_ * groups_h_; ++g) {
        const int gi = g % groups_w_, gj = g / groups_w_;
        const int bx0 = gi << kGroupShift, by0 = gj << kGroupShift;
        const int bx1 = std::min(blocks_w_, bx0 + (1 << kGroupShift)) - 1;
        const int by1 = std::min(blocks_h_, by0 + (1 << kGroupShift)) - 1;
        const Rect gr{bx0 << kShift, by0 << kShift, std::min(width_, (bx1 + 1) << kShift) - 1,
                      std::min(height_, (by1 + 1) << kShift) - 1};
        if (gap2(blob, gr) >= group_bound_[g]) continue;  // lowers nothing there
        for (int bj = by0; bj <= by1; ++bj) {
            for (int bi = bx0; bi <= bx1; ++bi) {
                const int b = bj * blocks_w_ + bi;
                const Rect r = rect_of(b);
                if (near.contains(r.x0, r.y0) && near.contains(r.x1, r.y1)) continue;
                if (gap2(blob, r) >= bound_[b]) continue;
                if (id < 0) {
                    if (!free_blobs_.empty()) {
                        id = free_blobs_.back();
                        free_blobs_.pop_back();
                    } else {
                        id = static_cast<int>(blobs_.size());
                        blobs_.emplace_back();
                    }
                    blob.sites = sites;
                    // In the order SiteBlob::reset() wants them, once.
                    std::sort(blob.sites.begin(), blob.sites.end(), [this](int a, int b) {
                        return a % width_ != b % width_ ? a % width_ < b % width_ : a < b;
                    });
                    blobs_[id] = std::move(blob);
                }
                pending_[b].push_back(id);
                ++blobs_[id].refs;
                // The block's pixels may lower, and with them its neighbours' rings.
                for (int nj = std::max(0, bj - 1); nj <= std::min(blocks_h_ - 1, bj + 1); ++nj)
                    for (int ni = std::max(0, bi - 1); ni <= std::min(blocks_w_ - 1, bi + 1); ++ni)
                        distrust(nj * blocks_w_ + ni, blobs_[id]);
            }
        }
    }
}

void PendingBlocks::release(int k) {
    if (--blobs_[k].refs > 0) return;
    blobs_[k].sites.clear();
    blobs_[k].sites.shrink_to_fit();
    free_blobs_.push_back(k);
}

std::int32_t PendingBlocks::measure(int k, const Rect& r, std::int64_t limit, std::int32_t* d2,
                                    std::vector<int>* changed) {
    const Blob& b = blobs_[k];
    blob_.reset(b.sites, width_, height_);
    std::int32_t top = 0;
    for (int j = r.y0; j <= r.y1; ++j) {
        std::int32_t* line = d2 + static_cast<std::size_t>(j) * width_;
        const std::int64_t dy = std::max({0, b.y0 - j, j - b.y1});
        // Only pixels nearer to the bounding box than `limit` (>= every value over r) can
        // change: a span of the row around the box.
        int x0 = r.x0, x1 = r.x1;
        if (dy * dy >= limit) {
            x1 = x0 - 1;
        } else {
            const int reach = static_cast<int>(std::sqrt(static_cast<double>(limit - dy * dy))) + 1;
            x0 = std::max(x0, b.x0 - reach);
            x1 = std::min(x1, b.x1 + reach);
        }
        for (int i = r.x0; i < x0; ++i) top = std::max(top, line[i]);
        for (int i = x1 + 1; i <= r.x1; ++i) top = std::max(top, line[i]);
        SiteBlob::Row row;
        bool built = false;
        for (int i = x0; i <= x1; ++i) {
            // The distance to the blob's bounding box is a lower bound of the distance to its
            // sites: most pixels are settled by it, without the envelope.
            const std::int64_t dx = std::max({0, b.x0 - i, i - b.x1});
            if (dx * dx + dy * dy >= line[i]) {
                top = std::max(top, line[i]);
                continue;
            }
            if (!built) {
                row = blob_.row(j, i);
                built = true;
            }
            int nearest;
            const std::int64_t m = row.at(i, nearest);
            if (m < line[i]) {
                line[i] = static_cast<std::int32_t>(m);
                if (changed) changed->push_back(j * width_ + i);
            }
            top = std::max(top, line[i]);
        }
    }
    return top;
}

void PendingBlocks::settle(int block, std::int32_t* d2, std::vector<int>* changed) {
    const Rect r = rect_of(block);
    std::vector<int>& own = pending_[block];
    // Nearest blobs first: each lowers the block's maximum, and a blob no nearer than that
    // lowers nothing.
    std::sort(own.begin(), own.end(), [&](int a, int b) {
        const std::int64_t ga = gap2(blobs_[a], r), gb = gap2(blobs_[b], r);
        return ga != gb ? ga < gb : a < b;
    });
    for (int k : own) {
        if (gap2(blobs_[k], r) < bound_[block])
            bound_[block] = measure(k, r, bound_[block], d2, changed);
        release(k);
    }
    own.clear();
    bound_[block] = max_over(r, d2);
    update_group((block / blocks_w_ >> kGroupShift) * groups_w_ +
                 (block % blocks_w_ >> kGroupShift));
    // The ring: each neighbour's pending sites over the pixels of the ring in that neighbour.
    const int bi = block % blocks_w_, bj = block / blocks_w_;
    for (int nj = std::max(0, bj - 1); nj <= std::min(blocks_h_ - 1, bj + 1); ++nj) {
        for (int ni = std::max(0, bi - 1); ni <= std::min(blocks_w_ - 1, bi + 1); ++ni) {
            const int n = nj * blocks_w_ + ni;
            if (n == block || pending_[n].empty()) continue;
            const Rect nr = rect_of(n);
            const Rect ring{std::max(nr.x0, r.x0 - 1), std::max(nr.y0, r.y0 - 1),
                            std::min(nr.x1, r.x1 + 1), std::min(nr.y1, r.y1 + 1)};
            std::int32_t limit = max_over(ring, d2);
            for (int k : pending_[n])
                if (gap2(blobs_[k], ring) < limit) limit = measure(k, ring, limit, d2, changed);
        }
    }
    untrusted_[block] = 0;
    reach_[block] = 0;
}

}  // namespace acanthus::detail
