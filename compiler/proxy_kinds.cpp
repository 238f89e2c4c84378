#include "proxy_kinds.hpp"

#include <array>

namespace acanthus {

namespace {

constexpr std::array<ProxyKindInfo, 6> kKinds{{
    {"point", "point", "acanthus::PointProxy"},
    {"circle", "circle", "acanthus::CircleProxy"},
    {"arc", "arc", "acanthus::ArcProxy"},
    {"linesegment", "linesegment", "acanthus::LineSegmentProxy"},
    {"bezier", "bezier", "acanthus::BezierProxy"},
    {"polygon", "polygon", "acanthus::PolygonProxy"},
}};

}  // namespace

std::optional<ProxyKindInfo> find_proxy_kind(std::string_view name) {
    for (const ProxyKindInfo& k : kKinds) {
        if (k.name == name) return k;
    }
    return std::nullopt;
}

std::string_view proxy_kind_list() { return "point, circle, arc, linesegment, bezier, polygon"; }

}  // namespace acanthus
