// Region from an SVG file: every filled shape outside defs/clipPath/mask/symbol, in the user
// units of the root element (its viewBox is not applied), with group and shape transforms.
// docs/regions.md says exactly what is read and what is left out.
#include <2geom/elliptical-arc.h>
#include <2geom/exception.h>
#include <2geom/path-sink.h>
#include <2geom/svg-path-parser.h>

#include <acanthus/error.hpp>
#include <acanthus/input_file.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include "region_build.hpp"
#include "region_svg_attributes.hpp"

namespace acanthus {
namespace {

constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";
constexpr std::string_view kXlinkNamespace = "http://www.w3.org/1999/xlink";
constexpr std::string_view kXmlNamespace = "http://www.w3.org/XML/1998/namespace";
constexpr int kMaxDepth = 256;               // element nesting, including <use> chains
constexpr int kMaxUseExpansions = 10000;     // guards against exponential <use> fan-out
constexpr std::size_t kMaxCurves = detail::kMaxRegionCurves;  // as read, before arcs become cubics
constexpr std::size_t kMaxEntityName = 256;
constexpr std::size_t kMaxCssRules = 10000;  // style-sheet rules setting fill-rule or display
constexpr const char* kBadArc =
    "an elliptical arc cannot be computed (its coordinates or radii are out of range)";
constexpr std::uintmax_t kMaxFileBytes = 64u << 20;

// XML namespace declarations in scope (pugixml does not resolve namespaces): the xmlns and
// xmlns:PREFIX attributes of one element, linked to those of its ancestors. Names point into
// the document, which outlives every scope.
struct Namespaces {
    const Namespaces* parent = nullptr;
    // (prefix, URI); the prefix "" is the default namespace.
    std::vector<std::pair<std::string_view, std::string_view>> bindings;

    // Adds the declarations `node` makes itself.
    void declare(pugi::xml_node node) {
        for (pugi::xml_attribute a : node.attributes()) {
            std::string_view name = a.name();
            if (name == "xmlns") {
                bindings.emplace_back(std::string_view(), a.value());
            } else if (name.substr(0, 6) == "xmlns:") {
                bindings.emplace_back(name.substr(6), a.value());
            }
        }
    }

    // Every declaration in scope at `node`, its own included, innermost first: the scope of an
    // element reached out of document order (the root, a <use> target).
    static Namespaces at(pugi::xml_node node) {
        Namespaces ns;
        for (pugi::xml_node n = node; n; n = n.parent())
            if (n.type() == pugi::node_element) ns.declare(n);
        return ns;
    }

