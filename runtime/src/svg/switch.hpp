// Conditional processing in a <switch>: which child's requiredFeatures, requiredExtensions
// and systemLanguage pass, so that the first such child is the one drawn.
#pragma once

#include <pugixml.hpp>

namespace acanthus::detail {

// The conditions of one child of a <switch>: requiredExtensions lists none (no extension is
// implemented), requiredFeatures only implemented features, and no systemLanguage (a
// region does not depend on the reader's locale; rsvg under the C locale matches none).
bool passes_conditions(pugi::xml_node node);

}  // namespace acanthus::detail
