#include "reference.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <map>

#include "geometry/coordinate_range.hpp"

namespace acanthus::growth::detail {

using acanthus::detail::in_coordinate_range;

int ReferenceData::symbol_id(const std::string& s) const {
    auto it = std::lower_bound(symbols.begin(), symbols.end(), s);
    return it != symbols.end() && *it == s ? static_cast<int>(it - symbols.begin()) : -1;
}

std::shared_ptr<const ReferenceData> analyse_reference(std::string name,
                                                       std::vector<ReferenceElement> elements,
                                                       std::vector<std::pair<int, int>> flips,
                                                       std::vector<std::vector<Outline>> outlines) {
    auto bad = [&](std::size_t i, const std::string& why) {
        throw InputError(name + ": element " + std::to_string(i) + ": " + why);
    };
    if (elements.size() < 3)
        throw InputError(name + ": a reference needs at least 3 elements, it has " +
                         std::to_string(elements.size()));
    std::map<std::pair<double, double>, std::size_t> seen;
    std::vector<Point> points;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const ReferenceElement& e = elements[i];
        if (e.symbol.empty()) bad(i, "empty \"symbol\"");
        if (!e.position.finite()) bad(i, "coordinates are not finite numbers");
        if (!in_coordinate_range(e.position.x) || !in_coordinate_range(e.position.y))
            bad(i, "coordinates out of range (the limit is ±1e9 user units)");
        if (!std::isfinite(e.angle)) bad(i, "\"angle\" is not a finite number");
        if (!std::isfinite(e.size) || e.size < 0) bad(i, "\"size\" must be a positive number");
        if (!in_coordinate_range(e.size)) bad(i, "\"size\" out of range (the limit is 1e9)");
        auto [it, fresh] = seen.emplace(std::pair{e.position.x, e.position.y}, i);
        if (!fresh) bad(i, "lies on element " + std::to_string(it->second));
        points.push_back(e.position);
    }
    auto data = std::make_shared<ReferenceData>();
    data->name = name;
    data->connectivity = analyse_connectivity(points, flips, name);
    const Connectivity& c = data->connectivity;

    for (const auto& e : elements) data->symbols.push_back(e.symbol);
    std::sort(data->symbols.begin(), data->symbols.end());
    data->symbols.erase(std::unique(data->symbols.begin(), data->symbols.end()),
                        data->symbols.end());

    double total = 0;
    data->shortest_edge = INFINITY;
    for (auto [i, j] : c.edges) {
        double l = distance(points[i], points[j]);
        total += l;
        data->shortest_edge = std::min(data->shortest_edge, l);
    }
    data->mean_edge = total / static_cast<double>(c.edges.size());

    for (std::size_t i = 0; i < elements.size(); ++i) {
        const ReferenceElement& e = elements[i];
        data->symbol.push_back(data->symbol_id(e.symbol));
        data->radius.push_back(e.size > 0 ? e.size : 0.35 * data->mean_edge);
        std::vector<RingSlot> ring;
        for (std::size_t k = 0; k < c.rings[i].size(); ++k) {
            int j = c.rings[i][k];
            ring.push_back({j, points[j] - points[i], c.closed[i][k]});
        }
        data->rings.push_back(std::move(ring));
        if (!c.boundary[i]) data->candidates.push_back(static_cast<int>(i));
    }
    // Section 4 matches only elements surrounded by their neighbours; a ring with a gap would be
    // copied with the gap (a single triangle, a strip, a row of two).
    if (data->candidates.empty())
        throw InputError(name +
                         ": no element is surrounded by its neighbours (every one lies on the "
                         "boundary of the connectivity), so there is no ring to copy; a reference "
                         "needs at least one element with neighbours all around it");
    outlines.resize(elements.size());
    data->outlines = std::move(outlines);
    data->elements = std::move(elements);
    return data;
}

}  // namespace acanthus::growth::detail
