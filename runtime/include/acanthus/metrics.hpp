// Extra sections of the program's --metrics JSON object, filled by rule libraries while the
// program runs (the growth library's fidelity report, say): the runtime cannot know what a
// library measures, so a library hands over a key and a JSON value as text.
#pragma once

#include <map>
#include <mutex>
#include <string>

namespace acanthus {

namespace detail {
struct MetricsSections {
    std::mutex mutex;
    std::map<std::string, std::string> sections;  // key -> JSON text, in key order
};
// One registry per program (header only, so that no stage below the program owns it).
inline MetricsSections& metrics_sections_registry() {
    static MetricsSections registry;
    return registry;
}
}  // namespace detail

// Sets (or replaces) the section `key` of --metrics to `json`, a complete JSON value. Keys the
// runtime writes itself (elements, rules, seconds, ...) are never replaced.
inline void set_metrics_section(const std::string& key, std::string json) {
    auto& r = detail::metrics_sections_registry();
    std::lock_guard lock(r.mutex);
    r.sections[key] = std::move(json);
}

// A copy of every section set so far, by key.
inline std::map<std::string, std::string> metrics_sections() {
    auto& r = detail::metrics_sections_registry();
    std::lock_guard lock(r.mutex);
    return r.sections;
}

}  // namespace acanthus
