// A proxy of the program's --json tree read back, for the symmetry checkers (check_symmetry,
// check_seams): {"kind": "circle", "center": [x, y], "radius": r} and the other kinds.
#pragma once

#include <acanthus/proxy.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace acanthus::tree_json {

using Json = nlohmann::json;

template <class P>
inline void destroy(Proxy* p) {
    delete static_cast<P*>(p);
}

inline Point point_of(const Json& j) { return {j.at(0).get<double>(), j.at(1).get<double>()}; }

inline std::unique_ptr<Proxy, void (*)(Proxy*)> load_proxy(const Json& j) {
    const std::string kind = j.at("kind");
    if (kind == "point") {
        auto* p = new PointProxy;
        p->set(point_of(j.at("point")));
        return {p, &destroy<PointProxy>};
    }
    if (kind == "circle") {
        auto* p = new CircleProxy;
        p->set(point_of(j.at("center")), j.at("radius").get<double>());
        return {p, &destroy<CircleProxy>};
    }
    if (kind == "arc") {
        auto* p = new ArcProxy;
        p->set(point_of(j.at("center")), j.at("radius").get<double>(), j.at("start").get<double>(),
               j.at("end").get<double>());
        return {p, &destroy<ArcProxy>};
    }
    if (kind == "linesegment") {
        auto* p = new LineSegmentProxy;
        p->set(point_of(j.at("p0")), point_of(j.at("p1")));
        return {p, &destroy<LineSegmentProxy>};
    }
    if (kind == "bezier") {
        auto* p = new BezierProxy;
        const Json& c = j.at("c");
        p->set(point_of(c.at(0)), point_of(c.at(1)), point_of(c.at(2)), point_of(c.at(3)));
        return {p, &destroy<BezierProxy>};
    }
    auto* p = new PolygonProxy;
    std::vector<Point> points;
    for (const Json& q : j.at("points")) points.push_back(point_of(q));
    p->set(std::move(points));
    return {p, &destroy<PolygonProxy>};
}

}  // namespace acanthus::tree_json
