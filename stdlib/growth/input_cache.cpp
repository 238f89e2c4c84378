// References and guides loaded once per path for the whole run (issue 10): the rule body that
// grows and the %draw that draws each motif use the same data.
#include <acanthus/stdlib/growth.hpp>
#include <map>
#include <mutex>

namespace acanthus::growth {

// One load per path for the run: rule bodies and %draw share what they load.
const Reference& load_reference(const std::string& path) {
    static std::mutex mutex;
    static std::map<std::string, Reference> loaded;
    std::lock_guard lock(mutex);
    auto it = loaded.find(path);
    if (it == loaded.end()) it = loaded.emplace(path, Reference::from_file(path)).first;
    return it->second;
}

const Guides& load_guides(const std::string& path) {
    static std::mutex mutex;
    static std::map<std::string, Guides> loaded;
    std::lock_guard lock(mutex);
    auto it = loaded.find(path);
    if (it == loaded.end()) it = loaded.emplace(path, Guides::from_svg_file(path)).first;
    return it->second;
}

}  // namespace acanthus::growth
