// The growth loop at poster scale: Appendix A's dots filling a square of about one unit per
// pixel at 1024, 2048 and 4096 px, each grown in a child process of its own so that its peak
// memory is its own; with the exact Euclidean field (the default), then with the paper's
// Manhattan MAT (--distance manhattan). Prints a table on stderr and, last, one JSON object
// with elements per second and peak bytes per buffer pixel at each size and the ratio of cost
// per element at 4096 px to 1024 px, for each metric. Each size is grown --runs times (3 by
// default), the sizes taking turns so that the machine's drift touches them alike; the run of
// median time is reported, with the range of all, and every run must grow the same tree.
//
//   bench_growth_scale [--sizes 1024,2048,4096] [--euclidean-only | --manhattan-only] [--runs N]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures/dots_pattern.hpp"

namespace {

struct Result {
    int resolution = 0;
    acanthus::DistanceMetric metric = acanthus::DistanceMetric::euclidean;
    long elements = 0;
    double seconds = 0;
    long pixels = 0;
    std::uint64_t tree_hash = 0;
    double peak_mb = 0;
    bool ok = false;
    double fastest = 0, slowest = 0;  // seconds over the runs
};

// The run of median time of one size and metric, with the range and the largest peak of all;
// not ok unless every run succeeded with the same tree.
Result median_of(std::vector<Result> runs) {
    std::sort(runs.begin(), runs.end(),
              [](const Result& a, const Result& b) { return a.seconds < b.seconds; });
    Result r = runs[runs.size() / 2];
    r.fastest = runs.front().seconds;
    r.slowest = runs.back().seconds;
    for (const Result& x : runs) {
        r.ok = r.ok && x.ok && x.tree_hash == r.tree_hash && x.elements == r.elements;
        r.peak_mb = std::max(r.peak_mb, x.peak_mb);
    }
    return r;
}

// FNV-1a over ids, parents and the bits of every dot's centre and radius: equal hashes at a
// size mean the same tree as another build grew.
std::uint64_t tree_hash(const std::vector<const acanthus::Element*>& elements) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ull;
    };
    for (const acanthus::Element* e : elements) {
        const int parent = e->parent ? e->parent->id : -1;
        mix(&e->id, sizeof e->id);
        mix(&parent, sizeof parent);
        if (e->type().name == "dot") {
            const auto& c = static_cast<const dots::dot&>(*e).p0;
            mix(&c.center.x, sizeof(double));
            mix(&c.center.y, sizeof(double));
            mix(&c.radius, sizeof(double));
        }
    }
    return h;
}

// Grows one size in this process and writes "elements seconds pixels hash" to fd.
int grow_one(int resolution, acanthus::DistanceMetric metric, int fd) {
    const double side = 1000.0 * resolution / 1024;
    const acanthus::Pattern pattern = dots::pattern();
    const acanthus::Region region =
        acanthus::Region::from_spec("rect:" + std::to_string(side) + "," + std::to_string(side));
    acanthus::GrowthOptions options;
    options.resolution = resolution;
    options.distance = metric;
    dots::dot_count = 0;
    acanthus::GrowthEngine engine(pattern, region, options);
    engine.run();
    const auto placed = engine.elements();
    const auto& g = engine.grid();
    const std::string line = std::to_string(placed.size()) + " " +
                             std::to_string(engine.stats().seconds) + " " +
                             std::to_string(static_cast<long>(g.width) * g.height) + " " +
                             std::to_string(tree_hash(placed)) + "\n";
    return write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size()) ? 0 : 1;
}

Result run_child(int resolution, acanthus::DistanceMetric metric) {
    Result r;
    r.resolution = resolution;
    r.metric = metric;
    int fds[2];
    if (pipe(fds) != 0) return r;
    const pid_t pid = fork();
    if (pid < 0) return r;
    if (pid == 0) {
        close(fds[0]);
        _exit(grow_one(resolution, metric, fds[1]));
    }
    close(fds[1]);
    std::string out;
    char buf[256];
    for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, buf + n);
    close(fds[0]);
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid) return r;
    r.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
    std::istringstream in(out);
    r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
           static_cast<bool>(in >> r.elements >> r.seconds >> r.pixels >> r.tree_hash);
    return r;
}

}  // namespace

