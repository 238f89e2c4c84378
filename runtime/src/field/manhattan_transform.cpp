#include "field/manhattan_transform.hpp"

#include <algorithm>
#include <limits>

namespace acanthus::detail {
namespace {

constexpr std::int64_t kFar = std::numeric_limits<std::int64_t>::max() / 4;
constexpr std::int32_t kInfinite = std::numeric_limits<std::int32_t>::max();

}  // namespace

void manhattan_transform(int w, int h, const std::uint8_t* occ, bool boundary_only,
                         std::uint8_t boundary_kind, std::int32_t* d2, std::int32_t* site) {
    auto is_site = [&](std::size_t p) {
        return boundary_only ? occ[p] == boundary_kind : occ[p] != 0;
    };
    const std::size_t width = static_cast<std::size_t>(w);
    // Per column: distance to the nearest site above or below (kept in d2 for now) and, with a
    // feature transform, its row (kept in site).
    std::vector<int> last(width, -1);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t p = static_cast<std::size_t>(j) * width + i;
            if (is_site(p)) last[i] = j;
            d2[p] = last[i] >= 0 ? j - last[i] : kInfinite;
            if (site) site[p] = last[i];
        }
    std::fill(last.begin(), last.end(), -1);
    for (int j = h - 1; j >= 0; --j)
        for (int i = 0; i < w; ++i) {
            const std::size_t p = static_cast<std::size_t>(j) * width + i;
            if (d2[p] == 0) last[i] = j;
            if (last[i] >= 0 && last[i] - j < d2[p]) {
                d2[p] = last[i] - j;
                if (site) site[p] = last[i];
            }
        }
    // Per row: min over columns q of |x - q| + g(q), a pass each way.
    std::vector<std::int64_t> g(width), best(width);
    std::vector<int> row(site ? width : 0), from(width);
    for (int j = 0; j < h; ++j) {
        const std::size_t base = static_cast<std::size_t>(j) * width;
        for (int x = 0; x < w; ++x) g[x] = d2[base + x] == kInfinite ? kFar : d2[base + x];
        if (site) std::copy(site + base, site + base + width, row.begin());
        std::int64_t b = kFar;
        int c = -1;
        for (int x = 0; x < w; ++x) {
            if (b < kFar) ++b;
            if (g[x] < b) {
                b = g[x];
                c = x;
            }
            best[x] = b;
            from[x] = c;
        }
        b = kFar;
        c = -1;
        for (int x = w - 1; x >= 0; --x) {
            if (b < kFar) ++b;
            if (g[x] < b) {
                b = g[x];
                c = x;
            }
            if (b < best[x]) {  // ties keep the left one
                best[x] = b;
                from[x] = c;
            }
            d2[base + x] =
                best[x] >= kFar ? kInfinite : static_cast<std::int32_t>(best[x] * best[x]);
            if (site) site[base + x] = from[x] < 0 ? -1 : row[from[x]] * w + from[x];
        }
    }
}

void manhattan_brushfire(int w, int h, const std::vector<int>& sites, std::int32_t* d2,
                         std::int32_t* site, std::vector<int>* out,
                         std::vector<std::pair<int, std::int32_t>>& queue) {
    queue.clear();
    for (int p : sites) {
        d2[p] = 0;
        if (site) site[p] = p;
        if (out) out->push_back(p);
        queue.emplace_back(p, 0);
    }
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int p = queue[head].first;  // not a structured binding: clang 14 cannot capture one
        const std::int32_t d = queue[head].second;
        const int i = p % w, j = p / w;
        const std::int64_t nd = static_cast<std::int64_t>(d) + 1;
        const std::int64_t nd2 = nd * nd;
        auto reach = [&](int n) {
            if (nd2 >= d2[n]) return;
            d2[n] = static_cast<std::int32_t>(nd2);
            if (site) site[n] = site[p];
            if (out) out->push_back(n);
            queue.emplace_back(n, static_cast<std::int32_t>(nd));
        };
        if (i > 0) reach(p - 1);
        if (i < w - 1) reach(p + 1);
        if (j > 0) reach(p - w);
        if (j < h - 1) reach(p + w);
    }
}

}  // namespace acanthus::detail
