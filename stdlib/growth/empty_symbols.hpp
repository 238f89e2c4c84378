// A data-symbol element that owns no shape (an empty group, or only text, images or templates)
// would vanish from the reference without a word, since the SVG reader hands over only shapes:
// a pass over the XML itself finds it and names it.
#pragma once

#include <string>
#include <string_view>

namespace acanthus::growth::detail {

// Throws InputError "NAME: <g id=...> (line N): carries data-symbol ... but owns no shape" for the
// first such element in document order; does nothing when the text is not well-formed XML (the
// SVG reader has said why already).
void check_symbols_own_shapes(std::string_view text, const std::string& name);

}  // namespace acanthus::growth::detail
