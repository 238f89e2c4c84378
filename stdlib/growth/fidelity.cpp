#include "fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "lattice.hpp"
#include "point_grid.hpp"

namespace acanthus::growth::detail {
namespace {

// Each point's neighbours within a reach (closer than it, as distance() measures).
class Neighbours {
  public:
    Neighbours(const std::vector<Point>& points, double reach)
        : points_(points), reach_(reach), squared_(reach * reach), grid_(points, reach) {}
    // f(j) for every point j within the reach of point i, other than i.
    template <class F>
    void each(std::size_t i, F&& f) const {
        const Point p = points_[i];
        grid_.around(p, [&](int k) {
            const auto j = static_cast<std::size_t>(k);
            if (j == i) return;
            const double dx = points_[j].x - p.x, dy = points_[j].y - p.y;
            const double d2 = dx * dx + dy * dy;
            // The squares settle all but a hair's breadth round the reach, where distance()
            // (hypot) decides as it always did.
            if (d2 > squared_ * (1 + 1e-10)) return;
            if (d2 >= squared_ * (1 - 1e-10) && !(distance(p, points_[j]) < reach_)) return;
            f(j);
        });
    }
    // Indices within the reach of point i, other than i, in index order.
    std::vector<std::size_t> of(std::size_t i) const {
        std::vector<std::size_t> out;
        each(i, [&](std::size_t j) { out.push_back(j); });
        std::sort(out.begin(), out.end());
        return out;
    }
    std::size_t count(std::size_t i) const {
        std::size_t n = 0;
        each(i, [&](std::size_t) { ++n; });
        return n;
    }
    // The distance from point i to its nearest neighbour within the reach, or the reach.
    double nearest(std::size_t i) const {
        const Point p = points_[i];
        // distance() of the points whose squares come within rounding of the least so far:
        // the least distance() is among them.
        double least = INFINITY, best = INFINITY;
        each(i, [&](std::size_t j) {
            const double dx = points_[j].x - p.x, dy = points_[j].y - p.y;
            const double d2 = dx * dx + dy * dy;
            if (d2 > least * (1 + 1e-10)) return;
            if (d2 < least * (1 - 1e-10)) best = INFINITY;
            least = std::min(least, d2);
            best = std::min(best, distance(p, points_[j]));
        });
        return std::min(best, reach_);
    }

  private:
    const std::vector<Point>& points_;
    double reach_, squared_;
    PointGrid grid_;
};

struct Site {
    std::vector<Point> points;
    std::vector<std::string> symbols;
};

// NN distances (within `cap`; a lone point counts as `cap`).
std::vector<double> nearest(const Site& s, double cap) { return nn_distances(s.points, cap); }

std::vector<double> histogram(const std::vector<double>& nn, double spacing, double bin) {
    std::vector<double> h(21, 0.0);  // 0 to 2 NN, and beyond
    for (double d : nn) h[std::min(h.size() - 1, static_cast<std::size_t>(d / spacing / bin))] += 1;
    for (double& share : h) share /= static_cast<double>(nn.size());
    return h;
}

std::map<std::string, double> mix(const Site& s) {
    std::map<std::string, double> m;
    for (const std::string& sym : s.symbols) m[sym] += 1;
    for (auto& [name, share] : m) share /= static_cast<double>(s.symbols.size());
    return m;
}

double same_share(const Site& s, double reach) {
    Neighbours n(s.points, reach);
    long close = 0, same = 0;
    for (std::size_t i = 0; i < s.points.size(); ++i)
        n.each(i, [&](std::size_t j) {
            if (j <= i) return;
            ++close;
            same += s.symbols[i] == s.symbols[j];
        });
    return close > 0 ? static_cast<double>(same) / static_cast<double>(close) : 0.0;
}

// Neighbours of each point within `reach`, as offsets and symbols.
std::vector<RingChecker::Ring> rings(const std::vector<Point>& points,
                                     const std::vector<int>& symbols, double reach) {
    Neighbours n(points, reach);
    std::vector<RingChecker::Ring> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j : n.of(i)) {
            out[i].offsets.push_back(points[j] - points[i]);
            out[i].symbols.push_back(symbols[j]);
        }
    return out;
}

// Every neighbour of `a` pairs with a distinct one of `b` of its symbol within `tolerance`.
bool same_ring(const RingChecker::Ring& a, const RingChecker::Ring& b, double tolerance) {
    if (a.offsets.size() != b.offsets.size()) return false;
    std::vector<bool> used(b.offsets.size(), false);
    for (std::size_t k = 0; k < a.offsets.size(); ++k) {
        bool found = false;
        for (std::size_t m = 0; m < b.offsets.size() && !found; ++m)
            if (!used[m] && b.symbols[m] == a.symbols[k] &&
                (b.offsets[m] - a.offsets[k]).length() < tolerance)
                used[m] = found = true;
        if (!found) return false;
    }
    return true;
}

std::vector<Point> points_of(const ReferenceData& reference) {
    std::vector<Point> points;
    for (const ReferenceElement& e : reference.elements) points.push_back(e.position);
    return points;
}

}  // namespace