    // The URI `prefix` is bound to; nullopt when it is not declared (an unprefixed name with
    // no default namespace, or a prefix nobody declared).
    static std::optional<std::string_view> uri(const Namespaces* scope, std::string_view prefix) {
        for (const Namespaces* s = scope; s; s = s->parent)
            for (const auto& [p, u] : s->bindings)
                if (p == prefix) return u;
        if (prefix == "xml") return kXmlNamespace;
        return std::nullopt;
    }
};

struct Context {
    Geom::Affine ctm = Geom::identity();  // element coordinates -> root user units
    bool evenodd = false;                 // inherited fill-rule
    const Namespaces* ns = nullptr;       // declarations in scope of the parent element
    Geom::Point viewport{0, 0};           // nearest viewport in user units (0: not known)
};

// Which way a percentage length is measured (SVG 1.1, 7.10).
enum class Axis { X, Y, Diagonal };

// Feature strings rsvg implements (requiredFeatures in a <switch>), sorted.
constexpr std::array<std::string_view, 21> kFeatures = {
    "http://www.w3.org/TR/SVG11/feature#BasicFilter",
    "http://www.w3.org/TR/SVG11/feature#BasicGraphicsAttribute",
    "http://www.w3.org/TR/SVG11/feature#BasicPaintAttribute",
    "http://www.w3.org/TR/SVG11/feature#BasicStructure",
    "http://www.w3.org/TR/SVG11/feature#BasicText",
    "http://www.w3.org/TR/SVG11/feature#ConditionalProcessing",
    "http://www.w3.org/TR/SVG11/feature#ContainerAttribute",
    "http://www.w3.org/TR/SVG11/feature#Filter",
    "http://www.w3.org/TR/SVG11/feature#Gradient",
    "http://www.w3.org/TR/SVG11/feature#Image",
    "http://www.w3.org/TR/SVG11/feature#Marker",
    "http://www.w3.org/TR/SVG11/feature#Mask",
    "http://www.w3.org/TR/SVG11/feature#OpacityAttribute",
    "http://www.w3.org/TR/SVG11/feature#Pattern",
    "http://www.w3.org/TR/SVG11/feature#SVG",
    "http://www.w3.org/TR/SVG11/feature#SVG-static",
    "http://www.w3.org/TR/SVG11/feature#Shape",
    "http://www.w3.org/TR/SVG11/feature#Structure",
    "http://www.w3.org/TR/SVG11/feature#Style",
    "http://www.w3.org/TR/SVG11/feature#View",
    "org.w3c.svg.static"};

// The conditions of one child of a <switch>: requiredExtensions lists none (no extension is
// implemented), requiredFeatures only implemented features, and no systemLanguage (a
// region does not depend on the reader's locale; rsvg under the C locale matches none).
bool passes_conditions(pugi::xml_node node) {
    auto words_all = [](std::string_view text, auto&& known) {
        std::istringstream in{std::string(text)};
        std::string word;
        while (in >> word)
            if (!known(word)) return false;
        return true;
    };
    if (pugi::xml_attribute a = node.attribute("requiredExtensions"))
        if (!words_all(a.value(), [](const std::string&) { return false; })) return false;
    if (pugi::xml_attribute a = node.attribute("requiredFeatures"))
        if (!words_all(a.value(), [](const std::string& w) {
                return std::binary_search(kFeatures.begin(), kFeatures.end(), w);
            }))
            return false;
    return !node.attribute("systemLanguage");
}

class SvgRegionReader {
  public:
    SvgRegionReader(std::string name, std::string_view text) : name_(std::move(name)), text_(text) {
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }

    std::vector<detail::FilledShape> read() {
        pugi::xml_parse_result result =
            doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default | pugi::parse_doctype);
        if (!result) {
            auto [line, col] = position(result.offset);
            throw InputError(name_ + ":" + std::to_string(line) + ":" + std::to_string(col) +
                             ": not a well-formed XML/SVG file: " + result.description());
        }
        pugi::xml_node root = doc_.document_element();
        if (!root) throw InputError(name_ + ": not an SVG file: no root element");
        read_entities();
        collect_ids(root);
        read_style_sheets();
        Namespaces root_scope = Namespaces::at(root);
        if (svg_name(root, &root_scope) != "svg")
            throw InputError(name_ + ": not an SVG file: the root element is <" +
                             std::string(root.name()) + ">, not <svg> in the SVG namespace");
        Context top;
        top.viewport = root_viewport(root);
        visit(root, top, 0, true);
        if (shapes_.empty())
            throw InputError(name_ +
                             ": no fillable shape (path, polygon, polyline, rect, circle or "
                             "ellipse) outside defs, clipPath, mask and symbol");
        return std::move(shapes_);
    }

