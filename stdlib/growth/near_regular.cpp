#include "near_regular.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
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
// A honeycomb's empty class holds fewer than 1 in this many elements.
constexpr std::size_t kVacantShare = 50;

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
    std::vector<double> lengths;
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
            lengths.push_back(ring[j].length());
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
    out.direction = (six >= four ? std::atan2(s6, c6) : std::atan2(s4, c4)) / out.fold;
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<long>(lengths.size() / 2),
                     lengths.end());
    out.shell = lengths[lengths.size() / 2];
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

namespace {

// Lattice coordinates of `v` in the basis (u, w), rounded.
std::pair<double, double> rounded(Vector v, Vector u, Vector w) {
    const double det = u.cross(w);
    return {std::round(v.cross(w) / det), std::round(u.cross(v) / det)};
}

// Least squares: the basis (u, w) that best maps the integer pairs `n` onto `v`.
bool fit_basis(const std::vector<Vector>& v, const std::vector<std::pair<double, double>>& n,
               Vector& u, Vector& w) {
    double aa = 0, ab = 0, bb = 0;
    Vector va, vb;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const auto [a, b] = n[k];
        aa += a * a;
        ab += a * b;
        bb += b * b;
        va += v[k] * a;
        vb += v[k] * b;
    }
    const double det = aa * bb - ab * ab;
    if (!(std::abs(det) > 1e-9 * (aa * bb + 1))) return false;
    u = (va * bb - vb * ab) / det;
    w = (vb * aa - va * ab) / det;
    return true;
}

}  // namespace

std::optional<JitteredLattice> fit_jittered_lattice(const ReferenceData& reference,
                                                    const RingRegularity& regularity) {
    if (regularity.fold == 0 || !(regularity.shell > 0)) return std::nullopt;
    const double a = regularity.shell;
    Vector u = Vector{std::cos(regularity.direction), std::sin(regularity.direction)} * a;
    Vector w = u.rotated(regularity.fold == 6 ? M_PI / 3 : M_PI / 2);
    // The basis from the interior rings' offsets, each snapped to the nearest short translation
    // (local: a first guess a few percent off snaps these right), then refitted.
    std::vector<Vector> offsets;
    for (int e : reference.candidates)
        for (const RingSlot& s : reference.rings[static_cast<std::size_t>(e)])
            if (s.offset.dot(s.offset) < 6.25 * a * a) offsets.push_back(s.offset);
    std::vector<std::pair<double, double>> steps(offsets.size());
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t k = 0; k < offsets.size(); ++k) steps[k] = rounded(offsets[k], u, w);
        if (!fit_basis(offsets, steps, u, w)) return std::nullopt;
    }
    // Every element on the lattice from an origin amid them, origin and basis refitted to all.
    const auto& elements = reference.elements;
    const std::size_t n = elements.size();
    Point mean;
    for (const auto& e : elements) mean = mean + (e.position - Point{}) / static_cast<double>(n);
    Point origin = elements.front().position;
    double nearest = (origin - mean).dot(origin - mean);
    for (const auto& e : elements)
        if ((e.position - mean).dot(e.position - mean) < nearest) {
            origin = e.position;
            nearest = (e.position - mean).dot(e.position - mean);
        }
    std::vector<std::pair<double, double>> index(n);
    std::vector<Vector> from(n);
    for (int pass = 0; pass < 3; ++pass) {
        for (std::size_t i = 0; i < n; ++i) index[i] = rounded(elements[i].position - origin, u, w);
        // The origin: the mean residual; then the basis from the positions about it.
        Vector shift;
        for (std::size_t i = 0; i < n; ++i)
            shift += (elements[i].position - origin) - u * index[i].first - w * index[i].second;
        origin = origin + shift / static_cast<double>(n);
        for (std::size_t i = 0; i < n; ++i) from[i] = elements[i].position - origin;
        if (!fit_basis(from, index, u, w)) return std::nullopt;
    }
    JitteredLattice out;
    out.basis[0] = u;
    out.basis[1] = w;
    out.origin = origin;
    std::vector<std::pair<double, double>> taken = index;
    std::sort(taken.begin(), taken.end());
    if (std::adjacent_find(taken.begin(), taken.end()) != taken.end()) return std::nullopt;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        out.site.push_back(origin + u * index[i].first + w * index[i].second);
        out.jitter.push_back(elements[i].position - out.site.back());
        sum += out.jitter.back().dot(out.jitter.back());
    }
    out.rms = std::sqrt(sum / static_cast<double>(n)) / std::sqrt(u.length() * w.length());
    if (!(out.rms <= kMostJitter)) return std::nullopt;
    if (regularity.fold == 6) {
        std::size_t count[3] = {0, 0, 0};
        for (const auto& [a, b] : index)
            ++count[JitteredLattice::sublattice({static_cast<long>(a), static_cast<long>(b)})];
        // A honeycomb: one class (almost) empty, the other two about even.
        const auto least = std::min_element(count, count + 3) - count;
        if (count[least] <= n / kVacantShare &&
            std::max({count[0], count[1], count[2]}) < n * 2 / 3)
            out.vacant = static_cast<int>(least);
    }
    return out;
}

const RingRegularity& regularity_of(const ReferenceData& reference) {
    std::call_once(reference.regularity_once, [&] {
        reference.regularity = std::make_shared<const RingRegularity>(ring_regularity(reference));
    });
    return *reference.regularity;
}

const JitteredLattice* jittered_lattice_of(const ReferenceData& reference) {
    std::call_once(reference.jittered_once, [&] {
        const RingRegularity& regularity = regularity_of(reference);
        if (!regularity.near_regular) return;
        if (auto fit = fit_jittered_lattice(reference, regularity))
            reference.jittered = std::make_shared<const JitteredLattice>(std::move(*fit));
    });
    return reference.jittered.get();
}

std::pair<long, long> JitteredLattice::index(Point p) const {
    const auto [i, j] = rounded(p - origin, basis[0], basis[1]);
    return {static_cast<long>(i), static_cast<long>(j)};
}

Point JitteredLattice::site_at(std::pair<long, long> index) const {
    return origin + basis[0] * static_cast<double>(index.first) +
           basis[1] * static_cast<double>(index.second);
}

int JitteredLattice::sublattice(std::pair<long, long> index) {
    return static_cast<int>(((index.first - index.second) % 3 + 3) % 3);
}

}  // namespace acanthus::growth::detail
