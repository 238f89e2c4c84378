#include "svg/source.hpp"

#include <acanthus/error.hpp>
#include <algorithm>

namespace acanthus::detail {

SvgSource::SvgSource(std::string name, std::string_view text) : name_(std::move(name)) {
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') line_starts_.push_back(i + 1);
}

std::pair<std::size_t, std::size_t> SvgSource::position(std::ptrdiff_t offset) const {
    if (offset < 0) return {0, 0};
    auto off = static_cast<std::size_t>(offset);
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), off);
    std::size_t line = static_cast<std::size_t>(it - line_starts_.begin());  // 1-based
    return {line, off - line_starts_[line - 1] + 1};
}

std::string SvgSource::label(pugi::xml_node node) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict, bug 105329) on "lit" + string&&.
    std::string s = std::string("<").append(node.name());
    if (const char* id = node.attribute("id").value(); *id)
        s.append(" id=\"").append(id).append("\"");
    return s + ">";
}

void SvgSource::fail(pugi::xml_node node, const std::string& why) const {
    auto [line, col] = position(node.offset_debug());
    std::string where = line > 0 ? name_ + ":" + std::to_string(line) : name_;
    throw InputError(where + ": " + label(node) + ": " + why);
}

}  // namespace acanthus::detail
