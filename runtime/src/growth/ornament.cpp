#include "growth/ornament.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "proxy/overlap.hpp"

namespace acanthus::detail {

Ornament::Ornament(const Region& region, double tolerance)
    : region_(region), tolerance_(tolerance) {}

Element& Ornament::add(std::unique_ptr<Element> e) {
    const int id = static_cast<int>(elements_.size());
    e->id = id;
    for (std::size_t k = 0; k < e->proxy_count(); ++k)
        index_.insert(id, static_cast<int>(k), e->proxy(k).bounds());
    elements_.push_back(std::move(e));
    return *elements_.back();
}

namespace {
Rect bounds_of(const Element& e) {
    Rect b{1e300, 1e300, -1e300, -1e300};
    for (std::size_t k = 0; k < e.proxy_count(); ++k) {
        const Rect p = e.proxy(k).bounds();
        b = {std::min(b.x0, p.x0), std::min(b.y0, p.y0), std::max(b.x1, p.x1),
             std::max(b.y1, p.y1)};
    }
    return b;
}
}  // namespace

int Ornament::Zone::count(int i0, int j0, int i1, int j1) const {
    i0 = std::max(i0, 0);
    j0 = std::max(j0, 0);
    i1 = std::min(i1, columns - 1);
    j1 = std::min(j1, rows - 1);
    if (i0 > i1 || j0 > j1) return 0;
    const int w = columns + 1;
    auto at = [&](int i, int j) { return sums[static_cast<std::size_t>(j * w + i)]; };
    return at(i1 + 1, j1 + 1) - at(i0, j1 + 1) - at(i1 + 1, j0) + at(i0, j0);
}

// Cell ranges of a box, widened by a cell (floating-point slack at the cells' edges).
bool Ornament::Zone::covers(const Rect& b) const {
    if (sums.empty() || !(b.x0 <= b.x1 && b.y0 <= b.y1)) return false;
    const double i0 = std::floor((b.x0 - origin.x) / cell) - 1,
                 i1 = std::floor((b.x1 - origin.x) / cell) + 1,
                 j0 = std::floor((b.y0 - origin.y) / cell) - 1,
                 j1 = std::floor((b.y1 - origin.y) / cell) + 1;
    if (i0 < 0 || j0 < 0 || i1 >= columns || j1 >= rows) return false;
    const int n = count(static_cast<int>(i0), static_cast<int>(j0), static_cast<int>(i1),
                        static_cast<int>(j1));
    return n == static_cast<int>((i1 - i0 + 1) * (j1 - j0 + 1));
}

bool Ornament::Zone::meets(const Rect& b) const {
    if (sums.empty() || !(b.x0 <= b.x1 && b.y0 <= b.y1)) return true;
    const double lo = -1e9, hi = 1e9;  // (clamped before the conversion to int)
    auto cell_of = [&](double v, double o) {
        return static_cast<int>(std::clamp(std::floor((v - o) / cell), lo, hi));
    };
    return count(cell_of(b.x0, origin.x) - 1, cell_of(b.y0, origin.y) - 1,
                 cell_of(b.x1, origin.x) + 1, cell_of(b.y1, origin.y) + 1) > 0;
}

void Ornament::set_near_zone(Point origin, double cell, int columns,
                             const std::vector<bool>& cells) {
    cover({-1e300, -1e300, 1e300, 1e300});  // the buckets go with the zone
    zone_ = Zone{};
    buckets_.clear();
    buckets_w_ = buckets_h_ = 0;
    if (columns <= 0 || cells.empty() || !(cell > 0)) return;
    const int rows = static_cast<int>(cells.size() / static_cast<std::size_t>(columns));
    zone_.origin = origin;
    zone_.cell = cell;
    zone_.columns = columns;
    zone_.rows = rows;
    const int w = columns + 1;
    zone_.sums.assign(static_cast<std::size_t>(w) * (rows + 1), 0);
    buckets_w_ = (columns + kBucketCells - 1) / kBucketCells;
    buckets_h_ = (rows + kBucketCells - 1) / kBucketCells;
    buckets_.assign(static_cast<std::size_t>(buckets_w_) * buckets_h_, {});
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const auto at = [&](int x, int y) -> int& {
                return zone_.sums[static_cast<std::size_t>(y * w + x)];
            };
            at(i + 1, j + 1) = at(i, j + 1) + at(i + 1, j) - at(i, j) +
                               (cells[static_cast<std::size_t>(j * columns + i)] ? 1 : 0);
        }
}

