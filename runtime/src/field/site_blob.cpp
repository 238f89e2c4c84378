#include "field/site_blob.hpp"

#include <algorithm>
#include <limits>

namespace acanthus::detail {

void SiteBlob::reset(const std::vector<int>& sites, int width, int height) {
    width_ = width;
    sorted_.assign(sites.begin(), sites.end());
    const auto by_column = [width](int a, int b) {
        return a % width != b % width ? a % width < b % width : a < b;
    };
    std::sort(sorted_.begin(), sorted_.end(), by_column);
    columns_.clear();
    run_start_.clear();
    runs_.clear();
    for (int p : sorted_) {
        const int c = p % width, row = p / width;
        if (columns_.empty() || columns_.back() != c) {
            columns_.push_back(c);
            run_start_.push_back(static_cast<int>(runs_.size()));
            runs_.push_back({row, row});
        } else if (runs_.back().second + 1 == row) {
            runs_.back().second = row;
        } else if (runs_.back().second != row) {
            runs_.push_back({row, row});
        }
    }
    run_start_.push_back(static_cast<int>(runs_.size()));

    const std::size_t h = static_cast<std::size_t>(height);
    if (row_stamp_.size() != h) {
        row_stamp_.assign(h, 0);
        count_.assign(h, 0);
        stamp_ = 0;
    }
    if (++stamp_ == 0) {  // wrapped: forget every row
        std::fill(row_stamp_.begin(), row_stamp_.end(), 0);
        stamp_ = 1;
    }
    stride_ = std::max<std::size_t>(1, columns_.size());
    if (pieces_.size() < h * stride_) pieces_.resize(h * stride_);
    if (num_.size() < stride_) {
        num_.resize(stride_);
        den_.resize(stride_);
        f_.resize(stride_);
    }
}

void SiteBlob::build_row(int j) {
    const std::size_t slot = static_cast<std::size_t>(j);
    Piece* piece = pieces_.data() + slot * stride_;
    std::int64_t* num = num_.data();
    std::int64_t* den = den_.data();
    std::int64_t* f = f_.data();
    int k = -1;
    for (std::size_t q = 0; q < columns_.size(); ++q) {
        // Nearest site row of column q to row j.
        int best_row = 0;
        std::int64_t best = std::numeric_limits<std::int64_t>::max();
        for (int r = run_start_[q]; r < run_start_[q + 1]; ++r) {
            const auto [lo, hi] = runs_[static_cast<std::size_t>(r)];
            const int row = j < lo ? lo : (j > hi ? hi : j);
            const std::int64_t dy = j - row;
            if (dy * dy < best) {
                best = dy * dy;
                best_row = row;
            }
        }
        const std::int64_t c = columns_[q];
        const std::int64_t fq = best + c * c;
        // Piece k starts at num[k] / den[k]; drop it while the new parabola is already lower
        // there (piece 0 extends to minus infinity: two such parabolas always cross once).
        std::int64_t sn = 0, sd = 1;
        while (k >= 0) {
            sn = fq - f[k];
            sd = 2 * (c - piece[k].column);
            if (k > 0 && sn * den[k] <= num[k] * sd) {
                --k;
                continue;
            }
            break;
        }
        ++k;
        piece[k].column = static_cast<int>(c);
        piece[k].site = best_row * width_ + static_cast<int>(c);
        piece[k].g2 = best;
        f[k] = fq;
        num[k] = sn;
        den[k] = sd;
    }
    // Integer starts: piece k is lowest from ceil(num / den) on (den > 0); at an exact
    // breakpoint both pieces give the same distance.
    piece[0].start = std::numeric_limits<int>::min();
    for (int p = 1; p <= k; ++p) {
        const std::int64_t n = num[p], d = den[p];
        std::int64_t s = n / d;
        if (n % d != 0 && n > 0) ++s;
        s = std::clamp<std::int64_t>(s, std::numeric_limits<int>::min() + 1,
                                     std::numeric_limits<int>::max());
        piece[p].start = static_cast<int>(s);
    }
    count_[slot] = k + 1;
    row_stamp_[slot] = stamp_;
}

}  // namespace acanthus::detail
