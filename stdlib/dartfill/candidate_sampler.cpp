#include "candidate_sampler.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace acanthus::dartfill {
namespace {

constexpr int group_count = 16 + 28 * 8;  // squared distances below 2^32

}  // namespace

double power_of_distance(double q, double exponent) {
    double half = exponent / 2;
    if (half == std::floor(half) && half >= 0 && half <= 64) {
        double result = 1, base = q;
        for (auto e = static_cast<unsigned>(half); e; e >>= 1) {
            if (e & 1u) result *= base;
            base *= base;
        }
        return result;
    }
    return std::pow(q, half);
}

int CandidateSampler::group_of(std::int64_t d2) {
    if (d2 < 16) return static_cast<int>(d2);
    int b = std::bit_width(static_cast<std::uint64_t>(d2)) - 1;
    return 16 + (b - 4) * 8 + static_cast<int>((d2 >> (b - 3)) & 7);
}

std::int64_t CandidateSampler::group_end(int g) {
    if (g < 16) return g + 1;
    int b = (g - 16) / 8 + 4, m = (g - 16) % 8;
    return static_cast<std::int64_t>(8 + m + 1) << (b - 3);
}

CandidateSampler::CandidateSampler(const GapField& gaps)
    : gaps_(gaps),
      groups_(group_count),
      group_(static_cast<std::size_t>(gaps.size()), -1),
      slot_(static_cast<std::size_t>(gaps.size()), 0) {
    for (int i = 0, n = gaps.size(); i < n; ++i) file(i);
}

void CandidateSampler::file(int pixel) {
    std::int64_t d2 = gaps_.squared_distance(pixel);
    if (!gaps_.free(pixel) || d2 <= 0 || d2 == acanthus::detail::DistanceField::infinite) return;
    int g = group_of(d2);
    group_[pixel] = g;
    slot_[pixel] = static_cast<int>(groups_[g].size());
    groups_[g].push_back(pixel);
    ++filed_;
}

void CandidateSampler::unfile(int pixel) {
    int g = group_[pixel];
    if (g < 0) return;
    std::vector<int>& members = groups_[g];
    int last = members.back();
    members[slot_[pixel]] = last;
    slot_[last] = slot_[pixel];
    members.pop_back();
    group_[pixel] = -1;
    --filed_;
}

void CandidateSampler::update(const std::vector<int>& pixels) {
    for (int p : pixels) {
        std::int64_t d2 = gaps_.squared_distance(p);
        bool fileable = gaps_.free(p) && d2 > 0 && d2 != acanthus::detail::DistanceField::infinite;
        int g = fileable ? group_of(d2) : -1;
        if (g == group_[p]) continue;
        unfile(p);
        if (fileable) file(p);
    }
}

std::int64_t CandidateSampler::max_squared_distance() const {
    for (int g = group_count - 1; g > 0; --g) {
        if (groups_[g].empty()) continue;
        std::int64_t best = 0;
        for (int p : groups_[g]) best = std::max(best, gaps_.squared_distance(p));
        return best;
    }
    return 0;
}

void CandidateSampler::draw_q(double exponent, Random& random, std::vector<int>& q) const {
    std::int64_t max = max_squared_distance();
    if (max == 0) return;
    double inv = 1.0 / static_cast<double>(max);
    for (int g = 1; g < group_count; ++g) {
        const std::vector<int>& members = groups_[g];
        if (members.empty()) continue;
        double bound =
            power_of_distance(std::min(1.0, static_cast<double>(group_end(g) - 1) * inv), exponent);
        if (!(bound > 0)) continue;
        auto size = static_cast<double>(members.size());
        // Proposals at rate `bound`: the gap to the next one is geometric.
        double log_miss = bound < 1 ? std::log1p(-bound) : 0;
        double k = -1;
        while (true) {
            if (bound < 1) {
                k += 1 + std::floor(std::log1p(-random.uniform()) / log_miss);
            } else {
                k += 1;
            }
            if (!(k < size)) break;
            int pixel = members[static_cast<std::size_t>(k)];
            double alpha = power_of_distance(
                static_cast<double>(gaps_.squared_distance(pixel)) * inv, exponent);
            if (bound < 1 || alpha < 1) {
                if (random.uniform() * bound >= alpha) continue;
            }
            q.push_back(pixel);
        }
    }
}

std::vector<int> CandidateSampler::draw(double exponent, int count, Random& random) const {
    std::vector<int> q;
    draw_q(exponent, random, q);
    auto n = std::min<std::size_t>(static_cast<std::size_t>(std::max(count, 1)), q.size());
    for (std::size_t k = 0; k < n; ++k) {
        auto j = static_cast<std::size_t>(
            random.uniform_int(static_cast<long long>(k), static_cast<long long>(q.size()) - 1));
        std::swap(q[k], q[j]);
    }
    q.resize(n);
    return q;
}

}  // namespace acanthus::dartfill
