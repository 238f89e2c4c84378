// The sites of one DistanceField::add_sites() call and the exact squared distance to the nearest
// of them, from per-row lower envelopes of parabolas (docs/field.md, "The distance field").
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace acanthus::detail {

class SiteBlob {
  public:
    // `sites` are pixel indices j*width+i (distinct); `height` is the grid's.
    void reset(const std::vector<int>& sites, int width, int height);
    std::size_t columns() const { return columns_.size(); }

    struct Piece {
        int column;       // site column of this piece of the envelope
        int site;         // nearest site in that column (pixel index)
        std::int64_t g2;  // squared row distance to it
        int start;        // first pixel column where this piece is the lowest
    };

    // Distances along one row (valid until the next reset()).
    class Row {
      public:
        // Exact squared distance from (i, j) to the nearest site; `site` is set to that site.
        std::int64_t at(int i, int& site) {
            while (k_ < top_ && piece_[k_ + 1].start <= i) ++k_;
            while (k_ > 0 && piece_[k_].start > i) --k_;
            const std::int64_t dx = i - piece_[k_].column;
            site = piece_[k_].site;
            return dx * dx + piece_[k_].g2;
        }

      private:
        friend class SiteBlob;
        const Piece* piece_ = nullptr;
        int top_ = 0;
        int k_ = 0;
    };

    // Row j's lower envelope (built on first use), positioned at pixel column x.
    Row row(int j, int x) {
        const std::size_t slot = static_cast<std::size_t>(j);
        if (row_stamp_[slot] != stamp_) build_row(j);
        Row r;
        r.piece_ = pieces_.data() + slot * stride_;
        r.top_ = count_[slot] - 1;
        // The last piece starting at or before x.
        int lo = 0, hi = r.top_;
        while (lo < hi) {
            const int mid = (lo + hi + 1) / 2;
            if (r.piece_[mid].start <= x)
                lo = mid;
            else
                hi = mid - 1;
        }
        r.k_ = lo;
        return r;
    }

  private:
    void build_row(int j);

    std::vector<int> columns_;               // distinct site columns, increasing
    std::vector<int> run_start_;             // runs of column k: run_start_[k] .. [k+1]
    std::vector<std::pair<int, int>> runs_;  // (first row, last row), increasing
    std::vector<int> sorted_;
    int width_ = 0;
    std::size_t stride_ = 0;                // pieces per row slot (= columns)
    std::vector<Piece> pieces_;             // row j's envelope at j * stride_
    std::vector<int> count_;                // per row: pieces
    std::vector<std::uint32_t> row_stamp_;  // per row: stamp_ when its envelope was built
    std::uint32_t stamp_ = 0;
    std::vector<std::int64_t> num_, den_, f_;  // envelope construction scratch
};

}  // namespace acanthus::detail