std::vector<double> nn_distances(const std::vector<Point>& points, double cap) {
    Neighbours n(points, cap);
    std::vector<double> out;
    out.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) out.push_back(n.nearest(i));
    return out;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

double reference_spacing(const ReferenceData& reference) {
    Site ref;
    ref.points = points_of(reference);
    return median(nearest(ref, 2 * reference.mean_edge));
}

std::int64_t RingChecker::key(Vector v) const {
    const double cell = tolerance();
    auto x = static_cast<std::int64_t>(std::floor(v.x / cell));
    auto y = static_cast<std::int64_t>(std::floor(v.y / cell));
    return (x << 32) ^ (y & 0xffffffff);
}

RingChecker::RingChecker(const ReferenceData& reference) {
    const std::vector<Point> points = points_of(reference);
    // reference_spacing(), keeping the distances.
    nn_cap_ = 2 * reference.mean_edge;
    nn_ = nearest(Site{points, {}}, nn_cap_);
    spacing_ = median(nn_);
    if (!(spacing_ > 0)) spacing_ = reference.mean_edge;
    std::vector<Ring> all = rings(points, reference.symbol, reach());
    for (const Ring& r : all) full_ = std::max(full_, r.offsets.size());
    for (std::size_t k = 0; k < all.size(); ++k) {
        const Ring& r = all[k];
        if (r.offsets.size() != full_ || full_ == 0) continue;
        bool known = false;
        const int symbol = reference.symbol[k];
        const Vector probe = r.offsets.front();
        const std::int64_t x = static_cast<std::int64_t>(std::floor(probe.x / tolerance()));
        const std::int64_t y = static_cast<std::int64_t>(std::floor(probe.y / tolerance()));
        for (std::int64_t dx = -1; dx <= 1 && !known; ++dx)
            for (std::int64_t dy = -1; dy <= 1 && !known; ++dy) {
                auto it = index_.find(((x + dx) << 32) ^ ((y + dy) & 0xffffffff));
                if (it == index_.end()) continue;
                for (int d : it->second)
                    if (distinct_symbol_[d] == symbol &&
                        same_ring(r, distinct_[d], 0.005 * spacing_)) {
                        known = true;
                        break;
                    }
            }
        if (known) continue;
        const int id = static_cast<int>(distinct_.size());
        distinct_.push_back(r);
        distinct_symbol_.push_back(symbol);
        std::vector<std::int64_t> keys;
        for (Vector v : r.offsets) keys.push_back(key(v));
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        for (std::int64_t k2 : keys) index_[k2].push_back(id);
    }
}

bool RingChecker::matches(const Ring& ring, int symbol) const {
    if (ring.offsets.size() != full_ || full_ == 0) return false;
    // A matching reference ring has an offset within the tolerance of this ring's first one.
    const Vector probe = ring.offsets.front();
    const std::int64_t x = static_cast<std::int64_t>(std::floor(probe.x / tolerance()));
    const std::int64_t y = static_cast<std::int64_t>(std::floor(probe.y / tolerance()));
    std::vector<int> tried;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            auto it = index_.find(((x + dx) << 32) ^ ((y + dy) & 0xffffffff));
            if (it == index_.end()) continue;
            for (int d : it->second) {
                if (distinct_symbol_[d] != symbol ||
                    std::find(tried.begin(), tried.end(), d) != tried.end())
                    continue;
                tried.push_back(d);
                if (same_ring(ring, distinct_[d], tolerance())) return true;
            }
        }
    return false;
}

std::vector<bool> RingChecker::good(const std::vector<Point>& points,
                                    const std::vector<int>& symbols) const {
    std::vector<Ring> got = rings(points, symbols, reach());
    std::vector<bool> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = matches(got[i], symbols[i]);
    return out;
}

