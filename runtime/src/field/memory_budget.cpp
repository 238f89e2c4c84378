#include "field/memory_budget.hpp"

#include <sys/resource.h>

#include <acanthus/error.hpp>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace acanthus::detail {
namespace {

// A "Key:   1234 kB" line of a /proc file, in bytes.
std::optional<std::uint64_t> proc_field(const char* file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.compare(0, key.size(), key) != 0 || line.size() <= key.size() ||
            line[key.size()] != ':')
            continue;
        std::istringstream fields(line.substr(key.size() + 1));
        std::uint64_t kb = 0;
        if (fields >> kb) return kb * 1024;
    }
    return std::nullopt;
}

// A number alone in a file (cgroup limits), or nothing ("max", missing).
std::optional<std::uint64_t> file_number(const char* file) {
    std::ifstream in(file);
    std::uint64_t v = 0;
    if (in >> v) return v;
    return std::nullopt;
}

std::string grid_size(const GridFrame& g) {
    return std::to_string(g.width) + " x " + std::to_string(g.height) + " pixels";
}

std::string gigabytes(double bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GB", bytes / 1e9);
    return buf;
}

}  // namespace

std::optional<std::uint64_t> available_memory() {
    std::optional<std::uint64_t> out = proc_field("/proc/meminfo", "MemAvailable");
    auto cap = [&](int resource, const char* used_key) {
        rlimit limit{};
        if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
        const std::uint64_t used = proc_field("/proc/self/status", used_key).value_or(0);
        const std::uint64_t room = limit.rlim_cur > used ? limit.rlim_cur - used : 0;
        out = out ? std::min(*out, room) : room;
    };
    cap(RLIMIT_AS, "VmSize");
    cap(RLIMIT_DATA, "VmData");
    // A container's memory limit (cgroup v2, then v1), less what the group uses already.
    for (const auto& [limit_file, usage_file] :
         {std::pair{"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
          std::pair{"/sys/fs/cgroup/memory/memory.limit_in_bytes",
                    "/sys/fs/cgroup/memory/memory.usage_in_bytes"}}) {
        const std::optional<std::uint64_t> limit = file_number(limit_file);
        if (!limit || *limit >= (std::uint64_t{1} << 60)) continue;  // "max" or no limit
        const std::uint64_t used = file_number(usage_file).value_or(0);
        const std::uint64_t room = *limit > used ? *limit - used : 0;
        out = out ? std::min(*out, room) : room;
        break;
    }
    return out;
}

void check_growth_memory(const GridFrame& grid, int resolution) {
    const double pixels = static_cast<double>(grid.width) * static_cast<double>(grid.height);
    const double need = pixels * kGrowthBytesPerPixel;
    const std::optional<std::uint64_t> room = available_memory();
    if (!room || need <= static_cast<double>(*room)) return;
    char mp[32];
    std::snprintf(mp, sizeof mp, "%.0f", pixels / 1e6);
    throw InputError("--resolution " + std::to_string(resolution) + " needs about " +
                     gigabytes(need) + " for the growth buffer (" + grid_size(grid) + ", " + mp +
                     " megapixels at " + std::to_string(static_cast<int>(kGrowthBytesPerPixel)) +
                     " bytes each) but only " + gigabytes(static_cast<double>(*room)) +
                     " of memory is available; use a lower --resolution");
}

}  // namespace acanthus::detail
