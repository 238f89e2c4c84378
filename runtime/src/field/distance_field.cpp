#include "field/distance_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <unordered_set>

#include "field/lanes.hpp"
#include "field/manhattan_transform.hpp"

namespace acanthus::detail {
namespace {

constexpr std::int32_t kInfinite = DistanceField::infinite;

// std::fill of 32-bit values, 16 at a time (the build's -O2 leaves std::fill's loop scalar):
// whole grids are filled when a growth starts.
void fill_values(std::int32_t* p, std::size_t n, std::int32_t v) {
    const Lanes x = {v, v, v, v};
    std::size_t k = 0;
    for (; k + 16 <= n; k += 16) {
        store_lanes(p + k, x);
        store_lanes(p + k + 4, x);
        store_lanes(p + k + 8, x);
        store_lanes(p + k + 12, x);
    }
    for (; k < n; ++k) p[k] = v;
}

// Felzenszwalb & Huttenlocher's separable squared EDT over a w x h grid, with a feature
// transform when `site` is not null (site index j*w+i in the same grid). Parabola
// intersections are compared as exact integer fractions, so the result is exact.
//
// Phase 1 keeps each pixel's column distance in d2 and, with a feature transform, that site's
// row in `site`; it runs over columns [c0, c1), row by row for cache friendliness: nearest site
// above, then below.
// Row j's kept columns [spans[2j], spans[2j+1]); empty: the row is not needed. Null: every
// pixel is kept.
using Spans = const int*;

bool row_kept(Spans spans, int j) { return !spans || spans[2 * j] < spans[2 * j + 1]; }

// The sites of a grid of bytes: those equal to `kind`, or with kind < 0 every non-zero byte.
// Eight bytes of a row are tested at once (a row is mostly free, or outside the region
// mostly boundary).
struct ByteSites {
    const std::uint8_t* bytes;
    int w;
    int kind;
    bool operator()(int i, int j) const {
        const std::uint8_t b = bytes[static_cast<std::size_t>(j) * w + i];
        return kind < 0 ? b != 0 : b == kind;
    }
    // 0: none of columns [i, i + 8) of row j is a site, 1: all are, -1: some.
    int eight(int i, int j) const {
        constexpr std::uint64_t kOnes = 0x0101010101010101ull, kHighs = 0x8080808080808080ull;
        std::uint64_t word;
        std::memcpy(&word, bytes + static_cast<std::size_t>(j) * w + i, sizeof word);
        // A byte of x is zero just where the test fails (non-sites).
        const std::uint64_t x = kind < 0 ? word : word ^ (kOnes * static_cast<std::uint8_t>(kind));
        const bool some_zero = ((x - kOnes) & ~x & kHighs) != 0;
        if (kind < 0) return !some_zero ? 1 : x == 0 ? 0 : -1;
        return x == 0 ? 1 : !some_zero ? 0 : -1;
    }
};

// Phase 1 for the rows kept by `spans` alone (no feature transform): every row is read for its
// sites, only the kept rows are written.
void edt_columns_kept(int w, int h, int c0, int c1, const ByteSites& is_site, std::int32_t* g,
                      Spans spans, DistanceField::Scratch& s) {
    int* last = nullptr;
    // last[i] = j for the sites of row j.
    const auto note_sites = [&](int j) {
        int i = c0;
        const Lanes row = {j, j, j, j};
        for (; i + 8 <= c1; i += 8) {
            const int all = is_site.eight(i, j);
            if (all == 0) continue;
            if (all > 0) {
                store_lanes(last + i, row);
                store_lanes(last + i + 4, row);
                continue;
            }
            for (int k = i; k < i + 8; ++k)
                if (is_site(k, j)) last[k] = j;
        }
        for (; i < c1; ++i)
            if (is_site(i, j)) last[i] = j;
    };
    // Rows past the last kept one (down) or before the first (up) matter to no kept row.
    int first_kept = 0, last_kept = h - 1;
    while (first_kept < h && !row_kept(spans, first_kept)) ++first_kept;
    while (last_kept >= first_kept && !row_kept(spans, last_kept)) --last_kept;
    s.last.assign(w, -1);
    last = s.last.data();
    for (int j = 0; j <= last_kept; ++j) {
        note_sites(j);
        if (!row_kept(spans, j)) continue;
        std::int32_t* gj = g + static_cast<std::size_t>(j) * w;
        // Four columns at a time (the build's -O2 leaves these loops scalar).
        const Lanes row = {j, j, j, j}, none = {-1, -1, -1, -1},
                    infinite = {kInfinite, kInfinite, kInfinite, kInfinite};
        int i = c0;
        for (; i + 4 <= c1; i += 4) {
            const Lanes l = load_lanes(last + i);
            store_lanes(gj + i, l > none ? row - l : infinite);
        }
        for (; i < c1; ++i) gj[i] = last[i] >= 0 ? j - last[i] : kInfinite;
    }
    s.last.assign(w, -1);
    last = s.last.data();
    for (int j = h - 1; j >= first_kept; --j) {
        std::int32_t* gj = g + static_cast<std::size_t>(j) * w;
        if (!row_kept(spans, j)) {
            note_sites(j);
            continue;
        }
        const Lanes row = {j, j, j, j}, none = {-1, -1, -1, -1}, zero = {0, 0, 0, 0};
        int i = c0;
        for (; i + 4 <= c1; i += 4) {
            const Lanes v = load_lanes(gj + i), l = load_lanes(last + i);
            const Lanes site = v == zero;
            const Lanes nearer = ~site & (l > none) & (l - row < v);
            store_lanes(last + i, site ? row : l);
            store_lanes(gj + i, nearer ? l - row : v);
        }
        for (; i < c1; ++i) {
            if (gj[i] == 0)
                last[i] = j;
            else if (last[i] >= 0 && last[i] - j < gj[i])
                gj[i] = last[i] - j;
        }
    }
}

void edt_columns(int w, int h, int c0, int c1, const ByteSites& is_site, std::int32_t* g,
                 std::int32_t* row, DistanceField::Scratch& s) {
    s.last.assign(w, -1);
    for (int j = 0; j < h; ++j) {
        std::int32_t* gj = g + static_cast<std::size_t>(j) * w;
        for (int i = c0; i < c1; ++i) {
            if (is_site(i, j)) s.last[i] = j;
            const int l = s.last[i];
            gj[i] = l >= 0 ? j - l : kInfinite;
        }
        if (row)
            std::copy(s.last.begin() + c0, s.last.begin() + c1,
                      row + static_cast<std::size_t>(j) * w + c0);
    }
    s.last.assign(w, -1);
    for (int j = h - 1; j >= 0; --j) {
        std::int32_t* gj = g + static_cast<std::size_t>(j) * w;
        std::int32_t* rj = row ? row + static_cast<std::size_t>(j) * w : nullptr;
        for (int i = c0; i < c1; ++i) {
            if (gj[i] == 0) {
                s.last[i] = j;
            } else if (s.last[i] >= 0 && s.last[i] - j < gj[i]) {
                gj[i] = s.last[i] - j;
                if (rj) rj[i] = s.last[i];
            }
        }
    }
}

// The lower envelope of the parabolas (x - q)^2 + g(q)^2 over q in [q0, q1) with g(q) finite:
// piece k is q = v[k] (f[k] its value at 0), starting at num[k] / den[k]. Returns the last
// piece's index, -1 when there is none.
inline int lower_envelope(const std::int32_t* g, int q0, int q1, int* v, std::int64_t* f,
                          std::int64_t* num, std::int64_t* den) {
    int k = -1;
    for (int q = q0; q < q1; ++q) {
        if (g[q] == kInfinite) continue;
        const std::int64_t fq =
            static_cast<std::int64_t>(g[q]) * g[q] + static_cast<std::int64_t>(q) * q;
        std::int64_t sn = 0, sd = 1;
        while (k >= 0) {
            sn = fq - f[k];
            sd = 2 * static_cast<std::int64_t>(q - v[k]);
            // Drop piece k when the new parabola already wins where piece k starts.
            if (k > 0 && sn * den[k] <= num[k] * sd) {
                --k;
                continue;
            }
            break;
        }
        ++k;
        v[k] = q;
        f[k] = fq;
        num[k] = sn;
        den[k] = sd;
    }
    return k;
}

// Phase 2, rows [j0, j1): per row, the lower envelope of parabolas (x - q)^2 + g(q)^2 over
// columns q that have a site, copied one row at a time before the row is overwritten. The
// envelope piece k starts at num[k] / den[k].
void edt_rows(int w, int j0, int j1, std::int32_t* d2, std::int32_t* site, Spans spans,
              DistanceField::Scratch& s) {
    const std::int32_t* g = d2;
    const std::int32_t* row = site;
    s.hull_column.resize(w);
    s.hull_f.resize(w);
    s.hull_num.resize(w);
    s.hull_den.resize(w);
    s.column_distance.resize(w);
    s.column_site_row.resize(row ? w : 0);
    int* v = s.hull_column.data();
    std::int64_t* f = s.hull_f.data();
    std::int64_t* num = s.hull_num.data();
    std::int64_t* den = s.hull_den.data();
    for (int j = j0; j < j1; ++j) {
        const std::size_t base = static_cast<std::size_t>(j) * w;
        // Outside the kept columns: infinite (nothing reads it; an element drawn there is
        // still a new site).
        const int xa = spans ? spans[2 * j] : 0, xb = spans ? std::max(xa, spans[2 * j + 1]) : w;
        if (xa >= xb) {
            fill_values(d2 + base, static_cast<std::size_t>(w), kInfinite);
            continue;
        }
        std::copy(g + base, g + base + w, s.column_distance.begin());
        if (row) std::copy(row + base, row + base + w, s.column_site_row.begin());
        const std::int32_t* gj = s.column_distance.data();
        const std::int32_t* rj = s.column_site_row.data();
        // With kept columns, a column farther from them than the largest of their own column
        // distances is nearest to none of them: the envelope leaves it out.
        int q0 = 0, q1 = w;
        if (spans) {
            const std::int32_t most = *std::max_element(gj + xa, gj + xb);
            if (most != kInfinite) {
                q0 = std::max(0, xa - most);
                q1 = std::min(w, xb + most);
            }
        }
        int k = lower_envelope(gj, q0, q1, v, f, num, den);
        if (k < 0) {
            fill_values(d2 + base, static_cast<std::size_t>(w), kInfinite);
            if (site) std::fill(site + base, site + base + w, -1);
            continue;
        }
        const int top = k;
        k = 0;
        fill_values(d2 + base, static_cast<std::size_t>(xa), kInfinite);
        fill_values(d2 + base + xb, static_cast<std::size_t>(w - xb), kInfinite);
        for (int x = xa; x < xb; ++x) {
            while (k < top && num[k + 1] <= static_cast<std::int64_t>(x) * den[k + 1]) ++k;
            const int c = v[k];
            const std::int64_t dx = x - c;
            const std::int64_t gc = gj[c];
            d2[base + x] = static_cast<std::int32_t>(dx * dx + gc * gc);
            if (site) site[base + x] = rj[c] * w + c;
        }
    }
}

// The same transform for the kept pixels only (`spans` not null, no feature transform), with
// the passes the other way round: phase 1 along each row, for the columns any row keeps;
// phase 2 per such column, the lower envelope over the rows, written at its kept pixels (the
// rest infinite). A rosette's or a tile's domain keeps few columns but rows across the grid:
// the envelopes then span the kept columns' height, not the grid's width for every kept row.
// The distances are exact either way, so the values are those of the row-wise passes.
void edt_kept_by_columns(int w, int h, int c0, int c1, const ByteSites& is_site, std::int32_t* d2,
                         Spans spans, DistanceField::Scratch& s) {
    const int n = c1 - c0;
    const std::size_t hs = static_cast<std::size_t>(h);
    // Phase 1: each kept column's row distances, column by column (column i at (i - c0) h).
    const std::size_t cells = static_cast<std::size_t>(n) * hs;
    if (s.across_size < cells) {  // every value is written below: no initialising
        s.across.reset(new std::int32_t[cells]);
        s.across_size = cells;
    }
    s.last.resize(static_cast<std::size_t>(n));
    std::int32_t* across = s.across.get();
    int* left = s.last.data();
    for (int j = 0; j < h; ++j) {
        // The nearest site left of the kept columns, eight bytes at a time where none is.
        int at = -1;
        for (int i = c0 - 1; i >= 0;) {
            if (i >= 7 && is_site.eight(i - 7, j) == 0) {
                i -= 8;
                continue;
            }
            if (is_site(i, j)) {
                at = i;
                break;
            }
            --i;
        }
        // Eight columns at a time where they are all sites or none (most of a row).
        int i = c0;
        for (; i + 8 <= c1; i += 8) {
            const int all = is_site.eight(i, j);
            if (all < 0) {
                for (int k = i; k < i + 8; ++k) {
                    if (is_site(k, j)) at = k;
                    left[k - c0] = at;
                }
                continue;
            }
            if (all > 0) at = i + 7;
            const Lanes a = all > 0 ? Lanes{i, i + 1, i + 2, i + 3} : Lanes{at, at, at, at};
            store_lanes(left + (i - c0), a);
            store_lanes(left + (i - c0) + 4, all > 0 ? a + 4 : a);
        }
        for (; i < c1; ++i) {
            if (is_site(i, j)) at = i;
            left[i - c0] = at;
        }
        at = -1;
        for (int k = c1; k < w;) {
            if (k + 8 <= w && is_site.eight(k, j) == 0) {
                k += 8;
                continue;
            }
            if (is_site(k, j)) {
                at = k;
                break;
            }
            ++k;
        }
        std::int32_t* column = across + j;
        auto put = [&](int k, std::int32_t g) {
            column[static_cast<std::size_t>(k - c0) * hs] = g;
        };
        i = c1 - 1;
        // Column k's distance to the nearer of its sites l (left) and r (right), -1: none.
        auto nearer = [](int k, int l, int r) {
            std::int32_t g = l >= 0 ? k - l : kInfinite;
            if (r >= 0 && r - k < g) g = r - k;
            return g;
        };
        for (; i >= c0 && ((i - c0 + 1) & 7) != 0; --i) {
            if (is_site(i, j)) at = i;
            put(i, nearer(i, left[i - c0], at));
        }
        // Now i + 1 - c0 is a multiple of 8: blocks [i - 7, i].
        const Lanes none = {-1, -1, -1, -1},
                    infinite = {kInfinite, kInfinite, kInfinite, kInfinite};
        for (; i >= c0; i -= 8) {
            const int b = i - 7;
            const int all = is_site.eight(b, j);
            if (all > 0) {
                at = b;
                for (int k = b; k <= i; ++k) put(k, 0);
                continue;
            }
            if (all < 0) {
                for (int k = i; k >= b; --k) {
                    if (is_site(k, j)) at = k;
                    put(k, nearer(k, left[k - c0], at));
                }
                continue;
            }
            // No site among them: the nearer of the last on the left and the next on the right.
            const Lanes ra = {at, at, at, at};
            for (int h4 = 0; h4 < 2; ++h4) {
                const int k0 = b + 4 * h4;
                const Lanes x = Lanes{k0, k0 + 1, k0 + 2, k0 + 3};
                const Lanes l = load_lanes(left + (k0 - c0));
                const Lanes gl = l > none ? x - l : infinite;
                const Lanes gr = ra > none ? ra - x : infinite;
                const Lanes g = gr < gl ? gr : gl;
                for (int q = 0; q < 4; ++q) put(k0 + q, g[q]);
            }
        }
    }
    // Each kept column's first and last kept row.
    s.hull_column.assign(static_cast<std::size_t>(n), h);
    s.column_distance.assign(static_cast<std::size_t>(n), -1);
    int* first = s.hull_column.data();
    std::int32_t* end = s.column_distance.data();
    for (int j = 0; j < h; ++j)
        for (int i = spans[2 * j]; i < spans[2 * j + 1]; ++i) {
            first[i - c0] = std::min(first[i - c0], j);
            end[i - c0] = j + 1;
        }
    fill_values(d2, static_cast<std::size_t>(w) * hs, kInfinite);
    s.hull_f.resize(hs);
    s.hull_num.resize(hs);
    s.hull_den.resize(hs);
    s.column_site_row.resize(hs);
    int* v = s.column_site_row.data();
    std::int64_t* f = s.hull_f.data();
    std::int64_t* num = s.hull_num.data();
    std::int64_t* den = s.hull_den.data();
    for (int i = c0; i < c1; ++i) {
        const int ya = first[i - c0], yb = end[i - c0];
        if (ya >= yb) continue;
        const std::int32_t* g = across + static_cast<std::size_t>(i - c0) * hs;
        // A row farther from the kept ones than the largest of their own row distances is
        // nearest to none of them.
        int q0 = 0, q1 = h;
        const std::int32_t most = *std::max_element(g + ya, g + yb);
        if (most != kInfinite) {
            q0 = std::max(0, ya - most);
            q1 = std::min(h, yb + most);
        }
        int k = lower_envelope(g, q0, q1, v, f, num, den);
        if (k < 0) continue;
        const int top = k;
        k = 0;
        for (int y = ya; y < yb; ++y) {
            while (k < top && num[k + 1] <= static_cast<std::int64_t>(y) * den[k + 1]) ++k;
            if (i < spans[2 * y] || i >= spans[2 * y + 1]) continue;
            const std::int64_t dy = y - v[k];
            const std::int64_t gc = g[v[k]];
            d2[static_cast<std::size_t>(y) * w + i] = static_cast<std::int32_t>(dy * dy + gc * gc);
        }
    }
}

// Grids of at least this many pixels are transformed by two threads (columns, then rows, split
// in halves): the start of a large growth waits for whole-grid transforms.
constexpr long long kTwoThreadPixels = 1LL << 20;

// `spans` (null: all) limits the exact values to each row's kept columns; only without a
// feature transform.
void separable_edt(int w, int h, const ByteSites& is_site, std::int32_t* d2, std::int32_t* site,
                   Spans spans, DistanceField::Scratch& s, DistanceField::Scratch& other) {
    const auto columns = [&](int c0, int c1, DistanceField::Scratch& scratch) {
        if (spans)
            edt_columns_kept(w, h, c0, c1, is_site, d2, spans, scratch);
        else
            edt_columns(w, h, c0, c1, is_site, d2, site, scratch);
    };
    long long kept_pixels = static_cast<long long>(w) * h;
    if (spans) {
        kept_pixels = 0;
        for (int j = 0; j < h; ++j) kept_pixels += std::max(0, spans[2 * j + 1] - spans[2 * j]);
    }
    if (kept_pixels < kTwoThreadPixels) {
        if (spans && !site) {
            // The kept columns, and the rows the row-wise passes would visit: the column pass
            // reads every row up to the last kept one and back to the first, each row's
            // envelope the grid's width. By columns: each row's bytes near the kept columns,
            // each kept column's envelope the grid's height.
            int c0 = w, c1 = 0, rows = 0, first_kept = h, last_kept = -1;
            for (int j = 0; j < h; ++j)
                if (spans[2 * j] < spans[2 * j + 1]) {
                    c0 = std::min(c0, spans[2 * j]);
                    c1 = std::max(c1, spans[2 * j + 1]);
                    ++rows;
                    first_kept = std::min(first_kept, j);
                    last_kept = j;
                }
            // Weighed as measured (instructions a pixel): an envelope's parabola 55 row-wise,
            // a column pass's pixel 7; by columns 85 a pixel of the kept columns. The row-wise
            // envelopes often leave out far columns, so by columns only when clearly cheaper
            // (a wallpaper tile's triangle, as many kept rows as columns, is not).
            const long long by_rows =
                static_cast<long long>(w) * (8LL * rows + (last_kept + 1 + h - first_kept));
            const long long by_columns = 12LL * std::max(0, c1 - c0) * h;
            // Its scratch holds a value per pixel of the kept columns: kept within 32 MB.
            const bool fits =
                static_cast<long long>(std::max(0, c1 - c0)) * h <= 8 * kTwoThreadPixels;
            if (fits && 3 * by_columns < 2 * by_rows) {
                edt_kept_by_columns(w, h, c0, std::max(c0, c1), is_site, d2, spans, s);
                return;
            }
        }
        columns(0, w, s);
        edt_rows(w, 0, h, d2, site, spans, s);
        return;
    }
    // The rows split where half the kept pixels lie on each side.
    int jm = h / 2;
    if (spans) {
        long long seen = 0;
        for (jm = 0; jm < h && 2 * seen < kept_pixels; ++jm)
            seen += std::max(0, spans[2 * jm + 1] - spans[2 * jm]);
    }
    const int cm = w / 2;
    std::thread right([&] { columns(cm, w, other); });
    columns(0, cm, s);
    right.join();
    std::thread rows([&] { edt_rows(w, jm, h, d2, site, spans, other); });
    edt_rows(w, 0, jm, d2, site, spans, s);
    rows.join();
}

}  // namespace

DistanceField::DistanceField(int width, int height, bool with_sites, DistanceMetric metric)
    : width_(width), height_(height), metric_(metric) {
    // Squared distances must fit in 32 bits.
    if (width <= 0 || height <= 0 || width > 30000 || height > 30000)  // also packs in 16 bits
        throw std::invalid_argument("DistanceField: grid size out of range");
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    dist2_.resize(n);
    boundary2_.resize(n);
    fill_values(dist2_.data(), n, kInfinite);
    fill_values(boundary2_.data(), n, kInfinite);
    if (with_sites) site_.assign(n, -1);
}

double DistanceField::distance(int i, int j) const {
    const std::int32_t d = dist2_[static_cast<std::size_t>(j) * width_ + i];
    return d == kInfinite ? HUGE_VAL : std::sqrt(static_cast<double>(d));
}

ObstacleKind DistanceField::nearest_kind(int index) const {
    const std::int32_t d = dist2_[index];
    if (d == kInfinite) return ObstacleKind::none;
    return boundary2_[index] == d ? ObstacleKind::boundary : ObstacleKind::element;
}

void DistanceField::compute(const std::vector<std::uint8_t>& occupancy) {
    if (occupancy.size() != dist2_.size())
        throw std::invalid_argument("DistanceField::compute: occupancy size mismatch");
    const int w = width_;
    const std::uint8_t* occ = occupancy.data();
    std::int32_t* site = site_.empty() ? nullptr : site_.data();
    // A lazy field's tiles left out are never read: only each row's kept columns are exact
    // (the others infinite), and no row without a kept tile is transformed.
    spans_.clear();
    if (lazy_ && !site && metric_ == DistanceMetric::euclidean) {
        const std::vector<std::uint8_t> kept = far_.kept_tiles(w, height_);
        if (!kept.empty()) {
            constexpr int kTile = 1 << PendingBlocks::kTileShift;
            const int tiles_w = (w + kTile - 1) / kTile;
            spans_.assign(2 * static_cast<std::size_t>(height_), 0);
            for (int j = 0; j < height_; ++j) {
                const std::uint8_t* row =
                    kept.data() + static_cast<std::size_t>(j / kTile) * tiles_w;
                int a = 0, b = tiles_w;
                while (a < b && !row[a]) ++a;
                while (b > a && !row[b - 1]) --b;
                spans_[2 * static_cast<std::size_t>(j)] = a * kTile;
                spans_[2 * static_cast<std::size_t>(j) + 1] = std::min(w, b * kTile);
            }
        }
    }
    if (metric_ == DistanceMetric::manhattan) {
        const auto boundary = static_cast<std::uint8_t>(ObstacleKind::boundary);
        manhattan_transform(w, height_, occ, false, boundary, dist2_.data(), site);
        manhattan_transform(w, height_, occ, true, boundary, boundary2_.data(), nullptr);
        if (lazy_) far_.reset(w, height_, dist2_.data(), metric_);
        return;
    }
    separable_edt(w, height_, ByteSites{occ, w, static_cast<int>(ObstacleKind::boundary)},
                  boundary2_.data(), nullptr, kept_spans(), scratch_, other_scratch_);
    // At the start of growth the element sites are a seed's few pixels: the nearer of the
    // boundary and of each of them costs less than a second transform.
    constexpr std::size_t kFewSites = 16;
    std::vector<int> elements;
    for (const std::uint8_t* at = occ; !site && elements.size() <= kFewSites;) {
        const void* found = std::memchr(at, static_cast<int>(ObstacleKind::element),
                                        static_cast<std::size_t>(occ + occupancy.size() - at));
        if (!found) break;
        at = static_cast<const std::uint8_t*>(found);
        elements.push_back(static_cast<int>(at - occ));
        ++at;
    }
    if (!site && elements.size() <= kFewSites) {
        std::copy(boundary2_.begin(), boundary2_.end(), dist2_.begin());
        // Under a group the sites are a seed's images, spread over the grid: each lowers only
        // the runs of rows nearer to it than to the boundary and the sites before.
        const int chunks = (w + kChunk - 1) / kChunk;
        std::vector<std::int32_t> chunk_max(static_cast<std::size_t>(chunks) * height_);
        for (int j = 0; j < height_; ++j)
            for (int c = 0; c < chunks; ++c) {
                const std::int32_t* row = dist2_.data() + static_cast<std::size_t>(j) * w;
                const auto [x0, x1] = kept_run(j, c);
                chunk_max[static_cast<std::size_t>(j) * chunks + c] =
                    x0 < x1 ? *std::max_element(row + x0, row + x1) : 0;
            }
        for (const int e : elements) nearer_site(e % w, e / w, chunk_max);
    } else {
        separable_edt(w, height_, ByteSites{occ, w, -1}, dist2_.data(), site, kept_spans(),
                      scratch_, other_scratch_);
    }
    if (lazy_) far_.reset(w, height_, dist2_.data(), metric_);
}

std::pair<int, int> DistanceField::kept_run(int j, int chunk) const {
    int x0 = chunk * kChunk, x1 = std::min(width_, x0 + kChunk);
    if (!spans_.empty()) {
        x0 = std::max(x0, spans_[2 * static_cast<std::size_t>(j)]);
        x1 = std::min(x1, spans_[2 * static_cast<std::size_t>(j) + 1]);
    }
    return {x0, x1};
}

void DistanceField::nearer_site(int si, int sj, std::vector<std::int32_t>& chunk_max) {
    // Squared distances of grids up to 30,000 pixels a side fit in 32 bits.
    const int chunks = (width_ + kChunk - 1) / kChunk;
    for (int j = 0; j < height_; ++j) {
        std::int32_t* row = dist2_.data() + static_cast<std::size_t>(j) * width_;
        std::int32_t* most = chunk_max.data() + static_cast<std::size_t>(j) * chunks;
        const std::int32_t dy2 = (j - sj) * (j - sj);
        for (int c = 0; c < chunks; ++c) {
            const auto [x0, x1] = kept_run(j, c);
            if (x0 >= x1) continue;
            const int dx = si < x0 ? x0 - si : si >= x1 ? si - (x1 - 1) : 0;
            if (dx * dx + dy2 >= most[c]) continue;  // no pixel of the run comes nearer
            std::int32_t m = 0;
            for (int i = x0; i < x1; ++i) {
                row[i] = std::min(row[i], (i - si) * (i - si) + dy2);
                m = std::max(m, row[i]);
            }
            most[c] = m;
        }
    }
}

void DistanceField::recompute_elements(const std::vector<std::uint8_t>& occupancy) {
    if (occupancy.size() != dist2_.size())
        throw std::invalid_argument("DistanceField::recompute_elements: occupancy size mismatch");
    const int w = width_;
    const std::uint8_t* occ = occupancy.data();
    std::int32_t* site = site_.empty() ? nullptr : site_.data();
    if (metric_ == DistanceMetric::manhattan) {
        manhattan_transform(w, height_, occ, false,
                            static_cast<std::uint8_t>(ObstacleKind::boundary), dist2_.data(), site);
    } else {
        separable_edt(w, height_, ByteSites{occ, w, -1}, dist2_.data(), site, kept_spans(),
                      scratch_, other_scratch_);
    }
    if (lazy_) far_.reset(w, height_, dist2_.data(), metric_);
}

// Keeps the first of equal pixels, in order: the order breaks ties of the feature transform.
// (The render buffer sends each pixel once.)
static void drop_duplicates(std::vector<int>& pixels) {
    if (std::is_sorted(pixels.begin(), pixels.end())) {
        pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
        return;
    }
    std::vector<int> sorted = pixels;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return;
    std::unordered_set<int> seen;
    std::erase_if(pixels, [&](int p) { return !seen.insert(p).second; });
}

void DistanceField::add_sites(const std::vector<int>& pixels, ObstacleKind kind,
                              std::vector<int>* changed) {
    if (kind == ObstacleKind::none) return;
    std::vector<int>& fresh = fresh_;  // kept between calls: most add a few pixels
    fresh.clear();
    for (int p : pixels) {
        // A site already (distance 0) keeps its kind.
        if (p < 0 || static_cast<std::size_t>(p) >= dist2_.size() || dist2_[p] == 0) continue;
        fresh.push_back(p);
    }
    drop_duplicates(fresh);
    if (fresh.empty()) return;
    if (lazy_ && kind == ObstacleKind::element) {
        // Measured when a tile that may need them is trusted.
        for (int p : fresh) {
            dist2_[p] = 0;
            if (changed) changed->push_back(p);
        }
        far_.defer(fresh);
        return;
    }
    if (metric_ == DistanceMetric::manhattan) {
        manhattan_brushfire(width_, height_, fresh, dist2_.data(),
                            site_.empty() ? nullptr : site_.data(), changed, queue_);
        if (kind == ObstacleKind::boundary)
            manhattan_brushfire(width_, height_, fresh, boundary2_.data(), nullptr, changed,
                                queue_);
        return;
    }
    propagate(fresh, dist2_, site_.empty() ? nullptr : &site_, changed);
    if (kind == ObstacleKind::boundary) propagate(fresh, boundary2_, nullptr, changed);
}

namespace {

// Blobs spanning at most this many columns are measured directly from their runs of sites;
// wider ones too while their row envelopes fit in direct_pieces_ (the window's EDT reads every
// pixel of a window wider than the blob, the envelopes only the rows the fill visits).
constexpr std::size_t kDirectColumns = 32;

// Distances to the new sites from their EDT over a window (pixels inside the window only).
struct WindowMeasure {
    const std::int32_t* d2;
    const std::int32_t* site;
    int width, window_width, x0, y0;