void Ornament::buckets_of(const Rect& box, int& i0, int& j0, int& i1, int& j1) const {
    // Monotone in each coordinate: boxes that meet have bucket ranges that meet.
    const double side = zone_.cell * kBucketCells;
    auto at = [&](double v, double o, int n) {
        return static_cast<int>(std::clamp(std::floor((v - o) / side), 0.0, n - 1.0));
    };
    i0 = at(box.x0, zone_.origin.x, buckets_w_);
    i1 = at(box.x1, zone_.origin.x, buckets_w_);
    j0 = at(box.y0, zone_.origin.y, buckets_h_);
    j1 = at(box.y1, zone_.origin.y, buckets_h_);
}

void Ornament::cover(const Rect& box) const {
    if (deferred_ == 0 || zone_.covers(box)) return;
    int i0 = 0, j0 = 0, i1 = buckets_w_ - 1, j1 = buckets_h_ - 1;
    if (box.x0 <= box.x1 && box.y0 <= box.y1) buckets_of(box, i0, j0, i1, j1);
    std::vector<std::pair<SpatialIndex::Entry, Rect>> entries;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            std::vector<int>& bucket = buckets_[static_cast<std::size_t>(j * buckets_w_ + i)];
            for (int id : bucket) {
                if (!waiting_[static_cast<std::size_t>(id)]) continue;  // in another bucket too
                waiting_[static_cast<std::size_t>(id)] = 0;
                --deferred_;
                const Element& e = at(id);
                for (std::size_t k = 0; k < e.proxy_count(); ++k)
                    entries.push_back({{id, static_cast<int>(k)}, e.proxy(k).bounds()});
            }
            std::vector<int>().swap(bucket);
        }
    if (!entries.empty()) index_.insert_all(entries);
}

std::vector<Element*> Ornament::add_all(std::vector<std::unique_ptr<Element>> elements,
                                        std::size_t deferrable_from, std::vector<Rect>* bounds,
                                        const std::vector<std::uint8_t>* far) {
    std::vector<std::pair<SpatialIndex::Entry, Rect>> entries;
    if (bounds) {
        bounds->clear();
        if (deferrable_from < elements.size()) bounds->reserve(elements.size() - deferrable_from);
    }
    const bool zoned = !zone_.sums.empty() && !buckets_.empty();
    for (std::size_t n = 0; n < elements.size(); ++n) {
        const int id = static_cast<int>(elements_.size() + n);
        if (n >= deferrable_from && (zoned || bounds)) {
            const Rect b = bounds_of(*elements[n]);
            if (bounds) bounds->push_back(b);
            // (A valid box: meets() takes any other as meeting.)
            if (zoned && ((far && (*far)[n - deferrable_from]) || !zone_.meets(b))) {
                int i0, j0, i1, j1;
                buckets_of(b, i0, j0, i1, j1);
                for (int j = j0; j <= j1; ++j)
                    for (int i = i0; i <= i1; ++i)
                        buckets_[static_cast<std::size_t>(j * buckets_w_ + i)].push_back(id);
                if (waiting_.size() <= static_cast<std::size_t>(id))
                    waiting_.resize(static_cast<std::size_t>(id) + 1, 0);
                waiting_[static_cast<std::size_t>(id)] = 1;
                ++deferred_;
                continue;
            }
        }
        for (std::size_t k = 0; k < elements[n]->proxy_count(); ++k)
            entries.push_back({{id, static_cast<int>(k)}, elements[n]->proxy(k).bounds()});
    }
    index_.insert_all(entries);
    std::vector<Element*> added;
    added.reserve(elements.size());
    for (auto& e : elements) {
        e->id = static_cast<int>(elements_.size());
        added.push_back(e.get());
        elements_.push_back(std::move(e));
    }
    return added;
}

std::vector<const Element*> Ornament::view() const {
    std::vector<const Element*> out;
    out.reserve(elements_.size());
    for (const auto& e : elements_) out.push_back(e.get());
    return out;
}

std::pair<Element*, double> Ornament::nearest(Point p, double hint) const {
    double covered = 0;
    const auto hits = nearest_within(p, hint, &covered, 0, 0);
    if (hits.empty()) return {nullptr, std::numeric_limits<double>::infinity()};
    return hits.front();
}

