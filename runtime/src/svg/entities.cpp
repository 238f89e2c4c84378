#include "svg/entities.hpp"

#include <acanthus/error.hpp>
#include <cctype>

namespace acanthus::detail {
namespace {

constexpr std::size_t kMaxEntityName = 256;

}  // namespace

DoctypeEntities::DoctypeEntities(const pugi::xml_document& doc, std::size_t limit)
    : limit_(limit), budget_(limit) {
    for (pugi::xml_node n : doc.children()) {
        if (n.type() != pugi::node_doctype) continue;
        std::string_view dtd = n.value();
        for (std::size_t at = dtd.find("<!ENTITY"); at != std::string_view::npos;
             at = dtd.find("<!ENTITY", at + 1)) {
            std::size_t p = at + 8;
            auto skip_space = [&] {
                while (p < dtd.size() && std::isspace(static_cast<unsigned char>(dtd[p]))) ++p;
            };
            skip_space();
            if (p >= dtd.size() || dtd[p] == '%') continue;  // a parameter entity
            std::size_t name_start = p;
            while (p < dtd.size() && !std::isspace(static_cast<unsigned char>(dtd[p]))) ++p;
            if (p - name_start > kMaxEntityName) continue;
            std::string name(dtd.substr(name_start, p - name_start));
            skip_space();
            if (p >= dtd.size() || (dtd[p] != '"' && dtd[p] != '\'')) continue;  // external
            std::size_t close = dtd.find(dtd[p], p + 1);
            if (close == std::string_view::npos) continue;
            entities_.emplace("&" + name + ";", std::string(dtd.substr(p + 1, close - p - 1)));
        }
    }
}

std::string DoctypeEntities::expand(std::string_view value, const std::string& file) {
    std::string out;
    std::size_t from = 0;
    for (std::size_t amp = value.find('&'); amp != std::string_view::npos;
         amp = value.find('&', amp + 1)) {
        std::size_t semi = value.find(';', amp);
        if (semi == std::string_view::npos) break;
        if (semi - amp > kMaxEntityName) continue;  // not an entity reference
        auto it = entities_.find(value.substr(amp, semi - amp + 1));
        if (it == entities_.end()) continue;
        if (it->second.size() > budget_)
            throw InputError(file + ": DOCTYPE entities expand to more than " +
                             std::to_string(limit_ >> 20) + " MiB");
        budget_ -= it->second.size();
        out.append(value.substr(from, amp - from)).append(it->second);
        from = semi + 1;
        amp = semi;
    }
    return out.append(value.substr(from));
}

}  // namespace acanthus::detail
