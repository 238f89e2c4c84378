// The --metrics JSON object.
#include "program/metrics_json.hpp"

#include <acanthus/metrics.hpp>
#include <nlohmann/json.hpp>

namespace acanthus::detail {

std::string metrics_json(const Pattern& pattern, const GrowthStats& stats, long elements,
                         double coverage, double total_seconds, double render_seconds,
                         bool reference_engine, const Region* region) {
    using Json = nlohmann::ordered_json;
    Json rules = Json::array();
    for (std::size_t i = 0; i < pattern.rules.size(); ++i) {
        RuleStats counts = i < stats.rules.size() ? stats.rules[i] : RuleStats{};
        rules.push_back(Json{{"rule", pattern.rules[i].name},
                             {"line", pattern.rules[i].line},
                             {"successes", counts.successes},
                             {"failures", counts.failures}});
    }
    Json out = Json::object();
    out["elements"] = elements;
    out["iterations"] = stats.iterations;
    out["rules"] = std::move(rules);
    out["exclude_points"] = stats.exclude_points;
    out["coverage"] = coverage;
    out["seconds"] =
        Json{{"total", total_seconds}, {"growth", stats.seconds}, {"render", render_seconds}};
    out["engine"] = reference_engine ? "reference" : "incremental";
    if (region) {
        const Rect b = region->bounds();
        out["region"] =
            Json{{"bounds", Json::array({b.x0, b.y0, b.x1, b.y1})}, {"area", region->area()}};
    }
    // Sections the rule libraries added (acanthus/metrics.hpp), after the runtime's own keys.
    for (const auto& [key, text] : metrics_sections())
        if (!out.contains(key)) out[key] = Json::parse(text);
    return out.dump();
}

}  // namespace acanthus::detail
