// The order of the structured SVG's layers, one per element type.
#pragma once

#include <acanthus/element.hpp>
#include <vector>

namespace acanthus::detail {

// Element types, bottom layer first. A rule's children are placed, and so drawn, in the order
// the rule lists them ("flower --> stem flower" draws the stem under its flower): type A goes
// under type B when, among siblings, A's elements come before B's more often than after.
// Otherwise (and to break a cycle) types keep the order of their first element.
std::vector<const ElementType*> layer_order(const std::vector<const Element*>& elements);

}  // namespace acanthus::detail
