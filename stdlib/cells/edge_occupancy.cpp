// 1-D occupancy maps of edges [3.3]: sorted, merged arc-length intervals.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>

namespace acanthus::cells {

void EdgeOccupancy::claim(double s0, double s1) {
    if (s1 < s0) std::swap(s0, s1);
    s0 = std::max(s0, 0.0);
    s1 = std::min(s1, length_);
    if (!(s1 > s0)) return;
    std::vector<std::pair<double, double>> merged;
    merged.reserve(runs_.size() + 1);
    bool placed = false;
    for (const auto& r : runs_) {
        if (r.second < s0) {
            merged.push_back(r);
        } else if (r.first > s1) {
            if (!placed) merged.emplace_back(s0, s1), placed = true;
            merged.push_back(r);
        } else {
            s0 = std::min(s0, r.first);
            s1 = std::max(s1, r.second);
        }
    }
    if (!placed) merged.emplace_back(s0, s1);
    runs_ = std::move(merged);
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
