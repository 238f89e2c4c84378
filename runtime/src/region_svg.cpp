// Region from an SVG file: every filled shape outside defs/clipPath/mask/symbol, in the user
// units of the root element (its viewBox is not applied), with group and shape transforms.
#include <2geom/exception.h>
#include <2geom/path-sink.h>
#include <2geom/svg-path-parser.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>

#include "region_build.hpp"
#include "region_svg_attributes.hpp"

namespace acanthus {
namespace {

constexpr const char* kSvgNamespace = "http://www.w3.org/2000/svg";
constexpr int kMaxDepth = 256;               // element nesting, including <use> chains
constexpr int kMaxUseExpansions = 10000;     // guards against exponential <use> fan-out
constexpr std::size_t kMaxCurves = 1000000;  // all shapes together
constexpr std::uintmax_t kMaxFileBytes = 64u << 20;

struct Context {
    Geom::Affine ctm = Geom::identity();  // element coordinates -> root user units
    bool evenodd = false;                 // inherited fill-rule
};

class SvgRegionReader {
  public:
    SvgRegionReader(std::string name, std::string_view text) : name_(std::move(name)), text_(text) {
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }

    std::vector<detail::FilledShape> read() {
        pugi::xml_parse_result result = doc_.load_buffer(text_.data(), text_.size());
        if (!result) {
            auto [line, col] = position(result.offset);
            throw InputError(name_ + ":" + std::to_string(line) + ":" + std::to_string(col) +
                             ": not a well-formed XML/SVG file: " + result.description());
        }
        pugi::xml_node root = doc_.document_element();
        if (!root) throw InputError(name_ + ": not an SVG file: no root element");
        if (svg_name(root) != "svg")
            throw InputError(name_ + ": not an SVG file: the root element is <" +
                             std::string(root.name()) + ">, not <svg>");
        collect_ids(root);
        visit(root, Context{}, 0, true);
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

    // Local name of an element in the SVG namespace, "" for foreign elements
    // (sodipodi:namedview, inkscape:*, metadata vocabularies).
    static std::string svg_name(pugi::xml_node node) {
        std::string_view name = node.name();
        std::size_t colon = name.find(':');
        if (colon == std::string_view::npos) return std::string(name);
        std::string xmlns = "xmlns:" + std::string(name.substr(0, colon));
        for (pugi::xml_node n = node; n; n = n.parent()) {
            if (pugi::xml_attribute a = n.attribute(xmlns.c_str()))
                return std::strcmp(a.value(), kSvgNamespace) == 0
                           ? std::string(name.substr(colon + 1))
                           : std::string();
        }
        return std::string();
    }

    void collect_ids(pugi::xml_node root) {
        for (pugi::xml_node n = root; n;) {
            if (n.type() == pugi::node_element) {
                if (const char* id = n.attribute("id").value(); *id) ids_.emplace(id, n);
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

    std::optional<std::string> property(pugi::xml_node node, const char* name) const {
        if (auto v = detail::style_property(node.attribute("style").value(), name)) return v;
        if (pugi::xml_attribute a = node.attribute(name)) return std::string(a.value());
        return std::nullopt;
    }

    double length(pugi::xml_node node, const char* attr, double fallback) const {
        pugi::xml_attribute a = node.attribute(attr);
        if (!a) return fallback;
        try {
            return detail::parse_length(a.value());
        } catch (const detail::SvgSyntaxError& e) {
            fail(node, std::string("attribute ") + attr + ": " + e.what());
        }
    }

    double non_negative(pugi::xml_node node, const char* attr, double fallback) const {
        double v = length(node, attr, fallback);
        if (v < 0) fail(node, std::string("attribute ") + attr + " is negative");
        return v;
    }

    void visit(pugi::xml_node node, const Context& parent, int depth, bool root = false) {
        if (node.type() != pugi::node_element) return;
        if (depth > kMaxDepth)
            fail(node, "elements nested deeper than " + std::to_string(kMaxDepth) + " levels");
        std::string tag = svg_name(node);
        static const std::set<std::string> kIgnored = {
            "defs", "clipPath", "mask",   "symbol",         "metadata",       "title",
            "desc", "style",    "script", "pattern",        "marker",         "filter",
            "text", "image",    "line",   "linearGradient", "radialGradient", "foreignObject"};
        if (tag.empty() || kIgnored.count(tag)) return;
        if (property(node, "display") == "none") return;

        Context ctx = parent;
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

        if (tag == "svg" && !root) ctx.ctm = nested_viewport(node) * ctx.ctm;
        if (tag == "svg" || tag == "g" || tag == "a" || tag == "switch") {
            for (pugi::xml_node child : node.children()) visit(child, ctx, depth + 1);
        } else if (tag == "use") {
            visit_use(node, ctx, depth);
        } else {
            Geom::PathVector pv = shape_geometry(node, tag);
            if (!pv.empty()) add_shape(node, std::move(pv), ctx);
        }
    }

    // A nested <svg>: x/y offset, and its viewBox fitted into width x height (xMidYMid meet,
    // or stretched with preserveAspectRatio="none").
    Geom::Affine nested_viewport(pugi::xml_node node) const {
        double x = length(node, "x", 0), y = length(node, "y", 0);
        Geom::Affine m(1, 0, 0, 1, x, y);
        pugi::xml_attribute vb = node.attribute("viewBox");
        if (!vb || !node.attribute("width") || !node.attribute("height")) return m;
        std::vector<double> v;
        try {
            v = detail::parse_number_list(vb.value());
        } catch (const detail::SvgSyntaxError& e) {
            fail(node, std::string("attribute viewBox: ") + e.what());
        }
        if (v.size() != 4 || !(v[2] > 0) || !(v[3] > 0))
            fail(node, "viewBox must be four numbers: min-x min-y width height > 0");
        double w = non_negative(node, "width", 0), h = non_negative(node, "height", 0);
        double sx = w / v[2], sy = h / v[3];
        double tx = x - v[0] * sx, ty = y - v[1] * sy;
        if (std::string(node.attribute("preserveAspectRatio").value()).find("none") ==
            std::string::npos) {
            double s = std::min(sx, sy);
            tx = x + (w - v[2] * s) / 2 - v[0] * s;
            ty = y + (h - v[3] * s) / 2 - v[1] * s;
            sx = sy = s;
        }
        return Geom::Affine(sx, 0, 0, sy, tx, ty);
    }

    void visit_use(pugi::xml_node node, const Context& ctx, int depth) {
        std::string href = node.attribute("href").value();
        if (href.empty()) href = node.attribute("xlink:href").value();
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
        inner.ctm = Geom::Affine(1, 0, 0, 1, length(node, "x", 0), length(node, "y", 0)) * ctx.ctm;
        use_chain_.push_back(target);
        if (svg_name(target) == "symbol") {
            for (pugi::xml_node child : target.children()) visit(child, inner, depth + 2);
        } else {
            visit(target, inner, depth + 1);
        }
        use_chain_.pop_back();
    }

    Geom::PathVector shape_geometry(pugi::xml_node node, const std::string& tag) const {
        Geom::PathVector pv;
        if (tag == "path") {
            const char* d = node.attribute("d").value();
            try {
                pv = Geom::parse_svg_path(d);
            } catch (const Geom::SVGPathParseError&) {
                std::string shown(d, std::min<std::size_t>(std::strlen(d), 60));
                fail(node,
                     "path data does not parse: '" + shown + (std::strlen(d) > 60 ? "...'" : "'"));
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
            pv = rect_geometry(node);
        } else if (tag == "circle" || tag == "ellipse") {
            double cx = length(node, "cx", 0), cy = length(node, "cy", 0);
            double rx = 0, ry = 0;
            if (tag == "circle") {
                rx = ry = non_negative(node, "r", 0);
            } else {
                pugi::xml_attribute ax = node.attribute("rx"), ay = node.attribute("ry");
                rx = non_negative(node, "rx", 0);
                ry = non_negative(node, "ry", 0);
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

    Geom::PathVector rect_geometry(pugi::xml_node node) const {
        double x = length(node, "x", 0), y = length(node, "y", 0);
        double w = non_negative(node, "width", 0), h = non_negative(node, "height", 0);
        Geom::PathVector pv;
        if (!(w > 0) || !(h > 0)) return pv;  // SVG: zero size disables rendering
        pugi::xml_attribute ax = node.attribute("rx"), ay = node.attribute("ry");
        double rx = non_negative(node, "rx", 0), ry = non_negative(node, "ry", 0);
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

    void add_shape(pugi::xml_node node, Geom::PathVector pv, const Context& ctx) {
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
        pv *= ctx.ctm;
        detail::require_finite(pv, name_, where);
        shapes_.push_back({std::move(pv), ctx.evenodd, where});
    }

    std::string name_;
    std::string_view text_;
    std::vector<std::size_t> line_starts_{0};
    pugi::xml_document doc_;
    std::map<std::string, pugi::xml_node> ids_;
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
    auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        throw InputError(path +
                         ": cannot open region file: no such file (expected an SVG file "
                         "or rect:W,H, circle:R, ellipse:RX,RY)");
    if (std::filesystem::is_directory(status))
        throw InputError(path + ": cannot open region file: it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open region file: " + std::strerror(errno));
    std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxFileBytes)
        throw InputError(path + ": region file is larger than " +
                         std::to_string(kMaxFileBytes >> 20) + " MiB");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw InputError(path + ": cannot read region file: " + std::strerror(errno));
    std::string text = buffer.str();
    if (text.size() > kMaxFileBytes)
        throw InputError(path + ": region file is larger than " +
                         std::to_string(kMaxFileBytes >> 20) + " MiB");
    return from_svg_string(text, path);
}

}  // namespace acanthus
