#include "growth/exclude_list.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
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
    const BoostPoint centre(c.center.x, c.center.y);
    // The nearest point decides: inside when it is closer than the radius.
    for (auto it = index_->tree.qbegin(bgi::nearest(centre, 1)); it != index_->tree.qend(); ++it) {
        const Point q{bg::get<0>(it->first), bg::get<1>(it->first)};
        return distance(q, c.center) < c.radius ? it->second : -1;
    }
    return -1;
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
