// After growth from a near-regular reference: the fitted motifs' jitter about their lattice sites
// is scaled by one factor until the motifs' NN median is the reference's. Each motif copies its
// element's jitter, but its neighbours' jitter comes from elsewhere in the reference, so the
// grown spacing is a fresh draw of the jitter: on a hundred motifs it lands a few percent either
// side of the reference's own draw, which is what an author compares with. Beyond the paper
// (docs/stdlib/growth.md, "Spacing matched").
#include <algorithm>
#include <cmath>

#include "fidelity.hpp"
#include "synthesis.hpp"

namespace acanthus::growth::detail {
namespace {

constexpr double kLeastScale = 0.6, kMostScale = 1.5;
// Left as grown within this of the reference's NN median (a fraction of it): a hundred motifs'
// own scatter, which the reference's draw has too. Beyond it, scaled back to this.
constexpr double kBand = 0.025;
constexpr double kClose = 0.004;  // of kBand's edge: near enough
constexpr std::size_t kFewestFitted = 12;
constexpr int kRounds = 3;

}  // namespace

void Synthesis::match_spacing() {
    if (!options_.match_spacing || !jittered_ || fitted_sites_.size() < kFewestFitted) return;
    const ReferenceProfile& profile = profile_of(reference_);
    const RingChecker& checker = profile.checker;
    const double spacing = checker.spacing();
    if (!(spacing > 0) || !(profile.copied_nn_median > 0) || !(profile.inner_nn_median > 0)) return;
    // As the report measures: NN within 2.1 NN (beyond: 4), all motifs against the copied
    // elements and those 1.5 NN inside the panel against the inner ones, the two ratios averaged.
    const double cap = 2.1 * spacing;
    std::vector<Point> points;
    std::vector<int> index_of(pattern_.nodes().size(), -1);
    std::vector<bool> inner;
    for (int id : placed_) {
        const Node& n = pattern_[id];
        if (!n.alive || !n.placed()) continue;
        index_of[static_cast<std::size_t>(id)] = static_cast<int>(points.size());
        points.push_back(n.position);
        inner.push_back(panel_.clearance(n.position) >= checker.interior_clearance());
    }
    struct Movable {
        int id;
        std::size_t at;  // in points
        Point site;
        Vector jitter;
    };
    std::vector<Movable> movable;
    for (const auto& [id, site] : fitted_sites_) {
        const int at = index_of[static_cast<std::size_t>(id)];
        if (at < 0 || !pattern_[id].fixed) continue;
        movable.push_back({id, static_cast<std::size_t>(at), site, pattern_[id].position - site});
    }
    // The two ratios' mean.
    auto ratio = [&](const std::vector<Point>& at) {
        std::vector<double> nn = nn_distances(at, cap);
        std::vector<double> inside;
        for (std::size_t i = 0; i < nn.size(); ++i) {
            if (nn[i] >= cap) nn[i] = 4 * spacing;
            if (inner[i]) inside.push_back(nn[i]);
        }
        const double all = median(nn) / spacing / profile.copied_nn_median;
        const double in = inside.empty() ? all : median(inside) / spacing / profile.inner_nn_median;
        return (all + in) / 2;
    };
    // The jitter copied is each movable motif's jitter from the first round on.
    double scale = 1;
    for (int round = 0; round < kRounds && movable.size() >= kFewestFitted; ++round) {
        const double now = ratio(points);
        if (std::abs(now - 1) <= kBand + kClose) break;
        const double target = std::clamp(now, 1 - kBand, 1 + kBand);
        auto scaled = [&](double k) {
            std::vector<Point> at = points;
            for (const Movable& m : movable) at[m.at] = m.site + m.jitter * (k / scale);
            return at;
        };
        // More jitter, closer nearest neighbours: the ratio falls as the factor grows.
        double lo = kLeastScale, hi = kMostScale, k;
        if (ratio(scaled(hi)) > target) {
            k = hi;
        } else if (ratio(scaled(lo)) < target) {
            k = lo;
        } else {
            for (int step = 0; step < 20; ++step) {
                const double mid = (lo + hi) / 2;
                (ratio(scaled(mid)) > target ? lo : hi) = mid;
            }
            k = (lo + hi) / 2;
        }
        if (std::abs(k - scale) < 1e-9) break;
        // Motif by motif in placement order, each checked where it would go against the others
        // where they stand; one that would overlap, crowd or leave the panel stays.
        std::vector<Movable> moved;
        for (const Movable& m : movable) {
            const Point from = pattern_[m.id].position;
            const Point to = m.site + m.jitter * (k / scale);
            const Node& n = pattern_[m.id];
            pattern_.move(m.id, to);
            if (panel_.contains(to) && panel_.reaches(from, to) && motif_fits(m.id, to, n.radius) &&
                too_close(m.id, to, n.symbol, true) < 0 && !crowded(m.id, to)) {
                points[m.at] = to;
                moved.push_back({m.id, m.at, m.site, m.jitter * (k / scale)});
            } else {
                pattern_.move(m.id, from);
            }
        }
        if (moved.empty()) break;
        movable = std::move(moved);
        scale = k;
        stats_.jitter_scale = k;
        stats_.rescaled = static_cast<long>(movable.size());
    }
}

}  // namespace acanthus::growth::detail