ReferenceProfile::ReferenceProfile(const ReferenceData& reference) : checker(reference) {
    Site ref;
    ref.points = points_of(reference);
    for (const ReferenceElement& e : reference.elements) ref.symbols.push_back(e.symbol);
    const double spacing = checker.spacing();
    // NN distances within 2.1 NN: the checker's, taken within its own cap, serve where that
    // reaches as far (a distance under a cap is the same under any cap above it).
    const double cap = 2.1 * spacing;
    std::vector<double> nn = checker.reference_nn();
    std::vector<std::size_t> far_apart;
    for (std::size_t i = 0; i < nn.size(); ++i) {
        if (nn[i] < checker.nn_cap() || cap <= checker.nn_cap())
            nn[i] = std::min(nn[i], cap);
        else
            far_apart.push_back(i);
    }
    if (!far_apart.empty()) {
        const Neighbours wider(ref.points, cap);
        for (std::size_t i : far_apart) nn[i] = wider.nearest(i);
    }
    for (double& d : nn)
        if (d >= cap) d = 4 * spacing;
    nn_histogram = histogram(nn, spacing, Fidelity{}.histogram_bin);
    // Boundary elements are never copied, and their NN is measured from one side only.
    std::vector<double> copied;
    for (int c : reference.candidates) copied.push_back(nn[static_cast<std::size_t>(c)]);
    if (!copied.empty() && spacing > 0) copied_nn_median = median(copied) / spacing;
    // Inner: two rings in from the reference's edge, like the inner motifs from the panel's:
    // no other boundary element within the clearance (found from the boundary's few).
    const Neighbours within(ref.points, checker.interior_clearance());
    std::vector<bool> near_edge(ref.points.size(), false);
    for (std::size_t j = 0; j < ref.points.size(); ++j)
        if (reference.connectivity.boundary[j])
            within.each(j, [&](std::size_t k) { near_edge[k] = true; });
    std::vector<double> inner;
    for (int c : reference.candidates)
        if (!near_edge[static_cast<std::size_t>(c)])
            inner.push_back(nn[static_cast<std::size_t>(c)]);
    inner_nn_median = !inner.empty() && spacing > 0 ? median(inner) / spacing : copied_nn_median;
    // Within the checker's reach, each pair once: the crowding rule's limit (the fullest
    // interior ring) and the same-symbol share.
    const Neighbours near(ref.points, checker.reach());
    std::vector<int> neighbours(ref.points.size(), 0);
    long pairs = 0, alike = 0;
    for (std::size_t i = 0; i < ref.points.size(); ++i)
        near.each(i, [&](std::size_t j) {
            if (j <= i) return;
            ++neighbours[i];
            ++neighbours[j];
            ++pairs;
            alike += reference.symbol[i] == reference.symbol[j];
        });
    for (int c : reference.candidates)
        most_neighbours = std::max(most_neighbours, neighbours[static_cast<std::size_t>(c)]);
    same_symbol_share = pairs > 0 ? static_cast<double>(alike) / static_cast<double>(pairs) : 0.0;
    symbol_mix = mix(ref);
    // A lattice's own share is its sites' per cell: the reference's count depends on where its
    // edge cuts the lattice (a 3-colour rectangle of 121 holds 44, 39 and 38).
    if (const Lattice* lattice = lattice_of(reference)) {
        symbol_mix.clear();
        for (const Lattice::Site& site : lattice->sites)
            symbol_mix[reference.symbols[static_cast<std::size_t>(site.symbol)]] +=
                1.0 / static_cast<double>(lattice->sites.size());
    }
    // Likewise its same-symbol share: each site's neighbours within reach on the lattice, once
    // per cell (a stripe reference cut after a stripe of the rarer symbol has more pairs alike).
    if (const Lattice* lattice = lattice_of(reference)) {
        const double reach = checker.reach();
        const long span = static_cast<long>(std::ceil(
                              reach / std::min(lattice->t1.length(), lattice->t2.length()))) +
                          2;
        long close = 0, same = 0;
        for (int a = 0; a < static_cast<int>(lattice->sites.size()); ++a)
            for (int b = 0; b < static_cast<int>(lattice->sites.size()); ++b)
                for (long i = -span; i <= span; ++i)
                    for (long j = -span; j <= span; ++j) {
                        const double d = distance(lattice->point({0, 0}, a, 0, 0),
                                                  lattice->point({0, 0}, b, i, j));
                        if (d <= 0.5 * lattice->spacing || d > reach) continue;
                        ++close;
                        same += lattice->sites[static_cast<std::size_t>(a)].symbol ==
                                lattice->sites[static_cast<std::size_t>(b)].symbol;
                    }
        if (close > 0) same_symbol_share = static_cast<double>(same) / static_cast<double>(close);
    }
}

const ReferenceProfile& profile_of(const ReferenceData& reference) {
    std::call_once(reference.profile_once, [&] {
        reference.profile = std::make_shared<const ReferenceProfile>(reference);
    });
    return *reference.profile;
}