    struct Row {
        const WindowMeasure& m;
        std::size_t offset;  // of pixel (0, j) in the window arrays, shifted by x0
        std::int64_t at(int i, int& nearest) const {
            const std::size_t local = offset + static_cast<std::size_t>(i - m.x0);
            const int ls = m.site[local];
            nearest = (ls / m.window_width + m.y0) * m.width + ls % m.window_width + m.x0;
            return m.d2[local];
        }
    };
    Row row(int j, int) const {
        return {*this, static_cast<std::size_t>(j - y0) * static_cast<std::size_t>(window_width)};
    }
};

}  // namespace

// The wavefront of the header comment, as an 8-connected scanline fill: a pixel is "inside"
// when it is a new site or sqrt(m) < sqrt(D) + 1; the fill evaluates every inside pixel
// reachable from the new sites and all their 8-neighbours, once each. `measure.row(j, x)` gives
// an object whose `at(i, nearest)` returns m exactly for pixels of row j in the measurable
// area and sets the nearest new site (a pixel index); `measurable(i, j)` says whether it can.
// Returns false (nothing changed) when the fill reached an unmeasurable pixel.
template <bool kCommit, class Measure, class Measurable>
bool DistanceField::wavefront(const std::vector<int>& sites, Grid32& d2v, std::int32_t* site,
                              std::vector<int>* out, Measure& measure, Measurable measurable) {
    const int w = width_, h = height_;
    // visit_ == base: evaluated, outside; base + 1: inside; base + 2: inside, its row span filled.
    // Allocated on the first fill: a lazy field (element sites deferred) may never need it.
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    if (visit_.size() != n) visit_.assign(n, 0);
    if (stamp_ > std::numeric_limits<std::uint16_t>::max() - 4) {
        std::fill(visit_.begin(), visit_.end(), 0);
        stamp_ = 0;
    }
    const std::uint16_t base = static_cast<std::uint16_t>(stamp_ + 1);
    stamp_ = static_cast<std::uint16_t>(stamp_ + 3);
    std::uint16_t* visit = visit_.data();
    std::int32_t* d2 = d2v.data();
    improved_.clear();
    stack_.clear();
    for (int p : sites) {
        visit[p] = static_cast<std::uint16_t>(base + 1);
        if constexpr (kCommit) {
            d2[p] = 0;
            if (site) site[p] = p;
            if (out) out->push_back(p);
        } else {
            improved_.push_back({p, 0, p});
        }
        stack_.push_back({p % w, p / w, 0, 0, 0});
    }
    bool escaped = false;
    // Evaluates pixel (i, j), r = j*w+i, not yet visited, of `line` (row j). Returns whether
    // it is inside.
    auto evaluate = [&](auto& line, int i, int j, int r) {
        if (!measurable(i, j)) {
            escaped = true;
            return false;
        }
        const std::int64_t old = d2[r];
        bool in = false;
        if (old != 0) {  // an obstacle is never nearer to a new site
            int nearest;
            const std::int64_t m = line.at(i, nearest);
            if (m < old) {
                if constexpr (kCommit) {
                    d2[r] = static_cast<std::int32_t>(m);
                    if (site) site[r] = nearest;
                    if (out) out->push_back(r);
                } else {
                    improved_.push_back({r, static_cast<std::int32_t>(m), nearest});
                }
            }
            const std::int64_t t = m - old - 1;  // sqrt(m) < sqrt(old) + 1
            in = t < 0 || t * t < 4 * old;
        }
        visit[r] = static_cast<std::uint16_t>(base + (in ? 1 : 0));
        return in;
    };
    auto inside = [&](auto& line, int i, int j, int r) {
        const std::uint16_t v = visit[r];
        if (v >= base) return v > base;
        return evaluate(line, i, j, r);
    };
    // Scans row nj over [x0, x1], evaluating new pixels and pushing one seed per run of inside
    // pixels not yet filled; (j, xl, xr) is the span being filled, the seeds' parent.
    auto scan = [&](int nj, int x0, int x1, int j, int xl, int xr) {
        x0 = std::max(0, x0);
        x1 = std::min(w - 1, x1);
        if (nj < 0 || nj >= h || x0 > x1) return;
        const int nrow = nj * w;
        auto line = measure.row(nj, x0);
        bool run = false;
        for (int x = x0; x <= x1; ++x) {
            const std::uint16_t v = visit[nrow + x];
            bool in;
            if (v >= base) {
                in = v > base;
                if (in && !run && v == base + 1) stack_.push_back({x, nj, nj - j, xl, xr});
            } else {
                in = evaluate(line, x, nj, nrow + x);
                if (escaped) return;
                if (in && !run) stack_.push_back({x, nj, nj - j, xl, xr});
            }
            run = in;
        }
    };
    while (!stack_.empty() && !escaped) {
        const Seed seed = stack_.back();
        stack_.pop_back();
        const int i = seed.x, j = seed.y;
        const int row = j * w;
        if (visit[row + i] == base + 2) continue;
        int xl = i, xr = i;
        {
            auto line = measure.row(j, i);
            while (xl > 0 && inside(line, xl - 1, j, row + xl - 1)) --xl;
            while (xr < w - 1 && inside(line, xr + 1, j, row + xr + 1)) ++xr;
        }
        if (escaped) break;
        for (int x = xl; x <= xr; ++x) visit[row + x] = static_cast<std::uint16_t>(base + 2);
        if (seed.dir == 0) {
            scan(j - 1, xl - 1, xr + 1, j, xl, xr);
            scan(j + 1, xl - 1, xr + 1, j, xl, xr);
        } else {
            scan(j + seed.dir, xl - 1, xr + 1, j, xl, xr);
            // The parent span's row was evaluated over [pl - 1, pr + 1] when it was filled, and
            // holds no unfilled inside pixel there: only the parts beyond it are new.
            scan(j - seed.dir, xl - 1, std::min(xr + 1, seed.pl - 2), j, xl, xr);
            scan(j - seed.dir, std::max(xl - 1, seed.pr + 2), xr + 1, j, xl, xr);
        }
    }
    return !escaped;
}

void DistanceField::propagate(const std::vector<int>& sites, Grid32& d2,
                              std::vector<std::int32_t>* site, std::vector<int>* out) {
    const int w = width_, h = height_;
    std::int32_t* site_data = site ? site->data() : nullptr;
    blob_.reset(sites, w, h);
    if (blob_.columns() <= kDirectColumns ||
        blob_.columns() * static_cast<std::size_t>(h) <= direct_pieces_) {
        wavefront<true>(sites, d2, site_data, out, blob_, [](int, int) { return true; });
        return;
    }

    // Wide blobs: an EDT of the new sites over a window around them, doubled until the
    // wavefront stays inside. It starts at twice the old distance of the new sites (the empty
    // space they were put in).
    int bx0 = w, by0 = h, bx1 = -1, by1 = -1;
    std::int64_t room = 0;
    for (int p : sites) {
        const int i = p % w, j = p / w;
        bx0 = std::min(bx0, i);
        bx1 = std::max(bx1, i);
        by0 = std::min(by0, j);
        by1 = std::max(by1, j);
        room = std::max<std::int64_t>(room, d2[p] == infinite ? 0 : d2[p]);
    }
    bool done = false;
    int rho = std::max(8, 2 * static_cast<int>(std::sqrt(static_cast<double>(room))) + 2);
    for (; !done; rho *= 2) {
        const int wx0 = std::max(0, bx0 - rho), wx1 = std::min(w - 1, bx1 + rho);
        const int wy0 = std::max(0, by0 - rho), wy1 = std::min(h - 1, by1 + rho);
        const int ww = wx1 - wx0 + 1, wh = wy1 - wy0 + 1;
        const std::size_t wn = static_cast<std::size_t>(ww) * static_cast<std::size_t>(wh);
        window_sites_.assign(wn, 0);
        for (int p : sites)
            window_sites_[static_cast<std::size_t>(p / w - wy0) * ww + (p % w - wx0)] = 1;
        window_d2_.resize(wn);
        window_site_.resize(wn);
        const std::uint8_t* mask = window_sites_.data();
        separable_edt(ww, wh, ByteSites{mask, ww, -1}, window_d2_.data(), window_site_.data(),
                      nullptr, window_scratch_, other_scratch_);
        WindowMeasure measure{window_d2_.data(), window_site_.data(), w, ww, wx0, wy0};
        auto measurable = [&](int i, int j) {
            return i >= wx0 && i <= wx1 && j >= wy0 && j <= wy1;
        };
        done = wavefront<false>(sites, d2, site_data, out, measure, measurable);
    }

    for (const Improvement& im : improved_) {
        d2[im.pixel] = im.d2;
        if (site_data) site_data[im.pixel] = im.site;
        if (out) out->push_back(im.pixel);
    }
}

}  // namespace acanthus::detail
