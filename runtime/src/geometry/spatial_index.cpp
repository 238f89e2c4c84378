#include "geometry/spatial_index.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

namespace acanthus::detail {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {
using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BBox = bg::model::box<BPoint>;
using Value = std::pair<BBox, SpatialIndex::Entry>;

BBox to_box(Rect r) { return BBox(BPoint(r.x0, r.y0), BPoint(r.x1, r.y1)); }

std::vector<SpatialIndex::Entry> sorted_entries(const std::vector<Value>& values) {
    std::vector<SpatialIndex::Entry> out;
    out.reserve(values.size());
    for (const Value& v : values) out.push_back(v.second);
    std::sort(out.begin(), out.end());
    return out;
}
void check_bounds(SpatialIndex::Entry e, Rect bounds) {
    bool finite = std::isfinite(bounds.x0) && std::isfinite(bounds.y0) &&
                  std::isfinite(bounds.x1) && std::isfinite(bounds.y1);
    if (!finite || bounds.x0 > bounds.x1 || bounds.y0 > bounds.y1) {
        throw std::invalid_argument("spatial index: bad bounds for element " +
                                    std::to_string(e.element) + " proxy " +
                                    std::to_string(e.proxy));
    }
}
}  // namespace

struct SpatialIndex::Tree {
    bgi::rtree<Value, bgi::linear<16>> rtree;
};

SpatialIndex::SpatialIndex() : tree_(std::make_unique<Tree>()) {}

SpatialIndex::SpatialIndex(const std::vector<std::pair<Entry, Rect>>& entries) {
    std::vector<Value> values;
    values.reserve(entries.size());
    for (const auto& [entry, bounds] : entries) {
        check_bounds(entry, bounds);
        values.emplace_back(to_box(bounds), entry);
    }
    tree_ = std::make_unique<Tree>(Tree{bgi::rtree<Value, bgi::linear<16>>(values)});
}
SpatialIndex::SpatialIndex(SpatialIndex&&) noexcept = default;
SpatialIndex& SpatialIndex::operator=(SpatialIndex&&) noexcept = default;
SpatialIndex::~SpatialIndex() = default;

void SpatialIndex::insert(int element, int proxy, Rect bounds) {
    check_bounds(Entry{element, proxy}, bounds);
    tree_->rtree.insert(Value(to_box(bounds), Entry{element, proxy}));
}

void SpatialIndex::insert_all(const std::vector<std::pair<Entry, Rect>>& entries) {
    for (const auto& [entry, bounds] : entries) check_bounds(entry, bounds);
    // Below this many, one insertion at a time costs less than packing the whole tree again.
    constexpr std::size_t kPackFrom = 64;
    if (entries.size() < kPackFrom || entries.size() < tree_->rtree.size()) {
        for (const auto& [entry, bounds] : entries)
            tree_->rtree.insert(Value(to_box(bounds), entry));
        return;
    }
    std::vector<Value> values(tree_->rtree.begin(), tree_->rtree.end());
    values.reserve(values.size() + entries.size());
    for (const auto& [entry, bounds] : entries) values.emplace_back(to_box(bounds), entry);
    tree_->rtree = bgi::rtree<Value, bgi::linear<16>>(values);
}

void SpatialIndex::clear() { tree_->rtree.clear(); }

std::size_t SpatialIndex::size() const { return tree_->rtree.size(); }

std::vector<SpatialIndex::Entry> SpatialIndex::query(Rect box) const {
    std::vector<Value> found;
    tree_->rtree.query(bgi::intersects(to_box(box)), std::back_inserter(found));
    return sorted_entries(found);
}

bool SpatialIndex::any_of(Rect box, const std::function<bool(Entry)>& test) const {
    // One query with the test as its predicate (the query iterators are type-erased and cost
    // more): once an entry passes, the others are not tested.
    bool found = false;
    tree_->rtree.query(bgi::intersects(to_box(box)) && bgi::satisfies([&](const Value& v) {
                           if (!found && test(v.second)) found = true;
                           return false;
                       }),
                       boost::make_function_output_iterator([](const Value&) {}));
    return found;
}

std::vector<SpatialIndex::Entry> SpatialIndex::within(Point p, double radius) const {
    std::vector<Value> found;
    BPoint q(p.x, p.y);
    tree_->rtree.query(
        bgi::intersects(to_box({p.x - radius, p.y - radius, p.x + radius, p.y + radius})) &&
            bgi::satisfies([&](const Value& v) { return bg::distance(q, v.first) <= radius; }),
        std::back_inserter(found));
    return sorted_entries(found);
}

std::vector<SpatialIndex::Hit> SpatialIndex::within_by_distance(Point p, double radius) const {
    std::vector<Hit> out;
    BPoint q(p.x, p.y);
    tree_->rtree.query(
        bgi::intersects(to_box({p.x - radius, p.y - radius, p.x + radius, p.y + radius})),
        boost::iterators::make_function_output_iterator([&](const Value& v) {
            const double d = bg::distance(q, v.first);
            if (d <= radius) out.push_back({v.second, d});
        }));
    std::sort(out.begin(), out.end(), [](const Hit& a, const Hit& b) {
        return a.distance != b.distance ? a.distance < b.distance : a.entry < b.entry;
    });
    return out;
}

std::vector<SpatialIndex::Entry> SpatialIndex::nearest(Point p, std::size_t k) const {
    if (k == 0 || size() == 0) return {};
    BPoint q(p.x, p.y);
    // Take every entry tied with the k-th box distance, then order deterministically.
    std::vector<std::pair<double, Entry>> ranked;
    for (auto it = tree_->rtree.qbegin(bgi::nearest(q, static_cast<unsigned>(size())));
         it != tree_->rtree.qend(); ++it) {
        double d = bg::distance(q, it->first);
        if (ranked.size() >= k && d > ranked.back().first) break;
        ranked.emplace_back(d, it->second);
    }
    std::sort(ranked.begin(), ranked.end());
    if (ranked.size() > k) ranked.resize(k);
    std::vector<Entry> out;
    for (const auto& r : ranked) out.push_back(r.second);
    return out;
}

std::optional<SpatialIndex::Hit> SpatialIndex::nearest_entry(
    Point p, const std::function<double(Entry)>& distance) const {
    std::optional<Hit> best;
    if (size() == 0) return best;
    BPoint q(p.x, p.y);
    // Batches of the k nearest bounds, k growing fourfold, until one reaches past the best
    // exact distance: Boost's incremental query with k = size() costs O(size) per call. Each
    // batch is evaluated whole, so ties never depend on Boost's order.
    std::vector<Value> batch;
    for (std::size_t k = 16;; k *= 4) {
        batch.clear();
        tree_->rtree.query(bgi::nearest(q, static_cast<unsigned>(std::min(k, size()))),
                           std::back_inserter(batch));
        std::sort(batch.begin(), batch.end(), [&q](const Value& a, const Value& b) {
            const double da = bg::distance(q, a.first), db = bg::distance(q, b.first);
            return da < db || (da == db && a.second < b.second);
        });
        bool done = batch.size() < k;
        for (const Value& v : batch) {
            if (best && bg::distance(q, v.first) > best->distance) {
                done = true;
                break;
            }
            double d = distance(v.second);
            if (!std::isfinite(d)) continue;
            if (!best || d < best->distance || (d == best->distance && v.second < best->entry))
                best = Hit{v.second, d};
        }
        if (done || batch.size() >= size()) break;
    }
    return best;
}

}  // namespace acanthus::detail