  private:
    std::pair<std::size_t, std::size_t> position(std::ptrdiff_t offset) const {
        if (offset < 0) return {0, 0};
        auto off = static_cast<std::size_t>(offset);
        auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), off);
        std::size_t line = static_cast<std::size_t>(it - line_starts_.begin());  // 1-based
        return {line, off - line_starts_[line - 1] + 1};
    }

    std::string label(pugi::xml_node node) const {
        std::string s = "<" + std::string(node.name());
        if (const char* id = node.attribute("id").value(); *id)
            s += " id=\"" + std::string(id) + "\"";
        return s + ">";
    }

    [[noreturn]] void fail(pugi::xml_node node, const std::string& why) const {
        auto [line, col] = position(node.offset_debug());
        std::string where = line > 0 ? name_ + ":" + std::to_string(line) : name_;
        throw InputError(where + ": " + label(node) + ": " + why);
    }

    // Local name of an element in the SVG namespace, "" for elements of other namespaces
    // (sodipodi:namedview, inkscape:*, metadata vocabularies) and for undeclared prefixes.
    // `scope` includes the element's own declarations. The namespace is found by URI, so
    // <svg:path> counts when xmlns:svg is bound to the SVG namespace. An unprefixed name with
    // no default namespace in scope (a file without xmlns, or xmlns="") is read as SVG, as
    // rsvg reads it.
    static std::string svg_name(pugi::xml_node node, const Namespaces* scope) {
        std::string_view name = node.name();
        std::size_t colon = name.find(':');
        std::string_view prefix = colon == std::string_view::npos ? "" : name.substr(0, colon);
        std::string_view local = colon == std::string_view::npos ? name : name.substr(colon + 1);
        std::optional<std::string_view> uri = Namespaces::uri(scope, prefix);
        if (!uri) return prefix.empty() ? std::string(local) : std::string();
        if (uri->empty() && prefix.empty()) return std::string(local);  // xmlns=""
        return *uri == kSvgNamespace ? std::string(local) : std::string();
    }

    // The reference of a <use>: SVG 2's plain href, else an href attribute in the XLink
    // namespace under whatever prefix is bound to it (xlink:href, a0:href, ...). href under
    // a prefix of another namespace is not a reference; under an undeclared prefix it is
    // refused, as XML namespaces require (rsvg refuses the file too).
    std::string use_href(pugi::xml_node node, const Namespaces* scope) const {
        if (pugi::xml_attribute a = node.attribute("href")) return a.value();
        for (pugi::xml_attribute a : node.attributes()) {
            std::string_view name = a.name();
            std::size_t colon = name.find(':');
            if (colon == std::string_view::npos || name.substr(colon + 1) != "href") continue;
            std::string_view prefix = name.substr(0, colon);
            if (prefix == "xmlns") continue;  // xmlns:href declares a prefix
            std::optional<std::string_view> uri = Namespaces::uri(scope, prefix);
            if (!uri)
                fail(node, "attribute " + std::string(name) + ": namespace prefix '" +
                               std::string(prefix) +
                               "' is not declared (xmlns:" + std::string(prefix) + "=\"" +
                               std::string(kXlinkNamespace) + "\" would make it XLink)");
            if (*uri == kXlinkNamespace) return a.value();
        }
        return std::string();
    }

    // General entities declared in the DOCTYPE's internal subset (<!ENTITY ns_svg
    // "http://www.w3.org/2000/svg">, as Adobe Illustrator declares its namespace URIs).
    // pugixml expands only the predefined entities; collect_ids expands these in attribute
    // values, one level deep (an entity's own references stay as written). External and
    // parameter entities are not read.
    void read_entities() {
        for (pugi::xml_node n : doc_.children()) {
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

    // `value` with the declared entities expanded; `budget` bounds what expansion may add.
    std::string expand_entities(std::string_view value, std::size_t& budget) const {
        std::string out;
        std::size_t from = 0;
        for (std::size_t amp = value.find('&'); amp != std::string_view::npos;
             amp = value.find('&', amp + 1)) {
            std::size_t semi = value.find(';', amp);
            if (semi == std::string_view::npos) break;
            if (semi - amp > kMaxEntityName) continue;  // not an entity reference
            auto it = entities_.find(value.substr(amp, semi - amp + 1));
            if (it == entities_.end()) continue;
            if (it->second.size() > budget)
                throw InputError(name_ + ": DOCTYPE entities expand to more than " +
                                 std::to_string(kMaxFileBytes >> 20) + " MiB");
            budget -= it->second.size();
            out.append(value.substr(from, amp - from)).append(it->second);
            from = semi + 1;
            amp = semi;
        }
        return out.append(value.substr(from));
    }

    void collect_ids(pugi::xml_node root) {
        std::size_t budget = kMaxFileBytes;
        for (pugi::xml_node n = root; n;) {
            if (n.type() == pugi::node_element) {
                if (!entities_.empty())
                    for (pugi::xml_attribute a : n.attributes())
                        if (std::strchr(a.value(), '&'))
                            a.set_value(expand_entities(a.value(), budget).c_str());
                if (const char* id = n.attribute("id").value(); *id) ids_.emplace(id, n);
                if (local_name(n) == "style") style_elements_.push_back(n);
            }
            // Iterative pre-order walk: depth is unbounded here.
            if (n.first_child()) {
                n = n.first_child();
                continue;
            }
            while (n && n != root && !n.next_sibling()) n = n.parent();
            if (!n || n == root) break;
            n = n.next_sibling();
        }
    }

    static std::string_view local_name(pugi::xml_node node) {
        std::string_view name = node.name();
        std::size_t colon = name.find(':');
        return colon == std::string_view::npos ? name : name.substr(colon + 1);
    }

    // The rules of every <style> element of the SVG namespace (type text/css or none) that
    // set a property a region reads.
    void read_style_sheets() {
        std::size_t order = 0;
        for (pugi::xml_node n : style_elements_) {
            Namespaces scope = Namespaces::at(n);
            std::string_view type = n.attribute("type").value();
            if (svg_name(n, &scope) != "style" || !(type.empty() || type == "text/css")) continue;
            std::string sheet;
            for (pugi::xml_node text : n.children())
                if (text.type() == pugi::node_pcdata || text.type() == pugi::node_cdata)
                    sheet += text.value();
            for (detail::CssRule& r :
                 detail::parse_style_sheet(sheet, {"fill-rule", "display"}, order)) {
                if (css_.size() == kMaxCssRules)
                    throw InputError(name_ +
                                     ": style sheets set fill-rule or display in more "
                                     "than " +
                                     std::to_string(kMaxCssRules) + " rules");
                const detail::CssCompound& key = r.compounds.back();
                css_index_[!key.id.empty()        ? "#" + key.id
                           : !key.classes.empty() ? "." + key.classes.front()
                           : !key.type.empty()    ? key.type
                                                  : "*"]
                    .push_back(css_.size());
                css_.push_back(std::move(r));
            }
        }
    }

    static bool matches(const detail::CssCompound& c, pugi::xml_node node) {
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
    static bool matches(const detail::CssRule& rule, pugi::xml_node node) {
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

    // A property as the cascade gives it: !important style-sheet rules, then the style
    // attribute, then style-sheet rules (by specificity, then order), then the presentation
    // attribute.
    std::optional<std::string> property(pugi::xml_node node, const char* name) const {
        const detail::CssRule* best = nullptr;
        auto consider = [&](const std::string& key) {
            auto it = css_index_.find(key);
            if (it == css_index_.end()) return;
            for (std::size_t i : it->second) {
                const detail::CssRule& r = css_[i];
                if (r.property != name || !matches(r, node)) continue;
                if (!best || std::tie(r.important, r.specificity, r.order) >
                                 std::tie(best->important, best->specificity, best->order))
                    best = &r;
            }
        };
        if (!css_.empty()) {
            // Only rules whose last compound could match: by id, class, type or any element.
            if (const char* id = node.attribute("id").value(); *id) consider("#" + std::string(id));
            std::istringstream classes(node.attribute("class").value());
            for (std::string c; classes >> c;) consider("." + c);
            consider(std::string(local_name(node)));
            consider("*");
        }
        if (best && best->important) return best->value;
        if (auto v = detail::style_property(node.attribute("style").value(), name)) return v;
        if (best) return best->value;
        if (pugi::xml_attribute a = node.attribute(name)) return std::string(a.value());
        return std::nullopt;
    }

    // The root's viewport in its user units, for percentages: its viewBox size, else its
    // absolute width and height; (0, 0) when neither is known. Nothing else of the root's
    // size is used (the region keeps the root's user units).
    static Geom::Point root_viewport(pugi::xml_node root) {
        try {
            std::vector<double> v = detail::parse_number_list(root.attribute("viewBox").value());
            if (v.size() == 4 && v[2] > 0 && v[3] > 0) return {v[2], v[3]};
            if (root.attribute("width") && root.attribute("height"))
                return {detail::parse_length(root.attribute("width").value()),
                        detail::parse_length(root.attribute("height").value())};
        } catch (const detail::SvgSyntaxError&) {
        }
        return {0, 0};
    }

    // A length attribute in user units; a percentage is of the viewport's width, height or
    // normalized diagonal as `axis` says.
    double length(pugi::xml_node node, const char* attr, double fallback, const Context& ctx,
                  Axis axis) const {
        pugi::xml_attribute a = node.attribute(attr);
        if (!a) return fallback;
        detail::Length l;
        try {
            l = detail::parse_length_or_percent(a.value());
        } catch (const detail::SvgSyntaxError& e) {
            fail(node, std::string("attribute ") + attr + ": " + e.what());
        }
        if (!l.percent) return l.value;
        double base = axis == Axis::X ? ctx.viewport.x()
                      : axis == Axis::Y
                          ? ctx.viewport.y()
                          : std::hypot(ctx.viewport.x(), ctx.viewport.y()) / std::sqrt(2.0);
        if (!(base > 0))
            fail(node, std::string("attribute ") + attr + ": '" + a.value() +
                           "' is a percentage of a viewport of unknown size (give the root "
                           "<svg> a viewBox, or use absolute lengths)");
        return l.value / 100 * base;
    }

    double non_negative(pugi::xml_node node, const char* attr, double fallback, const Context& ctx,
                        Axis axis) const {
        double v = length(node, attr, fallback, ctx, axis);
        if (v < 0) fail(node, std::string("attribute ") + attr + " is negative");
        return v;
    }

    // `use` is the <use> that draws `node` when node is an <svg> it references (its width and
    // height replace the svg's).
    void visit(pugi::xml_node node, const Context& parent, int depth, bool root = false,
               pugi::xml_node use = pugi::xml_node()) {
        if (node.type() != pugi::node_element) return;
        if (depth > kMaxDepth)
            fail(node, "elements nested deeper than " + std::to_string(kMaxDepth) + " levels");
        Namespaces scope{parent.ns, {}};
        scope.declare(node);
        const Namespaces* ns = scope.bindings.empty() ? parent.ns : &scope;
        std::string tag = svg_name(node, ns);
        static const std::set<std::string> kIgnored = {
            "defs", "clipPath", "mask",   "symbol",         "metadata",       "title",
            "desc", "style",    "script", "pattern",        "marker",         "filter",
            "text", "image",    "line",   "linearGradient", "radialGradient", "foreignObject"};
        if (tag.empty() || kIgnored.count(tag)) return;
        if (property(node, "display") == "none") return;

        Context ctx = parent;
        ctx.ns = ns;
        if (pugi::xml_attribute t = node.attribute("transform")) {
            try {
                ctx.ctm = detail::parse_transform(t.value()) * parent.ctm;
            } catch (const detail::SvgSyntaxError& e) {
                fail(node, e.what());
            }
        }
        if (auto rule = property(node, "fill-rule")) {
            if (*rule == "evenodd") {
                ctx.evenodd = true;
            } else if (*rule == "nonzero") {
                ctx.evenodd = false;
            } else if (*rule != "inherit") {
                fail(node, "fill-rule '" + *rule + "' is neither nonzero nor evenodd");
            }
        }

        if (tag == "svg" && !root && !enter_viewport(node, use, ctx)) return;
        if (tag == "svg" || tag == "g" || tag == "a") {
            for (pugi::xml_node child : node.children()) visit(child, ctx, depth + 1);
        } else if (tag == "switch") {
            // Only the first child element whose conditions pass is drawn (whatever it is).
            for (pugi::xml_node child : node.children()) {
                if (child.type() != pugi::node_element || !passes_conditions(child)) continue;
                visit(child, ctx, depth + 1);
                break;
            }
        } else if (tag == "use") {
            visit_use(node, ctx, depth);
        } else {
            Geom::PathVector pv;
            try {
                pv = shape_geometry(node, tag, ctx);
            } catch (const Geom::Exception&) {
                fail(node, kBadArc);  // lib2geom failed on an arc of the shape
            }
            if (!pv.empty()) add_shape(node, std::move(pv), ctx);
        }
    }

    // Enters the viewport of a nested <svg>, or of a <symbol> or <svg> drawn by `use` (whose
    // width and height, when set, replace the target's): the element's x/y, and its viewBox
    // fitted into width x height by preserveAspectRatio. A missing width or height is 100% of
    // the parent viewport. Returns false when a zero width or height disables rendering. The
    // viewport does not clip (docs/regions.md).
    bool enter_viewport(pugi::xml_node node, pugi::xml_node use, Context& ctx) const {
        const Context parent = ctx;  // percentages refer to the parent's viewport
        double x = length(node, "x", 0, parent, Axis::X);
        double y = length(node, "y", 0, parent, Axis::Y);
        bool disabled = false;
        auto size = [&](const char* attr, Axis axis) {
            pugi::xml_node from = use && use.attribute(attr) ? use : node;
            if (!from.attribute(attr))
                return axis == Axis::X ? parent.viewport.x() : parent.viewport.y();
            double v = non_negative(from, attr, 0, parent, axis);
            if (v == 0) disabled = true;
            return v;
        };
        double w = size("width", Axis::X), h = size("height", Axis::Y);
        if (disabled) return false;
        Geom::Affine m(1, 0, 0, 1, x, y);
        ctx.viewport = Geom::Point(w, h);
        if (pugi::xml_attribute vb = node.attribute("viewBox")) {
            std::vector<double> v;
            detail::AspectRatio aspect;
            try {
                v = detail::parse_number_list(vb.value());
                aspect = detail::parse_aspect_ratio(node.attribute("preserveAspectRatio").value());
            } catch (const detail::SvgSyntaxError& e) {
                fail(node, e.what());
            }
            if (v.size() != 4 || !(v[2] > 0) || !(v[3] > 0))
                fail(node, "viewBox must be four numbers: min-x min-y width height > 0");
            if (!(w > 0) || !(h > 0))
                fail(node,
                     "a viewBox needs the viewport's width and height: set them, or give the "
                     "root <svg> a viewBox");
            m = detail::viewbox_transform(v, aspect, x, y, w, h);
            ctx.viewport = Geom::Point(v[2], v[3]);
        }
        ctx.ctm = m * ctx.ctm;
        return true;
    }

    void visit_use(pugi::xml_node node, const Context& ctx, int depth) {
        std::string href = use_href(node, ctx.ns);
        if (href.empty()) return;
        if (href[0] != '#')
            fail(node, "references outside the file ('" + href + "') are not supported");
        auto it = ids_.find(href.substr(1));
        if (it == ids_.end()) fail(node, "references unknown id '" + href + "'");
        pugi::xml_node target = it->second;
        for (pugi::xml_node n = node; n; n = n.parent())
            if (n == target) fail(node, "references its own ancestor '" + href + "'");
        if (std::find(use_chain_.begin(), use_chain_.end(), target) != use_chain_.end())
            fail(node, "<use> references form a cycle through '" + href + "'");
        if (++use_expansions_ > kMaxUseExpansions)
            fail(node, "more than " + std::to_string(kMaxUseExpansions) + " <use> expansions");
        Context inner = ctx;
        inner.ctm = Geom::Affine(1, 0, 0, 1, length(node, "x", 0, ctx, Axis::X),
                                 length(node, "y", 0, ctx, Axis::Y)) *
                    ctx.ctm;
        // The target is read in its own namespace scope, where it stands in the file.
        Namespaces outer = Namespaces::at(target.parent());
        Namespaces own{&outer, {}};
        own.declare(target);
        use_chain_.push_back(target);
        if (svg_name(target, &own) == "symbol") {
            inner.ns = &own;
            if (enter_viewport(target, node, inner))
                for (pugi::xml_node child : target.children()) visit(child, inner, depth + 2);
        } else {
            inner.ns = &outer;
            visit(target, inner, depth + 1, false, node);
        }
        use_chain_.pop_back();
    }

    Geom::PathVector shape_geometry(pugi::xml_node node, const std::string& tag,
                                    const Context& ctx) const {
        Geom::PathVector pv;
        if (tag == "path") {
            const char* d = node.attribute("d").value();
            try {
                pv = Geom::parse_svg_path(d);
            } catch (const Geom::SVGPathParseError&) {
                std::string shown(d, std::min<std::size_t>(std::strlen(d), 60));
                fail(node,
                     "path data does not parse: '" + shown + (std::strlen(d) > 60 ? "...'" : "'"));
            } catch (const Geom::Exception&) {
                fail(node, kBadArc);
            } catch (const std::exception& e) {
                fail(node, std::string("path data does not parse: ") + e.what());
            }
        } else if (tag == "polygon" || tag == "polyline") {
            std::vector<Geom::Point> pts;
            try {
                pts = detail::parse_points(node.attribute("points").value());
            } catch (const detail::SvgSyntaxError& e) {
                fail(node, e.what());
            }
            if (pts.size() < 3) return pv;  // nothing to fill
            Geom::Path path(pts.front());
            for (std::size_t i = 1; i < pts.size(); ++i) path.appendNew<Geom::LineSegment>(pts[i]);
            path.close(true);  // a polyline is filled as if closed
            pv.push_back(std::move(path));
        } else if (tag == "rect") {
            pv = rect_geometry(node, ctx);
        } else if (tag == "circle" || tag == "ellipse") {
            double cx = length(node, "cx", 0, ctx, Axis::X);
            double cy = length(node, "cy", 0, ctx, Axis::Y);
            double rx = 0, ry = 0;
            if (tag == "circle") {
                rx = ry = non_negative(node, "r", 0, ctx, Axis::Diagonal);
            } else {
                pugi::xml_attribute ax = node.attribute("rx"), ay = node.attribute("ry");
                rx = non_negative(node, "rx", 0, ctx, Axis::X);
                ry = non_negative(node, "ry", 0, ctx, Axis::Y);
                if (!ax) rx = ry;  // SVG 2: a missing radius is "auto", the other one
                if (!ay) ry = rx;
            }
            if (rx > 0 && ry > 0) {
                Geom::PathBuilder b(pv);
                b.moveTo(Geom::Point(cx + rx, cy));
                b.arcTo(rx, ry, 0, false, true, Geom::Point(cx - rx, cy));
                b.arcTo(rx, ry, 0, false, true, Geom::Point(cx + rx, cy));
                b.closePath();
                b.flush();
            }
        }
        return pv;
    }

    Geom::PathVector rect_geometry(pugi::xml_node node, const Context& ctx) const {
        double x = length(node, "x", 0, ctx, Axis::X), y = length(node, "y", 0, ctx, Axis::Y);
        double w = non_negative(node, "width", 0, ctx, Axis::X);
        double h = non_negative(node, "height", 0, ctx, Axis::Y);
        Geom::PathVector pv;
        if (!(w > 0) || !(h > 0)) return pv;  // SVG: zero size disables rendering
        pugi::xml_attribute ax = node.attribute("rx"), ay = node.attribute("ry");
        double rx = non_negative(node, "rx", 0, ctx, Axis::X);
        double ry = non_negative(node, "ry", 0, ctx, Axis::Y);
        if (!ax) rx = ry;
        if (!ay) ry = rx;
        rx = std::min(rx, w / 2);
        ry = std::min(ry, h / 2);
        Geom::PathBuilder b(pv);
        if (rx > 0 && ry > 0) {
            b.moveTo(Geom::Point(x + rx, y));
            b.lineTo(Geom::Point(x + w - rx, y));
            b.arcTo(rx, ry, 0, false, true, Geom::Point(x + w, y + ry));
            b.lineTo(Geom::Point(x + w, y + h - ry));
            b.arcTo(rx, ry, 0, false, true, Geom::Point(x + w - rx, y + h));
            b.lineTo(Geom::Point(x + rx, y + h));
            b.arcTo(rx, ry, 0, false, true, Geom::Point(x, y + h - ry));
            b.lineTo(Geom::Point(x, y + ry));
            b.arcTo(rx, ry, 0, false, true, Geom::Point(x + rx, y));
        } else {
            b.moveTo(Geom::Point(x, y));
            b.lineTo(Geom::Point(x + w, y));
            b.lineTo(Geom::Point(x + w, y + h));
            b.lineTo(Geom::Point(x, y + h));
        }
        b.closePath();
        b.flush();
        return pv;
    }

    // Every elliptical arc has a finite centre, radii and sweep, and bounds lib2geom can find.
    void check_arcs(pugi::xml_node node, const Geom::PathVector& pv) const {
        for (const Geom::Path& path : pv) {
            for (const Geom::Curve& curve : path) {
                const auto* arc = dynamic_cast<const Geom::EllipticalArc*>(&curve);
                if (!arc) continue;
                Geom::Point centre = arc->center(), rays = arc->rays();
                Geom::Rect box = arc->boundsExact();
                if (!centre.isFinite() || !rays.isFinite() || !std::isfinite(arc->sweepAngle()) ||
                    !box.min().isFinite() || !box.max().isFinite())
                    fail(node, kBadArc);
            }
        }
    }

    void add_shape(pugi::xml_node node, Geom::PathVector pv, const Context& ctx) {
        if (ctx.ctm.det() == 0) return;  // flattened onto a line or a point: nothing to fill
        std::size_t curves = 0;
        for (Geom::Path& p : pv) {
            p.close(true);  // fill closes open subpaths
            curves += p.size_closed();
        }
        curves_ += curves;
        if (curves_ > kMaxCurves)
            fail(node, "the region has more than " + std::to_string(kMaxCurves) + " curves");
        std::string where = label(node);
        if (auto [line, col] = position(node.offset_debug()); line > 0)
            where += " (line " + std::to_string(line) + ")";
        detail::require_finite(pv, name_, where);
        // lib2geom throws on arcs it cannot place (radii stretched to reach a far endpoint,
        // M 1e88,0 A 1,1 6 0 0 0,1): refused naming the element, as any bad coordinate is.
        try {
            pv *= ctx.ctm;
            check_arcs(node, pv);
        } catch (const Geom::Exception&) {
            fail(node, kBadArc);
        }
        detail::require_finite(pv, name_, where);
        shapes_.push_back({std::move(pv), ctx.evenodd, where});
    }

    std::string name_;
    std::string_view text_;
    std::vector<std::size_t> line_starts_{0};
    pugi::xml_document doc_;
    std::map<std::string, pugi::xml_node> ids_;
    std::map<std::string, std::string, std::less<>> entities_;  // "&name;" -> replacement
    std::vector<pugi::xml_node> style_elements_;
    std::vector<detail::CssRule> css_;
    std::map<std::string, std::vector<std::size_t>> css_index_;  // "#id", ".class", type, "*"
    std::vector<pugi::xml_node> use_chain_;
    int use_expansions_ = 0;
    std::size_t curves_ = 0;
    std::vector<detail::FilledShape> shapes_;
};

}  // namespace

Region Region::from_svg_string(std::string_view svg, const std::string& name) {
    std::vector<detail::FilledShape> shapes = SvgRegionReader(name, svg).read();
    return Region(detail::build_region_data(name, std::move(shapes)));
}

Region Region::from_svg_file(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::status(path, ec)))
        throw InputError(path +
                         ": cannot open region file: no such file (expected an SVG file "
                         "or rect:W,H, circle:R, ellipse:RX,RY)");
    const std::string text = read_input_file_or_throw(path, "region file", kMaxFileBytes);
    return from_svg_string(text, path);
}

}  // namespace acanthus
