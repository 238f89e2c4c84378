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

std::vector<Element*> Ornament::add_all(std::vector<std::unique_ptr<Element>> elements) {
    std::vector<std::pair<SpatialIndex::Entry, Rect>> entries;
    for (std::size_t n = 0; n < elements.size(); ++n) {
        const int id = static_cast<int>(elements_.size() + n);
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
    const auto hits = nearest_within(p, hint, &covered);
    if (hits.empty()) return {nullptr, std::numeric_limits<double>::infinity()};
    return hits.front();
}

std::vector<std::pair<Element*, double>> Ornament::nearest_within(Point p, double hint,
                                                                  double* covered,
                                                                  double likely) const {
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
        auto hits = within(p, r);
        if (!hits.empty()) {
            *covered = r;
            return hits;
        }
        if (r > reach) break;
        r = likely > r ? std::min(4 * r, likely) : 4 * r;
    }
    // Elements far outside the region: the general search.
    const auto hit = index_.nearest_entry(p, [&](detail::SpatialIndex::Entry en) {
        return distance_to(at(en.element).proxy(static_cast<std::size_t>(en.proxy)), p);
    });
    if (!hit) return {};
    return {{&at(hit->entry.element), hit->distance}};
}

std::vector<std::pair<Element*, double>> Ornament::within(Point p, double radius) const {
    std::vector<std::pair<Element*, double>> out;
    // Entries come sorted by (element, proxy): one distance per element, over its near proxies
    // (a proxy whose bounds are farther than `radius` cannot be nearer than that).
    for (const auto& en : index_.within(p, radius)) {
        // Exact up to `radius`; beyond it the element is dropped below anyway.
        const double d =
            distance_to(at(en.element).proxy(static_cast<std::size_t>(en.proxy)), p, radius);
        if (!out.empty() && out.back().first->id == en.element) {
            out.back().second = std::min(out.back().second, d);
        } else {
            out.emplace_back(&at(en.element), d);
        }
    }
    std::erase_if(out, [&](const auto& x) { return !(x.second <= radius); });
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second < b.second : a.first->id < b.first->id;
    });
    return out;
}

bool Ornament::intersects(const Proxy& p) const {
    if (!p.is_set() || !p.finite())
        throw std::invalid_argument(std::string("intersection(): a ") +
                                    std::string(to_string(p.kind())) +
                                    " proxy that is not set or not finite");
    if (leaves_region(p, region_, tolerance_)) return true;
    for (const auto& en : index_.query(p.bounds())) {
        if (overlaps(p, at(en.element).proxy(static_cast<std::size_t>(en.proxy)), tolerance_))
            return true;
    }
    return false;
}

bool Ornament::overlaps_any(const Proxy& p,
                            const std::function<bool(const Element&)>& which) const {
    for (const auto& en : index_.query(p.bounds())) {
        const Element& e = at(en.element);
        if (which(e) && overlaps(p, e.proxy(static_cast<std::size_t>(en.proxy)), tolerance_))
            return true;
    }
    return false;
}

bool Ornament::intersects(const Element& e) const {
    for (std::size_t k = 0; k < e.proxy_count(); ++k)
        if (intersects(e.proxy(k))) return true;
    return false;
}

}  // namespace acanthus::detail
