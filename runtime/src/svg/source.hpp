// The SVG file a region is read from, as its error messages name it: the file name, and the
// line of an element found from its byte offset (pugixml keeps offsets, not lines).
#pragma once

#include <cstddef>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace acanthus::detail {

class SvgSource {
  public:
    SvgSource(std::string name, std::string_view text);

    const std::string& name() const { return name_; }

    // 1-based (line, column) of a byte offset into the text; (0, 0) for a negative offset.
    std::pair<std::size_t, std::size_t> position(std::ptrdiff_t offset) const;

    // The element as a message shows it: <path id="a">.
    static std::string label(pugi::xml_node node);

    // Throws InputError "FILE:LINE: <element>: why".
    [[noreturn]] void fail(pugi::xml_node node, const std::string& why) const;

  private:
    std::string name_;
    std::vector<std::size_t> line_starts_{0};
};

}  // namespace acanthus::detail
