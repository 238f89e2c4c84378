#include "fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <unordered_map>

namespace acanthus::growth::detail {
namespace {

// Points bucketed by cells of one reach, so each site's neighbours cost a few buckets.
class Neighbours {
  public:
    Neighbours(const std::vector<Point>& points, double reach) : points_(points), reach_(reach) {
        for (std::size_t i = 0; i < points.size(); ++i) grid_[key(points[i])].push_back(i);
    }
    // Indices within the reach of point i, other than i, in index order.
    std::vector<std::size_t> of(std::size_t i) const {
        std::vector<std::size_t> out;
        const auto [cx, cy] = cell(points_[i]);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                auto it = grid_.find(pack(cx + dx, cy + dy));
                if (it == grid_.end()) continue;
                for (std::size_t j : it->second)
                    if (j != i && distance(points_[i], points_[j]) < reach_) out.push_back(j);
            }
        std::sort(out.begin(), out.end());
        return out;
    }

  private:
    std::pair<long, long> cell(Point p) const {
        return {static_cast<long>(std::floor(p.x / reach_)),
                static_cast<long>(std::floor(p.y / reach_))};
    }
    static long long pack(long x, long y) {
        return (static_cast<long long>(x) << 32) ^ (y & 0xffffffffLL);
    }
    long long key(Point p) const {
        auto [x, y] = cell(p);
        return pack(x, y);
    }
    const std::vector<Point>& points_;
    double reach_;
    std::unordered_map<long long, std::vector<std::size_t>> grid_;  // looked up, never iterated
};

struct Site {
    std::vector<Point> points;
    std::vector<std::string> symbols;
};

// NN distances (within `cap`; a lone point counts as `cap`).
std::vector<double> nearest(const Site& s, double cap) {
    Neighbours n(s.points, cap);
    std::vector<double> out;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        double best = cap;
        for (std::size_t j : n.of(i)) best = std::min(best, distance(s.points[i], s.points[j]));
        out.push_back(best);
    }
    return out;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

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
        for (std::size_t j : n.of(i))
            if (j > i) {
                ++close;
                same += s.symbols[i] == s.symbols[j];
            }
    return close > 0 ? static_cast<double>(same) / static_cast<double>(close) : 0.0;
}

struct Ring {
    std::vector<Vector> offsets;
    std::vector<std::string> symbols;
};

std::vector<Ring> rings(const Site& s, double reach) {
    Neighbours n(s.points, reach);
    std::vector<Ring> out(s.points.size());
    for (std::size_t i = 0; i < s.points.size(); ++i)
        for (std::size_t j : n.of(i)) {
            out[i].offsets.push_back(s.points[j] - s.points[i]);
            out[i].symbols.push_back(s.symbols[j]);
        }
    return out;
}

// Every neighbour of `a` pairs with a distinct one of `b` of its symbol within `tolerance`.
bool same_ring(const Ring& a, const Ring& b, double tolerance) {
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

}  // namespace

Fidelity measure_fidelity(const ReferenceData& reference, const std::vector<Motif>& motifs,
                          const Panel& panel, double spacing, double largest_hole) {
    Fidelity f;
    Site ref, got;
    for (std::size_t i = 0; i < reference.elements.size(); ++i) {
        ref.points.push_back(reference.elements[i].position);
        ref.symbols.push_back(reference.elements[i].symbol);
    }
    for (const Motif& m : motifs) {
        got.points.push_back(m.position);
        got.symbols.push_back(m.symbol);
    }
    // NN distances beyond 4 NN are reported as 4: the histogram's last bin holds them anyway.
    const double cap = 4 * spacing;
    std::vector<double> ref_nn = nearest(ref, cap), got_nn = nearest(got, cap);
    // The unit is measured on the reference's points, as an author (or a checker) would.
    spacing = median(ref_nn);
    f.spacing = spacing;
    f.nn_median = got.points.size() > 1 ? median(got_nn) / spacing : 0.0;
    f.reference_nn_histogram = histogram(ref_nn, spacing, f.histogram_bin);
    f.nn_histogram = got.points.size() > 1 ? histogram(got_nn, spacing, f.histogram_bin)
                                           : std::vector<double>(21, 0.0);
    f.reference_symbol_mix = mix(ref);
    f.symbol_mix = mix(got);
    const double reach = 1.2 * spacing;
    f.reference_same_symbol_share = same_share(ref, reach);
    f.same_symbol_share = same_share(got, reach);

    // Defects: only the reference's fullest rings are what an interior motif may look like.
    std::vector<Ring> ref_rings = rings(ref, reach), got_rings = rings(got, reach);
    std::size_t full = 0;
    for (const Ring& r : ref_rings) full = std::max(full, r.offsets.size());
    long defects = 0;
    for (std::size_t i = 0; i < got.points.size(); ++i) {
        if (panel.clearance(got.points[i]) < 1.5 * spacing) continue;
        ++f.interior;
        bool matched = false;
        for (std::size_t k = 0; k < ref_rings.size() && !matched; ++k)
            matched = ref_rings[k].offsets.size() == full && ref.symbols[k] == got.symbols[i] &&
                      same_ring(got_rings[i], ref_rings[k], 0.15 * spacing);
        defects += !matched;
    }
    f.defect_share =
        f.interior > 0 ? static_cast<double>(defects) / static_cast<double>(f.interior) : 0.0;
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
    out["spacing"] = f.spacing;
    out["nn_median"] = f.nn_median;
    out["nn_histogram"] = Json{{"bin", f.histogram_bin},
                               {"result", f.nn_histogram},
                               {"reference", f.reference_nn_histogram}};
    out["symbols"] = std::move(symbols);
    out["same_symbol_neighbours"] =
        Json{{"result", f.same_symbol_share}, {"reference", f.reference_same_symbol_share}};
    out["defects"] = Json{{"interior", f.interior}, {"share", f.defect_share}};
    out["largest_hole"] = f.largest_hole;
    return out.dump();
}

}  // namespace acanthus::growth
