#include "svg/shape_reader.hpp"

#include <2geom/elliptical-arc.h>
#include <2geom/exception.h>
#include <2geom/path-sink.h>
#include <2geom/svg-path-parser.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <sstream>

#include "geometry/path_checks.hpp"
#include "svg/attributes.hpp"
#include "svg/entities.hpp"
#include "svg/namespaces.hpp"
#include "svg/source.hpp"
#include "svg/style.hpp"
#include "svg/switch.hpp"
#include "svg/viewport.hpp"

namespace acanthus::detail {
namespace {

using Axis = SvgAxis;

constexpr int kMaxDepth = 256;            // element nesting, including <use> chains
constexpr int kMaxUseExpansions = 10000;  // guards against exponential <use> fan-out
constexpr std::size_t kMaxCurves = kMaxSvgCurves;
constexpr const char* kBadArc =
    "an elliptical arc cannot be computed (its coordinates or radii are out of range)";

struct Context {
    Geom::Affine ctm = Geom::identity();          // element coordinates -> root user units
    bool evenodd = false;                         // inherited fill-rule
    const Namespaces* ns = nullptr;               // declarations in scope of the parent element
    Geom::Point viewport{0, 0};                   // nearest viewport in user units (0: not known)
    std::string fill = "black", stroke = "none";  // inherited paint
    double stroke_width = 1;                      // inherited, in the element's units
    std::shared_ptr<const SvgElement> element;    // the parent element
};

std::vector<std::string> words(const char* text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(std::move(w));
    return out;
}

class SvgShapeReader {
  public:
    SvgShapeReader(std::string name, std::string_view text)
        : name_(std::move(name)), text_(text), source_(name_, text_) {}

    std::vector<SvgShape> read() {
        pugi::xml_parse_result result =
            doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default | pugi::parse_doctype);
        if (!result) {
            auto [line, col] = source_.position(result.offset);
            throw InputError(name_ + ":" + std::to_string(line) + ":" + std::to_string(col) +
                             ": not a well-formed XML/SVG file: " + result.description());
        }
        pugi::xml_node root = doc_.document_element();
        if (!root) throw InputError(name_ + ": not an SVG file: no root element");
        collect_ids(root);
        style_.read(style_elements_, name_);
        Namespaces root_scope = Namespaces::at(root);
        if (svg_name(root, &root_scope) != "svg")
            throw InputError(name_ + ": not an SVG file: the root element is <" +
                             std::string(root.name()) + ">, not <svg> in the SVG namespace");
        Context top;
        top.viewport = root_viewport(root);
        visit(root, top, 0, true);
        return std::move(shapes_);
    }

  private:
    [[noreturn]] void fail(pugi::xml_node node, const std::string& why) const {
        source_.fail(node, why);
    }

