#include "lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>

#include "point_grid.hpp"
#include "reference.hpp"

namespace acanthus::growth::detail {
namespace {

// Translations are looked for this far from the central element (a stripe of period 5, a
// rosette cell of three sites fit well within).
constexpr double kReach = 6.0;
// Of the elements a translation moves onto another element or into the reference's triangles,
// at most this share may be contradicted (an element of another kind, or none).
constexpr double kContradictions = 0.02;
// Elements checked per translation: those nearest the central element (bounds the cost of a
// huge reference; a small one is checked whole).
constexpr std::size_t kSample = 4000;
constexpr int kMaxSites = 24;
// Candidates kept per site, the nearest the central element: on a lattice they all have one
// ring, and a huge reference need not be matched whole at every seed.
constexpr std::size_t kSiteCandidates = 64;
// A lattice found on positions and symbols alone keeps its elements this close to their sites
// (RMS, in spacings): rounded coordinates are far within, a jitter of a tenth is not.
constexpr double kExact = 0.03;

// The nearest of `points` to q within r (r at most the grid's cell), the lowest index among
// equals; -1 when none.
int nearest_within(const PointGrid& grid, const std::vector<Point>& points, Point q, double r) {
    int best = -1;
    double best_d = r;
    grid.around(q, [&](int i) {
        const double d = distance(points[static_cast<std::size_t>(i)], q);
        if (d < best_d || (d == best_d && best >= 0 && i < best)) {
            best_d = d;
            best = i;
        }
    });
    return best;
}

// The kept triangles, for "is this place inside the reference" (an empty place inside a
// honeycomb's hexagon is one; beyond the reference's edge is not).
class TriangleGrid {
  public:
    TriangleGrid(const std::vector<Point>& points, const std::vector<std::array<int, 3>>& triangles,
                 double cell)
        : points_(points), triangles_(triangles), cell_(cell) {
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
            for (int v : triangles[t]) {
                x0 = std::min(x0, points[v].x), x1 = std::max(x1, points[v].x);
                y0 = std::min(y0, points[v].y), y1 = std::max(y1, points[v].y);
            }
            for (long i = cx(x0); i <= cx(x1); ++i)
                for (long j = cx(y0); j <= cx(y1); ++j) grid_[key(i, j)].push_back(t);
        }
    }
    bool inside(Point q) const {
        auto it = grid_.find(key(cx(q.x), cx(q.y)));
        if (it == grid_.end()) return false;
        for (std::size_t t : it->second) {
            const auto& v = triangles_[t];
            double a = (points_[v[1]] - points_[v[0]]).cross(q - points_[v[0]]);
            double b = (points_[v[2]] - points_[v[1]]).cross(q - points_[v[1]]);
            double c = (points_[v[0]] - points_[v[2]]).cross(q - points_[v[2]]);
            if ((a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0)) return true;
        }
        return false;
    }

