#include "growth/exclude_list.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <map>
#include <utility>

namespace acanthus::detail {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {
using BoostPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BoostBox = bg::model::box<BoostPoint>;
using Entry = std::pair<BoostPoint, int>;
}  // namespace

struct ExcludeList::Index {
    bgi::rtree<Entry, bgi::quadratic<16>> tree;
    std::map<int, Point> by_id;  // ordered, for points()
    int next_id = 0;
};

ExcludeList::ExcludeList() : index_(std::make_unique<Index>()) {}
ExcludeList::~ExcludeList() = default;

int ExcludeList::add(Point p) {
    const int id = index_->next_id++;
    index_->tree.insert({BoostPoint(p.x, p.y), id});
    index_->by_id.emplace(id, p);
    return id;
}

int ExcludeList::find_inside(const Circle& c) const {
    if (index_->tree.empty() || !(c.radius > 0)) return -1;
    // Any point inside will do (the search only caches the answer, and asks again when that
    // point is removed): the first one a box query meets, which costs less than the nearest.
    const double r = c.radius;
    // (widened by far more than the rounding of its corners)
    const double half = r * (1 + 1e-9) + 1e-9 * (std::abs(c.center.x) + std::abs(c.center.y));
    const BoostBox box(BoostPoint(c.center.x - half, c.center.y - half),
                       BoostPoint(c.center.x + half, c.center.y + half));
    const double r2 = r * r;
    const auto inside = [&](const Entry& e) {
        const Point q{bg::get<0>(e.first), bg::get<1>(e.first)};
        // The squared distance decides unless it is within rounding of r^2: then distance()
        // does, as it always did.
        const double dx = q.x - c.center.x, dy = q.y - c.center.y, d2 = dx * dx + dy * dy;
        if (d2 < r2 * (1 - 1e-9)) return true;
        if (d2 > r2 * (1 + 1e-9)) return false;
        return distance(q, c.center) < r;
    };
    const auto it = index_->tree.qbegin(bgi::intersects(box) && bgi::satisfies(inside));
    return it != index_->tree.qend() ? it->second : -1;
}

void ExcludeList::remove_within(Point p, double epsilon, std::vector<int>* removed) {
    if (index_->tree.empty() || !(epsilon >= 0)) return;
    const BoostBox box(BoostPoint(p.x - epsilon, p.y - epsilon),
                       BoostPoint(p.x + epsilon, p.y + epsilon));
    std::vector<Entry> hits;
    index_->tree.query(bgi::intersects(box), std::back_inserter(hits));
    for (const Entry& e : hits) {
        const Point q{bg::get<0>(e.first), bg::get<1>(e.first)};
        if (distance(q, p) > epsilon) continue;
        index_->tree.remove(e);
        index_->by_id.erase(e.second);
        if (removed) removed->push_back(e.second);
    }
}

void ExcludeList::clear() {
    index_->tree.clear();
    index_->by_id.clear();
    ++clears_;
}

std::size_t ExcludeList::size() const { return index_->by_id.size(); }

std::vector<Point> ExcludeList::points() const {
    std::vector<Point> out;
    out.reserve(index_->by_id.size());
    for (const auto& [id, p] : index_->by_id) out.push_back(p);
    return out;
}

}  // namespace acanthus::detail