    // Expands DOCTYPE entities in attribute values (pugixml expands only the predefined
    // ones), and finds the elements that ids name and the <style> elements.
    void collect_ids(pugi::xml_node root) {
        DoctypeEntities entities(doc_, kMaxSvgFileBytes);
        for (pugi::xml_node n = root; n;) {
            if (n.type() == pugi::node_element) {
                if (!entities.empty())
                    for (pugi::xml_attribute a : n.attributes())
                        if (std::strchr(a.value(), '&'))
                            a.set_value(entities.expand(a.value(), name_).c_str());
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

    double length(pugi::xml_node node, const char* attr, double fallback, const Context& ctx,
                  Axis axis) const {
        return svg_length(source_, node, attr, fallback, ctx.viewport, axis);
    }

    double non_negative(pugi::xml_node node, const char* attr, double fallback, const Context& ctx,
                        Axis axis) const {
        return non_negative_length(source_, node, attr, fallback, ctx.viewport, axis);
    }

    // Enters the viewport `node` establishes (see enter_viewport); false when it
    // disables rendering.
    bool enter_viewport(pugi::xml_node node, pugi::xml_node use, Context& ctx) const {
        std::optional<SvgViewport> v =
            ::acanthus::detail::enter_viewport(source_, node, use, ctx.viewport);
        if (!v) return false;
        ctx.viewport = v->size;
        ctx.ctm = v->transform * ctx.ctm;
        return true;
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
            "defs", "clipPath", "mask",           "symbol",         "metadata",     "title",
            "desc", "style",    "script",         "pattern",        "marker",       "filter",
            "text", "image",    "linearGradient", "radialGradient", "foreignObject"};
        if (tag.empty() || kIgnored.count(tag)) return;
        if (style_.property(node, "display") == "none") return;

        Context ctx = parent;
        ctx.ns = ns;
        if (pugi::xml_attribute t = node.attribute("transform")) {
            try {
                ctx.ctm = parse_transform(t.value()) * parent.ctm;
            } catch (const SvgSyntaxError& e) {
                fail(node, e.what());
            }
        }
        if (auto rule = style_.property(node, "fill-rule")) {
            if (*rule == "evenodd") {
                ctx.evenodd = true;
            } else if (*rule == "nonzero") {
                ctx.evenodd = false;
            } else if (*rule != "inherit") {
                fail(node, "fill-rule '" + *rule + "' is neither nonzero nor evenodd");
            }
        }

        inherit_paint(node, ctx);
        ctx.element = element_of(node, tag, parent.element);

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

    void visit_use(pugi::xml_node node, const Context& ctx, int depth) {
        std::string href = use_href(source_, node, ctx.ns);
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
                pts = parse_points(node.attribute("points").value());
            } catch (const SvgSyntaxError& e) {
                fail(node, e.what());
            }
            if (pts.size() < 2) return pv;  // nothing drawn
            Geom::Path path(pts.front());
            for (std::size_t i = 1; i < pts.size(); ++i) path.appendNew<Geom::LineSegment>(pts[i]);
            path.close(tag == "polygon");
            pv.push_back(std::move(path));
        } else if (tag == "line") {
            Geom::Point a(length(node, "x1", 0, ctx, Axis::X), length(node, "y1", 0, ctx, Axis::Y));
            Geom::Point b(length(node, "x2", 0, ctx, Axis::X), length(node, "y2", 0, ctx, Axis::Y));
            Geom::Path path(a);
            path.appendNew<Geom::LineSegment>(b);
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
        for (Geom::Path& p : pv) curves += p.size_closed();
        curves_ += curves;
        if (curves_ > kMaxCurves)
            fail(node, "the file has more than " + std::to_string(kMaxCurves) + " curves");
        const std::string where = name_ + ": " + ctx.element->label;
        require_finite(pv, where);
        // lib2geom throws on arcs it cannot place (radii stretched to reach a far endpoint,
        // M 1e88,0 A 1,1 6 0 0 0,1): refused naming the element, as any bad coordinate is.
        try {
            pv *= ctx.ctm;
            check_arcs(node, pv);
        } catch (const Geom::Exception&) {
            fail(node, kBadArc);
        }
        require_finite(pv, where);
        require_in_range(pv, where);
        SvgShape shape;
        shape.paths = std::move(pv);
        shape.evenodd = ctx.evenodd;
        shape.fill = ctx.fill;
        shape.stroke = ctx.stroke;
        shape.stroke_width = ctx.stroke_width * std::sqrt(std::abs(ctx.ctm.det()));
        shape.element = ctx.element;
        shapes_.push_back(std::move(shape));
    }

    // fill, stroke and stroke-width as CSS inherits them; a stroke width that does not parse
    // (a percentage, em) keeps the inherited one.
    void inherit_paint(pugi::xml_node node, Context& ctx) const {
        if (auto v = style_.property(node, "fill"); v && *v != "inherit") ctx.fill = *v;
        if (auto v = style_.property(node, "stroke"); v && *v != "inherit") ctx.stroke = *v;
        if (auto v = style_.property(node, "stroke-width"); v && *v != "inherit") {
            try {
                double w = parse_length(*v);
                if (std::isfinite(w) && w >= 0) ctx.stroke_width = w;
            } catch (const SvgSyntaxError&) {
            }
        }
    }

    std::shared_ptr<const SvgElement> element_of(pugi::xml_node node, const std::string& tag,
                                                 std::shared_ptr<const SvgElement> parent) const {
        auto e = std::make_shared<SvgElement>();
        e->tag = tag;
        e->id = node.attribute("id").value();
        e->classes = words(node.attribute("class").value());
        for (pugi::xml_attribute a : node.attributes())
            if (std::strncmp(a.name(), "data-", 5) == 0) e->data.emplace(a.name() + 5, a.value());
        e->label = SvgSource::label(node);
        if (auto [line, col] = source_.position(node.offset_debug()); line > 0)
            e->label += " (line " + std::to_string(line) + ")";
        e->parent = std::move(parent);
        return e;
    }

    std::string name_;
    std::string_view text_;
    SvgSource source_;
    pugi::xml_document doc_;
    std::map<std::string, pugi::xml_node> ids_;
    std::vector<pugi::xml_node> style_elements_;
    StyleCascade style_;
    std::vector<pugi::xml_node> use_chain_;
    int use_expansions_ = 0;
    std::size_t curves_ = 0;
    std::vector<SvgShape> shapes_;
};

}  // namespace

bool SvgElement::has_class(const std::string& word) const {
    return std::find(classes.begin(), classes.end(), word) != classes.end();
}

std::vector<SvgShape> read_svg_shapes(std::string_view text, const std::string& name) {
    return SvgShapeReader(name, text).read();
}

}  // namespace acanthus::detail