  private:
    long cx(double v) const { return static_cast<long>(std::floor(v / cell_)); }
    static std::int64_t key(long x, long y) {
        return (static_cast<std::int64_t>(x) << 32) ^ (static_cast<std::int64_t>(y) & 0xffffffff);
    }
    const std::vector<Point>& points_;
    const std::vector<std::array<int, 3>>& triangles_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> grid_;
};

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace

Point Lattice::point(Point origin, int site, long i, long j) const {
    return origin + sites[static_cast<std::size_t>(site)].offset + t1 * static_cast<double>(i) +
           t2 * static_cast<double>(j);
}

Lattice::Spot Lattice::nearest(Point origin, Point p) const {
    const double det = t1.cross(t2);
    Spot best;
    best.residual = INFINITY;
    for (int s = 0; s < static_cast<int>(sites.size()); ++s) {
        Vector d = p - (origin + sites[static_cast<std::size_t>(s)].offset);
        // Cell coordinates: d = u t1 + v t2.
        double u = d.cross(t2) / det, v = t1.cross(d) / det;
        const long i0 = std::lround(u), j0 = std::lround(v);
        for (long i = i0 - 1; i <= i0 + 1; ++i)
            for (long j = j0 - 1; j <= j0 + 1; ++j) {
                Point at = point(origin, s, i, j);
                double r = distance(at, p);
                if (r < best.residual) best = {s, i, j, at, r};
            }
    }
    return best;
}

namespace {

// Shortest first, then the one pointing nearer +x: a deterministic order of lattice vectors.
bool shorter(Vector a, Vector b) {
    const double la = a.length(), lb = b.length();
    if (la != lb) return la < lb;
    return a.x != b.x ? a.x > b.x : a.y > b.y;
}

// Lagrange's reduction: the two shortest vectors spanning the lattice of (a, b), |a| <= |b|.
void reduce(Vector& a, Vector& b) {
    if (shorter(b, a)) std::swap(a, b);
    for (int guard = 0; guard < 64; ++guard) {
        const double k = std::round(a.dot(b) / a.dot(a));
        if (k == 0) break;
        b -= a * k;
        if (!shorter(b, a)) break;
        std::swap(a, b);
    }
}

}  // namespace

std::optional<Lattice> detect_lattice(const ReferenceData& reference) {
    const auto& elements = reference.elements;
    const std::size_t n = elements.size();
    if (reference.candidates.empty() || n < 4) return std::nullopt;
    std::vector<Point> points;
    for (const auto& e : elements) points.push_back(e.position);

    double spacing = 0;
    {
        std::vector<double> nn;
        for (std::size_t i = 0; i < n; ++i) {
            double best = INFINITY;
            for (const RingSlot& s : reference.rings[i]) best = std::min(best, s.offset.length());
            if (std::isfinite(best)) nn.push_back(best);
        }
        spacing = median(nn);
    }
    if (!(spacing > 0)) return std::nullopt;
    const double tol = 0.15 * spacing;
    PointGrid grid(points, spacing);
    TriangleGrid inside(points, reference.connectivity.triangles, 2 * spacing);

    // Alike in everything drawn: symbol, label, turn and size.
    auto same_kind = [&](int a, int b) {
        const ReferenceElement& x = elements[a];
        const ReferenceElement& y = elements[b];
        if (reference.symbol[a] != reference.symbol[b] || x.label != y.label) return false;
        double turn = std::remainder(x.angle - y.angle, 2 * M_PI);
        return std::abs(turn) < 0.05 &&
               std::abs(x.size - y.size) <= 0.05 * std::max(x.size, y.size);
    };
    // Alike in what growth places by: symbol and label (motifs turned or sized at random).
    auto same_symbol = [&](int a, int b) {
        return reference.symbol[a] == reference.symbol[b] && elements[a].label == elements[b].label;
    };
    auto any = [](int, int) { return true; };

    // The interior element nearest the centroid anchors the search.
    Vector sum{0, 0};
    for (Point p : points) sum += p - Point{0, 0};
    const Point centroid = Point{0, 0} + sum / static_cast<double>(n);
    int anchor = reference.candidates.front();
    for (int c : reference.candidates)
        if (distance(points[c], centroid) < distance(points[anchor], centroid)) anchor = c;

    std::vector<int> order(n);  // by distance from the anchor
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> from_anchor(n);  // once each, not twice per comparison
    for (std::size_t i = 0; i < n; ++i) from_anchor[i] = distance(points[i], points[anchor]);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return from_anchor[a] < from_anchor[b]; });
    const std::vector<int> sample(order.begin(),
                                  order.begin() + static_cast<long>(std::min(n, kSample)));

    // A translation that holds for `alike`, refined as the mean offset of the pairs it maps.
    auto holds = [&](Vector t, Vector& refined, auto&& alike) {
        long support = 0, contra = 0;
        Vector total{0, 0};
        for (int i : sample) {
            Point q = points[i] + t;
            int j = nearest_within(grid, points, q, tol);
            if (j >= 0 && alike(i, j)) {
                ++support;
                total += points[j] - points[i];
            } else if (j >= 0 || inside.inside(q)) {
                // Past this many it cannot hold, whatever the rest says.
                if (static_cast<double>(++contra) >
                    kContradictions * static_cast<double>(sample.size()))
                    return false;
            }
        }
        if (support < 6 || static_cast<double>(support) < 0.2 * static_cast<double>(sample.size()))
            return false;
        if (static_cast<double>(contra) > kContradictions * static_cast<double>(support + contra))
            return false;
        refined = total / static_cast<double>(support);
        return true;
    };
    // The two shortest independent offsets from the anchor to an element `alike` it that hold.
    auto basis = [&](Vector& t1, Vector& t2, auto&& alike) {
        bool have1 = false;
        for (int j : sample) {
            if (j == anchor || distance(points[j], points[anchor]) > kReach * spacing ||
                !alike(anchor, j))
                continue;  // the sample is by distance, ties by index
            Vector t = points[j] - points[anchor], refined;
            if (have1 && std::abs(t1.cross(t)) < 0.2 * t1.length() * t.length())
                continue;  // parallel to t1: a multiple of it, or a worse one
            if (!holds(t, refined, alike)) continue;
            if (!have1) {
                t1 = refined;
                have1 = true;
            } else {
                t2 = refined;
                return true;
            }
        }
        return false;
    };

    Lattice lattice;
    lattice.spacing = spacing;
    lattice.tolerance = tol;
    bool by_symbol = false;
    if (!basis(lattice.t1, lattice.t2, same_kind)) {
        // Motifs turned or sized at random repeat in position and symbol only: the lattice of
        // the positions, then its smallest sub-lattice under which the symbols repeat (a
        // checker's, a 3-colour's, a stripe's period).
        Vector p1, p2;
        if (!basis(p1, p2, any)) return std::nullopt;
        bool found = false;
        for (int index = 1; index <= kMaxSites && !found; ++index)
            for (int a = 1; a <= index && !found; ++a) {
                if (index % a != 0) continue;
                const int d = index / a;
                for (int b = 0; b < a && !found; ++b) {
                    Vector v1 = p1 * static_cast<double>(a),
                           v2 = p1 * static_cast<double>(b) + p2 * static_cast<double>(d), r1, r2;
                    reduce(v1, v2);
                    if (v1.length() > 2 * kReach * spacing) continue;
                    if (!holds(v1, r1, same_symbol) || !holds(v2, r2, same_symbol)) continue;
                    lattice.t1 = r1;
                    lattice.t2 = r2;
                    found = true;
                }
            }
        if (!found) return std::nullopt;
        by_symbol = true;
    }
    if (lattice.t1.cross(lattice.t2) < 0) lattice.t2 = -lattice.t2;
    auto site_kind = [&](int a, int b) { return by_symbol ? same_symbol(a, b) : same_kind(a, b); };

    // Sites: every element reduced into the cell around the anchor, grouped within the tolerance.
    const double det = lattice.t1.cross(lattice.t2);
    std::vector<Vector> unwrapped_sum;
    std::vector<Vector> unwrapped;  // per element, its offset in the cell
    lattice.site_of.assign(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        Vector d = points[i] - points[anchor];
        double u = d.cross(lattice.t2) / det, v = lattice.t1.cross(d) / det;
        Vector r = d - lattice.t1 * std::floor(u + 0.5) - lattice.t2 * std::floor(v + 0.5);
        int found = -1;
        Vector at;
        for (std::size_t s = 0; s < lattice.sites.size() && found < 0; ++s) {
            const Lattice::Site& site = lattice.sites[s];
            Vector first = points[site.elements.front()] - points[anchor];
            Vector rep = first - lattice.t1 * std::floor(first.cross(lattice.t2) / det + 0.5) -
                         lattice.t2 * std::floor(lattice.t1.cross(first) / det + 0.5);
            for (int a = -1; a <= 1 && found < 0; ++a)
                for (int b = -1; b <= 1 && found < 0; ++b) {
                    Vector shifted = r + lattice.t1 * a + lattice.t2 * b;
                    if ((shifted - rep).length() >= tol) continue;
                    if (!site_kind(site.elements.front(), static_cast<int>(i)))
                        return std::nullopt;  // two kinds on one site: not a lattice
                    found = static_cast<int>(s);
                    at = shifted;
                }
        }
        if (found < 0) {
            if (static_cast<int>(lattice.sites.size()) == kMaxSites) return std::nullopt;
            found = static_cast<int>(lattice.sites.size());
            lattice.sites.push_back({});
            lattice.sites.back().symbol = reference.symbol[i];
            unwrapped_sum.push_back({0, 0});
            at = r;
        }
        lattice.sites[found].elements.push_back(static_cast<int>(i));
        unwrapped_sum[found] += at;
        unwrapped.push_back(at);
        lattice.site_of[i] = found;
    }
    for (int c : order)
        if (!reference.connectivity.boundary[c] &&
            lattice.sites[lattice.site_of[c]].candidates.size() < kSiteCandidates)
            lattice.sites[lattice.site_of[c]].candidates.push_back(c);
    for (Lattice::Site& site : lattice.sites)
        std::sort(site.candidates.begin(), site.candidates.end());
    for (std::size_t s = 0; s < lattice.sites.size(); ++s) {
        Lattice::Site& site = lattice.sites[s];
        if (site.candidates.empty()) return std::nullopt;  // a site no ring can be copied from
        site.offset = unwrapped_sum[s] / static_cast<double>(site.elements.size());
    }
    if (by_symbol) {
        // Found on positions alone, a jittered lattice would pass the tolerance too: it is
        // near-regular growth's (near_regular.hpp), not one to snap every motif onto.
        double squares = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const Vector off = unwrapped[i] - lattice.sites[lattice.site_of[i]].offset;
            squares += off.dot(off);
        }
        if (std::sqrt(squares / static_cast<double>(n)) > kExact * spacing) return std::nullopt;
    }
    // The anchor's site sits at the origin.
    const Vector shift = lattice.sites[lattice.site_of[anchor]].offset;
    for (Lattice::Site& site : lattice.sites) site.offset -= shift;
    return lattice;
}

const Lattice* lattice_of(const ReferenceData& reference) {
    std::call_once(reference.lattice_once, [&] {
        if (auto found = detect_lattice(reference))
            reference.lattice = std::make_shared<const Lattice>(std::move(*found));
    });
    return reference.lattice.get();
}

}  // namespace acanthus::growth::detail
