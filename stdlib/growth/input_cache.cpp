// References and guides loaded once per path for the whole run (issue 10): the rule body that
// grows and the %draw that draws each motif use the same data.
#include <acanthus/stdlib/growth.hpp>
#include <map>
#include <mutex>

namespace acanthus::growth {
namespace {

template <class T, class Load>
const T& once_per_path(const std::string& path, Load load) {
    static std::mutex mutex;
    static std::map<std::string, T> loaded;
    std::lock_guard lock(mutex);
    auto it = loaded.find(path);
    if (it == loaded.end()) it = loaded.emplace(path, load(path)).first;
    return it->second;
}

}  // namespace

const Reference& load_reference(const std::string& path) {
    return once_per_path<Reference>(path, Reference::from_file);
}

const Guides& load_guides(const std::string& path) {
    return once_per_path<Guides>(path, Guides::from_svg_file);
}

}  // namespace acanthus::growth