// The JSON array of one metric's results; sets the ratio of cost per element 4096 / 1024.
std::string json_sizes(const std::vector<Result>& results, acanthus::DistanceMetric metric,
                       double& ratio) {
    std::string json = "[";
    double cost_first = -1, cost_last = -1;
    for (const Result& r : results) {
        if (r.metric != metric) continue;
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "%s{\"resolution\":%d,\"elements\":%ld,\"seconds\":%.3f,"
                      "\"elements_per_second\":%.1f,\"elements_per_second_range\":[%.1f,%.1f],"
                      "\"peak_rss_mb\":%.1f,\"bytes_per_pixel\":%.2f,\"tree_hash\":\"%016llx\"}",
                      json.size() > 1 ? "," : "", r.resolution, r.elements, r.seconds,
                      r.ok ? r.elements / r.seconds : 0.0, r.ok ? r.elements / r.slowest : 0.0,
                      r.ok ? r.elements / r.fastest : 0.0, r.peak_mb,
                      r.ok ? r.peak_mb * 1024 * 1024 / static_cast<double>(r.pixels) : 0.0,
                      static_cast<unsigned long long>(r.tree_hash));
        json += buf;
        if (r.ok && r.resolution == 1024) cost_first = r.seconds / r.elements;
        if (r.ok && r.resolution == 4096) cost_last = r.seconds / r.elements;
    }
    ratio = cost_first > 0 && cost_last > 0 ? cost_last / cost_first : -1.0;
    return json + "]";
}

int main(int argc, char** argv) {
    using acanthus::DistanceMetric;
    std::vector<int> sizes = {1024, 2048, 4096};
    std::vector<DistanceMetric> metrics = {DistanceMetric::euclidean, DistanceMetric::manhattan};
    int runs = 3;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--sizes" && k + 1 < argc) {
            sizes.clear();
            std::istringstream in(argv[++k]);
            for (std::string s; std::getline(in, s, ',');) sizes.push_back(std::atoi(s.c_str()));
        } else if (arg == "--euclidean-only") {
            metrics = {DistanceMetric::euclidean};
        } else if (arg == "--manhattan-only") {
            metrics = {DistanceMetric::manhattan};
        } else if (arg == "--runs" && k + 1 < argc && std::atoi(argv[k + 1]) > 0) {
            runs = std::atoi(argv[++k]);
        } else {
            std::fprintf(stderr,
                         "usage: %s [--sizes 1024,2048,4096] [--euclidean-only | --manhattan-only] "
                         "[--runs N]\n",
                         argv[0]);
            return 2;
        }
    }

    std::vector<Result> results;
    std::fprintf(stderr, "%-10s %-18s %10s %9s %11s %17s %10s %8s\n", "metric", "panel, resolution",
                 "elements", "growth", "elements/s", "(all runs)", "peak", "B/pixel");
    bool ok = true;
    for (DistanceMetric metric : metrics) {
        std::vector<std::vector<Result>> per_size(sizes.size());
        for (int round = 0; round < runs; ++round)
            for (std::size_t k = 0; k < sizes.size(); ++k)
                per_size[k].push_back(run_child(sizes[k], metric));
        for (std::size_t k = 0; k < sizes.size(); ++k) {
            const Result r = median_of(per_size[k]);
            ok = ok && r.ok;
            results.push_back(r);
            const std::string name(acanthus::to_string(metric));
            if (!r.ok) {
                std::fprintf(stderr, "%-10s %d px: a run failed or grew another tree\n",
                             name.c_str(), sizes[k]);
                continue;
            }
            const int side = static_cast<int>(1000.0 * sizes[k] / 1024 + 0.5);
            std::fprintf(stderr,
                         "%-10s %5d^2, %5d px %10ld %8.2fs %11.0f %8.0f-%-8.0f %7.0f MB %8.1f\n",
                         name.c_str(), side, sizes[k], r.elements, r.seconds,
                         r.elements / r.seconds, r.elements / r.slowest, r.elements / r.fastest,
                         r.peak_mb, r.peak_mb * 1024 * 1024 / static_cast<double>(r.pixels));
        }
    }

    double ratio = -1, manhattan_ratio = -1;
    std::string json = "{\"benchmark\":\"growth-scale\",\"pattern\":\"dots\",\"sizes\":" +
                       json_sizes(results, DistanceMetric::euclidean, ratio);
    char buf[160];
    std::snprintf(buf, sizeof buf, ",\"cost_per_element_ratio_4096_1024\":%.3f", ratio);
    json += buf;
    if (std::find(metrics.begin(), metrics.end(), DistanceMetric::manhattan) != metrics.end()) {
        json += ",\"manhattan\":" + json_sizes(results, DistanceMetric::manhattan, manhattan_ratio);
        std::snprintf(buf, sizeof buf, ",\"manhattan_cost_per_element_ratio_4096_1024\":%.3f",
                      manhattan_ratio);
        json += buf;
    }
    std::printf("%s}\n", json.c_str());
    return ok ? 0 : 1;
}
