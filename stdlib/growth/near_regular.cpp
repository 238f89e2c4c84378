#include "near_regular.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference.hpp"

namespace acanthus::growth::detail {
namespace {

// Interior elements measured: an even sample of a huge reference (a few hundred rings show the
// order, and a scatter's noise is already below 0.1 at 100 offsets).
constexpr std::size_t kSampleElements = 2000;
// Fewer first-shell offsets than this tell nothing (a scatter's order is noise about
// 1/sqrt(offsets)).
constexpr std::size_t kFewestOffsets = 60;

}  // namespace

RingRegularity ring_regularity(const ReferenceData& reference) {
    RingRegularity out;
    const std::vector<int>& interior = reference.candidates;
    const std::size_t stride =
        std::max<std::size_t>(1, (interior.size() + kSampleElements - 1) / kSampleElements);
    double c4 = 0, s4 = 0, c6 = 0, s6 = 0;
    std::size_t count = 0;
    std::vector<Vector> ring;
    std::vector<double> gaps;  // per element with more than kShell offsets: 4th / 3rd
    for (std::size_t k = 0; k < interior.size(); k += stride) {
        ring.clear();
        for (const RingSlot& s : reference.rings[static_cast<std::size_t>(interior[k])])
            ring.push_back(s.offset);
        const std::size_t shell = std::min<std::size_t>(kShell, ring.size());
        std::sort(ring.begin(), ring.end(),
                  [](Vector a, Vector b) { return a.length() < b.length(); });
        if (ring.size() > kShell && ring[kShell - 1].length() > 0)
            gaps.push_back(ring[kShell].length() / ring[kShell - 1].length());
        for (std::size_t j = 0; j < shell; ++j) {
            const double a = std::atan2(ring[j].y, ring[j].x);
            c4 += std::cos(4 * a);
            s4 += std::sin(4 * a);
            c6 += std::cos(6 * a);
            s6 += std::sin(6 * a);
            ++count;
        }
    }
    if (count < kFewestOffsets) return out;
    const double n = static_cast<double>(count);
    const double four = std::hypot(c4, s4) / n, six = std::hypot(c6, s6) / n;
    out.fold = six >= four ? 6 : 4;
    out.order = std::max(four, six);
    out.spread = out.order > 0 ? std::sqrt(2 * std::log(1 / out.order)) / out.fold : INFINITY;
    if (!gaps.empty()) {
        std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2),
                         gaps.end());
        out.honeycomb = gaps[gaps.size() / 2] > kShellGap;
    }
    out.near_regular = out.order >= std::max(kNearRegularOrder, kNoiseMargin / std::sqrt(n));
    return out;
}

}  // namespace acanthus::growth::detail
