#include "svg/style.hpp"

#include <acanthus/error.hpp>
#include <iterator>
#include <set>
#include <sstream>
#include <tuple>

#include "svg/namespaces.hpp"

namespace acanthus::detail {
namespace {

constexpr std::size_t kMaxCssRules = 10000;  // style-sheet rules setting a property read here

const std::vector<std::string_view> kProperties = {"fill-rule", "display", "fill", "stroke",
                                                   "stroke-width"};
constexpr const char* kPropertyNames = "fill-rule, display, fill, stroke or stroke-width";

bool matches(const CssCompound& c, pugi::xml_node node) {
    if (!c.type.empty() && c.type != local_name(node)) return false;
    if (!c.id.empty() && c.id != node.attribute("id").value()) return false;
    if (c.classes.empty()) return true;
    std::istringstream words(node.attribute("class").value());
    std::set<std::string> classes{std::istream_iterator<std::string>(words),
                                  std::istream_iterator<std::string>()};
    for (const std::string& k : c.classes)
        if (!classes.count(k)) return false;
    return true;
}

// Right to left, each descendant compound on the nearest ancestor that matches it.
bool matches(const CssRule& rule, pugi::xml_node node) {
    std::size_t i = rule.compounds.size() - 1;
    if (!matches(rule.compounds[i], node)) return false;
    while (i > 0) {
        char combinator = rule.combinators[i - 1];
        --i;
        node = node.parent();
        if (combinator == '>') {
            if (node.type() != pugi::node_element || !matches(rule.compounds[i], node))
                return false;
            continue;
        }
        while (node.type() == pugi::node_element && !matches(rule.compounds[i], node))
            node = node.parent();
        if (node.type() != pugi::node_element) return false;
    }
    return true;
}

}  // namespace

void StyleCascade::read(const std::vector<pugi::xml_node>& style_elements,
                        const std::string& file) {
    std::size_t order = 0;
    for (pugi::xml_node n : style_elements) {
        Namespaces scope = Namespaces::at(n);
        std::string_view type = n.attribute("type").value();
        if (svg_name(n, &scope) != "style" || !(type.empty() || type == "text/css")) continue;
        std::string sheet;
        for (pugi::xml_node text : n.children())
            if (text.type() == pugi::node_pcdata || text.type() == pugi::node_cdata)
                sheet += text.value();
        for (CssRule& r : parse_style_sheet(sheet, kProperties, order)) {
            if (rules_.size() == kMaxCssRules)
                throw InputError(file + ": style sheets set " + kPropertyNames + " in more than " +
                                 std::to_string(kMaxCssRules) + " rules");
            const CssCompound& key = r.compounds.back();
            index_[!key.id.empty()        ? "#" + key.id
                   : !key.classes.empty() ? "." + key.classes.front()
                   : !key.type.empty()    ? key.type
                                          : "*"]
                .push_back(rules_.size());
            rules_.push_back(std::move(r));
        }
    }
}

std::optional<std::string> StyleCascade::property(pugi::xml_node node, const char* name) const {
    const CssRule* best = nullptr;
    auto consider = [&](const std::string& key) {
        auto it = index_.find(key);
        if (it == index_.end()) return;
        for (std::size_t i : it->second) {
            const CssRule& r = rules_[i];
            if (r.property != name || !matches(r, node)) continue;
            if (!best || std::tie(r.important, r.specificity, r.order) >
                             std::tie(best->important, best->specificity, best->order))
                best = &r;
        }
    };
    if (!rules_.empty()) {
        // Only rules whose last compound could match: by id, class, type or any element.
        if (const char* id = node.attribute("id").value(); *id) consider("#" + std::string(id));
        std::istringstream classes(node.attribute("class").value());
        for (std::string c; classes >> c;) consider("." + c);
        consider(std::string(local_name(node)));
        consider("*");
    }
    if (best && best->important) return best->value;
    if (auto v = style_property(node.attribute("style").value(), name)) return v;
    if (best) return best->value;
    if (pugi::xml_attribute a = node.attribute(name)) return std::string(a.value());
    return std::nullopt;
}

}  // namespace acanthus::detail
