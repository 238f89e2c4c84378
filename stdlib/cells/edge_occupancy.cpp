// 1-D occupancy maps of edges [3.3]: sorted, merged arc-length intervals.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <iterator>

namespace acanthus::cells {

void EdgeOccupancy::claim(double s0, double s1) {
    if (s1 < s0) std::swap(s0, s1);
    s0 = std::max(s0, 0.0);
    s1 = std::min(s1, length_);
    if (!(s1 > s0)) return;
    // Runs ending before s0 or starting after s1 stay; those between merge with the claim.
    auto first = std::lower_bound(runs_.begin(), runs_.end(), s0,
                                  [](const auto& r, double v) { return r.second < v; });
    auto last = std::upper_bound(first, runs_.end(), s1,
                                 [](double v, const auto& r) { return v < r.first; });
    if (first != last) {
        s0 = std::min(s0, first->first);
        s1 = std::max(s1, std::prev(last)->second);
        first = runs_.erase(first, last);
    }
    runs_.insert(first, {s0, s1});
}

bool EdgeOccupancy::is_free(double s0, double s1) const {
    if (s1 < s0) std::swap(s0, s1);
    for (const auto& r : runs_)
        if (r.first < s1 && r.second > s0) return false;
    return true;
}

std::vector<std::pair<double, double>> EdgeOccupancy::free_intervals(double min_length) const {
    std::vector<std::pair<double, double>> out;
    double at = 0;
    for (const auto& r : runs_) {
        if (r.first - at > min_length) out.emplace_back(at, r.first);
        at = std::max(at, r.second);
    }
    if (length_ - at > min_length) out.emplace_back(at, length_);
    return out;
}

}  // namespace acanthus::cells
