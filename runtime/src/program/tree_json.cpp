// Element tree JSON writer (nlohmann-json, keys in the documented order).
#include "program/tree_json.hpp"

#include <nlohmann/json.hpp>

#include "output/output_writer.hpp"
#include "symmetry/image_element.hpp"

namespace acanthus::detail {

namespace {

using Json = nlohmann::ordered_json;

Json point_json(Point p) { return Json::array({p.x, p.y}); }

// Collects user fields in declaration order.
class JsonFieldWriter : public FieldWriter {
  public:
    explicit JsonFieldWriter(Json& out) : out_(out) {}
    using FieldWriter::field;
    void field(std::string_view name, long long value) override { out_[std::string(name)] = value; }
    void field(std::string_view name, double value) override { out_[std::string(name)] = value; }
    void field(std::string_view name, bool value) override { out_[std::string(name)] = value; }
    void field(std::string_view name, const std::string& value) override {
        out_[std::string(name)] = value;
    }

  private:
    Json& out_;
};

Json proxy_json(const Proxy& proxy) {
    Json out = Json::object();
    out["kind"] = std::string(to_string(proxy.kind()));
    switch (proxy.kind()) {
        case ProxyKind::point:
            out["point"] = point_json(static_cast<const PointProxy&>(proxy).point());
            break;
        case ProxyKind::circle: {
            const auto& c = static_cast<const CircleProxy&>(proxy);
            out["center"] = point_json(c.center);
            out["radius"] = c.radius;
            break;
        }
        case ProxyKind::arc: {
            const auto& a = static_cast<const ArcProxy&>(proxy);
            out["center"] = point_json(a.center);
            out["radius"] = a.radius;
            out["start"] = a.start;
            out["end"] = a.end;
            break;
        }
        case ProxyKind::linesegment: {
            const auto& l = static_cast<const LineSegmentProxy&>(proxy);
            out["p0"] = point_json(l.p0);
            out["p1"] = point_json(l.p1);
            break;
        }
        case ProxyKind::bezier: {
            const auto& b = static_cast<const BezierProxy&>(proxy);
            Json c = Json::array();
            for (Point p : b.c) c.push_back(point_json(p));
            out["c"] = std::move(c);
            break;
        }
        case ProxyKind::polygon: {
            Json points = Json::array();
            for (Point p : static_cast<const PolygonProxy&>(proxy).points)
                points.push_back(point_json(p));
            out["points"] = std::move(points);
            break;
        }
    }
    return out;
}

Json element_json(const Element& e) {
    Json out = Json::object();
    out["id"] = e.id;
    out["type"] = e.type().name;
    out["parent"] = e.parent ? Json(e.parent->id) : Json(nullptr);
    out["depth"] = e.depth;
    out["sterile"] = e.sterile;
    Json fields = Json::object();
    JsonFieldWriter writer(fields);
    e.write_fields(writer);
    out["fields"] = std::move(fields);
    Json proxies = Json::array();
    for (std::size_t k = 0; k < e.proxy_count(); ++k) proxies.push_back(proxy_json(e.proxy(k)));
    out["proxies"] = std::move(proxies);
    // Under symmetry: the element this one is an image of, and the transformation (Cairo's
    // matrix order: x' = a x + c y + e, y' = b x + d y + f).
    if (const ImageElement* image = as_image(e)) {
        out["image_of"] = image->original().id;
        const auto m = image->transform().matrix();
        out["transform"] = Json::array({m[0], m[1], m[2], m[3], m[4], m[5]});
    }
    return out;
}

}  // namespace

std::string tree_json(const Region& region, const std::vector<const Element*>& elements) {
    Rect b = region.bounds();
    Json root = Json::object();
    root["region"] =
        Json{{"bounds", Json::array({b.x0, b.y0, b.x1, b.y1})}, {"area", region.area()}};
    Json list = Json::array();
    for (const Element* e : elements) list.push_back(element_json(*e));
    root["elements"] = std::move(list);
    return root.dump() + "\n";
}

void write_tree_json(const std::string& path, const Region& region,
                     const std::vector<const Element*>& elements) {
    std::string text = tree_json(region, elements);
    detail::write_output(path, text);
}

}  // namespace acanthus::detail