std::vector<std::pair<Element*, double>> Ornament::nearest_within(Point p, double hint,
                                                                  double* covered, double likely,
                                                                  double slack) const {
    *covered = 0;
    if (elements_.empty() || !p.finite()) return {};
    // Any proxy nearer than the best one found within r has bounds within r too, so the first
    // radius that holds a proxy at most r away decides. (The index's k-nearest query costs far
    // more per call on large trees than these box queries.)
    const Rect b = region_.bounds();
    const double size = std::max(b.width(), b.height());
    const double reach =
        size + acanthus::distance(p, b.center()) + 1;  // beyond this, every bound is in
    double r = hint > 0 ? hint : size / 256;
    for (;;) {
        auto hits = within(p, r, slack);
        if (!hits.empty()) {
            *covered = r;
            return hits;
        }
        if (r > reach) break;
        r = likely > r ? std::min(4 * r, likely) : 4 * r;
    }
    // Elements far outside the region: the general search.
    cover({-1e300, -1e300, 1e300, 1e300});
    const auto hit = index_.nearest_entry(p, [&](detail::SpatialIndex::Entry en) {
        return distance_to(at(en.element).proxy(static_cast<std::size_t>(en.proxy)), p);
    });
    if (!hit) return {};
    return {{&at(hit->entry.element), hit->distance}};
}

std::vector<std::pair<Element*, double>> Ornament::within(Point p, double radius,
                                                          double slack) const {
    cover({p.x - radius, p.y - radius, p.x + radius, p.y + radius});
    // Entries nearest bounds first: once an element is known within `best`, an entry whose
    // bounds are farther than best + slack cannot be wanted (a proxy is never nearer than its
    // bounds), and is not measured.
    const auto hits = index_.within_by_distance(p, radius);
    std::vector<std::pair<Element*, double>> out;
    double best = INFINITY;
    for (const auto& hit : hits) {
        const double keep = std::min(radius, best + slack);
        if (hit.distance > keep) break;
        // Exact up to `keep`; beyond it the element is dropped below anyway.
        const double d = distance_to(
            at(hit.entry.element).proxy(static_cast<std::size_t>(hit.entry.proxy)), p, keep);
        if (!(d <= keep)) continue;
        best = std::min(best, d);
        out.emplace_back(&at(hit.entry.element), d);
    }
    const double keep = std::min(radius, best + slack);
    std::erase_if(out, [&](const auto& x) { return !(x.second <= keep); });
    // One distance per element: the nearest of its proxies.
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second < b.second : a.first->id < b.first->id;
    });
    std::vector<std::pair<Element*, double>> unique;
    unique.reserve(out.size());
    std::vector<bool> seen;
    for (const auto& x : out) {
        const auto id = static_cast<std::size_t>(x.first->id);
        if (id >= seen.size()) seen.resize(id + 1, false);
        if (seen[id]) continue;
        seen[id] = true;
        unique.push_back(x);
    }
    return unique;
}

bool Ornament::intersects(const Proxy& p) const {
    if (!p.is_set() || !p.finite())
        throw std::invalid_argument(std::string("intersection(): a ") +
                                    std::string(to_string(p.kind())) +
                                    " proxy that is not set or not finite");
    if (leaves_region(p, region_, tolerance_)) return true;
    cover(p.bounds());
    // Whether any does: the order the entries are tested in does not matter.
    return index_.any_of(p.bounds(), [&](SpatialIndex::Entry en) {
        return overlaps(p, at(en.element).proxy(static_cast<std::size_t>(en.proxy)), tolerance_);
    });
}

bool Ornament::overlaps_any(const Proxy& p,
                            const std::function<bool(const Element&)>& which) const {
    cover(p.bounds());
    return index_.any_of(p.bounds(), [&](SpatialIndex::Entry en) {
        const Element& e = at(en.element);
        return which(e) && overlaps(p, e.proxy(static_cast<std::size_t>(en.proxy)), tolerance_);
    });
}

void Ornament::for_each_meeting(const Rect& box,
                                const std::function<void(const Element&)>& visit) const {
    cover(box);
    for (const auto& en : index_.query(box)) visit(at(en.element));
}

bool Ornament::intersects(const Element& e) const {
    for (std::size_t k = 0; k < e.proxy_count(); ++k)
        if (intersects(e.proxy(k))) return true;
    return false;
}

}  // namespace acanthus::detail
