// The element tree as JSON (--json FILE), in the shape docs/rendering.md gives ("--json FILE").
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/region.hpp>
#include <string>
#include <vector>

namespace acanthus::detail {

// {"region": {"bounds": [x0, y0, x1, y1], "area": a}, "elements": [{"id", "type", "parent",
// "depth", "sterile", "fields", "proxies"}, ...]}; proxies carry "kind" and the fields named in
// the rule language (point: "point", circle: "center"/"radius", arc: + "start"/"end",
// linesegment: "p0"/"p1", bezier: "c", polygon: "points"). Points are [x, y]; NaN is null.
std::string tree_json(const Region& region, const std::vector<const Element*>& elements);

// Writes tree_json() through a temporary file renamed on success; "-" writes to stdout.
void write_tree_json(const std::string& path, const Region& region,
                     const std::vector<const Element*>& elements);

}  // namespace acanthus::detail