Fidelity measure_fidelity(const ReferenceData& reference, const std::vector<Motif>& motifs,
                          const Panel& panel, double largest_hole) {
    Fidelity f;
    const ReferenceProfile& profile = profile_of(reference);
    const RingChecker& checker = profile.checker;
    Site got;
    for (const Motif& m : motifs) {
        got.points.push_back(m.position);
        got.symbols.push_back(m.symbol);
    }
    // The unit is measured on the reference's points, as an author (or a checker) would.
    const double spacing = checker.spacing();
    // NN distances are searched within 2.1 NN and beyond reported as 4: the histogram's last
    // bin (from 2 up) holds them anyway.
    std::vector<double> got_nn = nearest(got, 2.1 * spacing);
    for (double& d : got_nn)
        if (d >= 2.1 * spacing) d = 4 * spacing;
    f.spacing = spacing;
    f.nn_median = got.points.size() > 1 ? median(got_nn) / spacing : 0.0;
    f.reference_nn_median = profile.copied_nn_median;
    f.reference_nn_median_inner = profile.inner_nn_median;
    std::vector<double> inner_nn;
    for (std::size_t i = 0; i < got.points.size(); ++i)
        if (panel.clearance(got.points[i]) >= checker.interior_clearance())
            inner_nn.push_back(got_nn[i]);
    f.nn_median_inner = inner_nn.empty() ? f.nn_median : median(inner_nn) / spacing;
    f.reference_nn_histogram = profile.nn_histogram;
    f.nn_histogram = got.points.size() > 1 ? histogram(got_nn, spacing, f.histogram_bin)
                                           : std::vector<double>(21, 0.0);
    f.reference_symbol_mix = profile.symbol_mix;
    f.symbol_mix = mix(got);
    f.reference_same_symbol_share = profile.same_symbol_share;
    f.same_symbol_share = same_share(got, checker.reach());

    // Defects: interior motifs whose ring matches no full reference ring of their symbol.
    std::vector<int> symbols;
    for (const Motif& m : motifs) symbols.push_back(reference.symbol_id(m.symbol));
    const std::vector<bool> good = checker.good(got.points, symbols);
    for (std::size_t i = 0; i < got.points.size(); ++i) {
        if (panel.clearance(got.points[i]) < checker.interior_clearance()) continue;
        ++f.interior;
        f.defects += !good[i];
    }
    f.defect_share =
        f.interior > 0 ? static_cast<double>(f.defects) / static_cast<double>(f.interior) : 0.0;
    f.largest_hole = largest_hole / spacing;
    return f;
}

}  // namespace acanthus::growth::detail

namespace acanthus::growth {

std::string fidelity_json(const SynthesisResult& result) {
    using Json = nlohmann::ordered_json;
    const Fidelity& f = result.fidelity;
    Json symbols = Json::object();
    for (const auto& [name, share] : f.reference_symbol_mix)
        symbols[name] = Json{{"result", f.symbol_mix.count(name) ? f.symbol_mix.at(name) : 0.0},
                             {"reference", share}};
    for (const auto& [name, share] : f.symbol_mix)
        if (!symbols.contains(name)) symbols[name] = Json{{"result", share}, {"reference", 0.0}};
    Json out = Json::object();
    out["motifs"] = result.motifs.size();
    out["restarts"] = result.stats.restarts;
    out["exchanges"] = result.stats.exchanges;
    out["spacing"] = f.spacing;
    out["nn_median"] = f.nn_median;
    out["nn_median_reference"] = f.reference_nn_median;
    out["nn_median_inner"] = f.nn_median_inner;
    out["nn_median_reference_inner"] = f.reference_nn_median_inner;
    out["nn_histogram"] = Json{{"bin", f.histogram_bin},
                               {"result", f.nn_histogram},
                               {"reference", f.reference_nn_histogram}};
    out["symbols"] = std::move(symbols);
    out["same_symbol_neighbours"] =
        Json{{"result", f.same_symbol_share}, {"reference", f.reference_same_symbol_share}};
    out["defects"] =
        Json{{"interior", f.interior}, {"count", f.defects}, {"share", f.defect_share}};
    out["largest_hole"] = f.largest_hole;
    out["lattice"] = Json{{"sites", result.stats.lattice_sites},
                          {"completed", result.stats.completed},
                          {"repaired", result.stats.repaired}};
    out["near_regular"] =
        Json{{"ring_order", result.stats.ring_order}, {"near_regular", result.stats.near_regular},
             {"honeycomb", result.stats.honeycomb},   {"jitter", result.stats.jitter},
             {"fitted", result.stats.fitted},         {"jitter_scale", result.stats.jitter_scale},
             {"rescaled", result.stats.rescaled}};
    return out.dump();
}

}  // namespace acanthus::growth
