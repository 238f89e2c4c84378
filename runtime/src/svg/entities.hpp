// General entities declared in an SVG file's DOCTYPE, which pugixml leaves unexpanded
// (<!ENTITY ns_svg "http://www.w3.org/2000/svg">, as Adobe Illustrator declares its
// namespace URIs).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <pugixml.hpp>
#include <string>
#include <string_view>

namespace acanthus::detail {

// The entities of the internal subset, expanded one level deep (an entity's own references
// stay as written). External and parameter entities are not read.
class DoctypeEntities {
  public:
    // `limit`: the bytes expansion may add, over every value expanded.
    DoctypeEntities(const pugi::xml_document& doc, std::size_t limit);

    bool empty() const { return entities_.empty(); }

    // `value` with the declared entities expanded; throws InputError naming `file` when
    // expansion passes the limit.
    std::string expand(std::string_view value, const std::string& file);

  private:
    std::map<std::string, std::string, std::less<>> entities_;  // "&name;" -> replacement
    std::size_t limit_;
    std::size_t budget_;  // what expansion may still add
};

}  // namespace acanthus::detail
