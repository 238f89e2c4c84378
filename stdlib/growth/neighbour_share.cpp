// After growth from an irregular reference: pairs of motifs of two symbols exchange their
// reference elements until the share of close neighbour pairs with one symbol is the
// reference's (the fidelity report's `same_symbol_neighbours`). Ring matching copies the
// reference's symbol pairs only on the links it makes itself; where fronts meet, seeds merge and
// restarts fill, the pairs are left to chance, and in a panel of a hundred motifs that moves the
// share by up to ten points either way. An exchange keeps every position, so the spacing and the
// symbol mix stay exactly as grown.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "fidelity.hpp"
#include "lattice.hpp"
#include "synthesis.hpp"

namespace acanthus::growth::detail {
namespace {

// Motifs looked at per symbol and direction each round: the ones whose change of symbol moves
// the most pairs.
constexpr std::size_t kShortlist = 12;

}  // namespace

void Synthesis::balance_neighbours() {
    const std::size_t symbols = reference_.symbols.size();
    // A regular reference's symbols follow its lattice (also where growth did not use it, in
    // flow or rotation mode): an exchange there would break the pattern, not restore a share.
    if (!options_.neighbour_share || symbols < 2 || placed_.size() < 3 || lattice_of(reference_))
        return;
    const ReferenceProfile& profile = profile_of(reference_);
    const double reach = profile.checker.reach();
    const std::size_t n = placed_.size();
    std::vector<int> at(pattern_.nodes().size(), -1);
    for (std::size_t k = 0; k < n; ++k)
        at[static_cast<std::size_t>(placed_[k])] = static_cast<int>(k);
    // Close neighbours as the report counts them: placed motifs nearer than `reach`.
    std::vector<std::vector<int>> near(n);
    long close = 0, same = 0;
    auto symbol = [&](int k) { return pattern_[placed_[static_cast<std::size_t>(k)]].symbol; };
    for (std::size_t k = 0; k < n; ++k) {
        const Point p = pattern_[placed_[k]].position;
        for (int other : pattern_.near(p, reach)) {
            const int j = at[static_cast<std::size_t>(other)];
            if (j < 0 || j == static_cast<int>(k) ||
                !(distance(pattern_[other].position, p) < reach))
                continue;
            near[k].push_back(j);
            if (j > static_cast<int>(k)) {
                ++close;
                same += symbol(j) == symbol(static_cast<int>(k));
            }
        }
    }
    if (close == 0) return;
    const double target = profile.same_symbol_share * static_cast<double>(close);
    // Same-symbol pairs gained when motif k takes symbol s, the others kept.
    auto gain = [&](int k, int s) {
        long g = 0;
        const int own = symbol(k);
        for (int j : near[static_cast<std::size_t>(k)]) g += (symbol(j) == s) - (symbol(j) == own);
        return g;
    };
    auto adjacent = [&](int a, int b) {
        const auto& list = near[static_cast<std::size_t>(a)];
        return std::find(list.begin(), list.end(), b) != list.end();
    };
    auto exchange = [&](int a, int b) {
        Node& x = pattern_[placed_[static_cast<std::size_t>(a)]];
        Node& y = pattern_[placed_[static_cast<std::size_t>(b)]];
        const int sx = x.source, sy = y.source;
        x.angle += reference_.elements[sy].angle - reference_.elements[sx].angle;
        y.angle += reference_.elements[sx].angle - reference_.elements[sy].angle;
        x.radius = reference_.radius[sy] * x.scale;
        y.radius = reference_.radius[sx] * y.scale;
        std::swap(x.source, y.source);
        std::swap(x.symbol, y.symbol);
    };
    std::vector<std::vector<std::pair<long, int>>> by_symbol(symbols);
    for (;;) {
        const double need = target - static_cast<double>(same);
        if (std::abs(need) < 1) break;  // within one pair of the reference's share
        const long sign = need > 0 ? 1 : -1;
        // For each ordered pair of symbols (a, b): a's motifs that gain most (in the direction
        // needed) by taking b, and b's by taking a; every exchange of one from each is scored.
        struct Option {
            double left;  // |need - change| after it
            int a, b;
            long change;
        };
        std::vector<Option> options;
        for (std::size_t sa = 0; sa < symbols; ++sa)
            for (std::size_t sb = sa + 1; sb < symbols; ++sb) {
                for (std::size_t s : {sa, sb}) {
                    by_symbol[s].clear();
                    const auto other = static_cast<int>(s == sa ? sb : sa);
                    for (std::size_t k = 0; k < n; ++k)
                        if (symbol(static_cast<int>(k)) == static_cast<int>(s))
                            by_symbol[s].push_back(
                                {-sign * gain(static_cast<int>(k), other), static_cast<int>(k)});
                    const std::size_t keep = std::min(kShortlist, by_symbol[s].size());
                    std::partial_sort(by_symbol[s].begin(),
                                      by_symbol[s].begin() + static_cast<long>(keep),
                                      by_symbol[s].end());
                    by_symbol[s].resize(keep);
                }
                for (auto [ga, a] : by_symbol[sa])
                    for (auto [gb, b] : by_symbol[sb]) {
                        // Next to each other, each counted the other as a pair it would join.
                        const long change = -sign * (ga + gb) - (adjacent(a, b) ? 2 : 0);
                        const double left = std::abs(need - static_cast<double>(change));
                        if (left < std::abs(need)) options.push_back({left, a, b, change});
                    }
            }
        std::sort(options.begin(), options.end(), [](const Option& x, const Option& y) {
            return std::tie(x.left, x.a, x.b) < std::tie(y.left, y.a, y.b);
        });
        bool done = false;
        for (const Option& o : options) {
            exchange(o.a, o.b);
            // The larger element must fit, and the spacing rule hold, where each now stands.
            if (still_valid(placed_[static_cast<std::size_t>(o.a)]) &&
                still_valid(placed_[static_cast<std::size_t>(o.b)])) {
                for (int k : {o.a, o.b})
                    pattern_.note_radius(pattern_[placed_[static_cast<std::size_t>(k)]].radius);
                same += o.change;
                ++stats_.exchanges;
                done = true;
                break;
            }
            exchange(o.a, o.b);  // back
        }
        if (!done) break;
    }
}

}  // namespace acanthus::growth::detail
