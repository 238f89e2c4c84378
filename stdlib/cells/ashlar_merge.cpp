#include "ashlar_merge.hpp"

#include <acanthus/progress.hpp>
#include <algorithm>
#include <cstddef>

namespace acanthus::cells::detail {

std::vector<Stone> merge_ashlar(const std::vector<char>& free, int rows, int units, int max_w,
                                int max_h, Random& random) {
    std::vector<Stone> stones;
    std::vector<int> owner(free.size(), -1);
    for (int r = 0; r < rows; ++r)
        for (int u = 0; u < units; ++u)
            if (free[static_cast<std::size_t>(r * units + u)]) {
                owner[static_cast<std::size_t>(r * units + u)] = static_cast<int>(stones.size());
                stones.push_back({r, u, 1, 1});
            }
    auto at = [&](int r, int u) {
        if (r < 0 || u < 0 || r >= rows || u >= units) return -1;
        return owner[static_cast<std::size_t>(r * units + u)];
    };
    std::vector<char> alive(stones.size(), 1), queued(stones.size(), 1);
    std::vector<int> queue(stones.size());
    for (std::size_t i = 0; i < queue.size(); ++i) queue[i] = static_cast<int>(i);
    auto push = [&](int s) {
        if (s >= 0 && !queued[static_cast<std::size_t>(s)]) {
            queued[static_cast<std::size_t>(s)] = 1;
            queue.push_back(s);
        }
    };
    long merges = 0;
    while (!queue.empty()) {
        auto k = static_cast<std::size_t>(
            random.uniform_int(0, static_cast<long long>(queue.size()) - 1));
        int s = queue[k];
        queue[k] = queue.back();
        queue.pop_back();
        queued[static_cast<std::size_t>(s)] = 0;
        if (!alive[static_cast<std::size_t>(s)]) continue;  // merged into another since queued
        const Stone a = stones[static_cast<std::size_t>(s)];
        // Neighbours sharing a whole side, so that the merge stays a rectangle.
        int candidates[4], n = 0;
        auto side = [&](int t, bool across) {
            if (t < 0) return;
            const Stone& b = stones[static_cast<std::size_t>(t)];
            if (across ? b.row == a.row && b.h == a.h && a.w + b.w <= max_w
                       : b.unit == a.unit && b.w == a.w && a.h + b.h <= max_h)
                candidates[n++] = t;
        };
        side(at(a.row, a.unit - 1), true);
        side(at(a.row, a.unit + a.w), true);
        side(at(a.row - 1, a.unit), false);
        side(at(a.row + a.h, a.unit), false);
        if (n == 0) continue;
        int t = candidates[random.uniform_int(0, n - 1)];
        const Stone b = stones[static_cast<std::size_t>(t)];
        Stone m{std::min(a.row, b.row), std::min(a.unit, b.unit), 0, 0};
        m.h = std::max(a.row + a.h, b.row + b.h) - m.row;
        m.w = std::max(a.unit + a.w, b.unit + b.w) - m.unit;
        alive[static_cast<std::size_t>(t)] = 0;
        stones[static_cast<std::size_t>(s)] = m;
        // A wall's worth of units merges in seconds before any of them becomes a cell.
        report_progress("ashlar merges", ++merges);
        for (int r = b.row; r < b.row + b.h; ++r)
            for (int u = b.unit; u < b.unit + b.w; ++u)
                owner[static_cast<std::size_t>(r * units + u)] = s;
        // The merged stone and everything around it may merge anew.
        push(s);
        for (int u = m.unit; u < m.unit + m.w; ++u)
            push(at(m.row - 1, u)), push(at(m.row + m.h, u));
        for (int r = m.row; r < m.row + m.h; ++r)
            push(at(r, m.unit - 1)), push(at(r, m.unit + m.w));
    }
    std::vector<Stone> out;
    for (std::size_t i = 0; i < stones.size(); ++i)
        if (alive[i]) out.push_back(stones[i]);
    std::sort(out.begin(), out.end(), [](const Stone& x, const Stone& y) {
        return x.row != y.row ? x.row < y.row : x.unit < y.unit;
    });
    return out;
}

}  // namespace acanthus::cells::detail
