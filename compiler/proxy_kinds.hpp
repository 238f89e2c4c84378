// The proxy kinds a %element header may name, and the runtime classes behind them.
#pragma once

#include <optional>
#include <string_view>

namespace acanthus {

struct ProxyKindInfo {
    std::string_view name;        // as written in rule files: "bezier"
    std::string_view enumerator;  // acanthus::ProxyKind enumerator: "bezier"
    std::string_view cpp_class;   // "acanthus::BezierProxy"
};

std::optional<ProxyKindInfo> find_proxy_kind(std::string_view name);
// "point, circle, arc, linesegment, bezier, polygon"
std::string_view proxy_kind_list();

}  // namespace acanthus
