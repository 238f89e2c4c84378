// The growth loop at 1024 px: the dots pattern of Appendix A filling a 1000 x 1000 square.
// Measures the incremental engine's elements per second, its cost per element early (around
// 2,000 elements) and late (around 20,000), and the reference engine (whole distance field and
// full candidate scan every iteration) over the first elements of the same run, checking that
// both placed the same elements. Last line: one JSON object.
//
//   bench_growth_loop [--reference-elements N] [--resolution PX] [--png OUT.png]
// ACANTHUS_BENCH_TRACE=1 prints the time at every 1000th iteration on stderr.
#include <sys/resource.h>

#include <acanthus/growth.hpp>
#include <acanthus/region.hpp>
#include <acanthus/render.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "fixtures/dots_pattern.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Sample {
    long elements;
    double seconds;
};

double peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// Seconds per element between the samples nearest to `from` and `to` elements.
double cost_between(const std::vector<Sample>& samples, long from, long to) {
    const Sample* a = nullptr;
    const Sample* b = nullptr;
    for (const Sample& s : samples) {
        if (!a || std::labs(s.elements - from) < std::labs(a->elements - from)) a = &s;
        if (!b || std::labs(s.elements - to) < std::labs(b->elements - to)) b = &s;
    }
    if (!a || !b || b->elements <= a->elements) return -1;
    return (b->seconds - a->seconds) / static_cast<double>(b->elements - a->elements);
}

bool same_element(const acanthus::Element& a, const acanthus::Element& b) {
    if (a.id != b.id || a.type().name != b.type().name || a.proxy_count() != b.proxy_count())
        return false;
    if ((a.parent ? a.parent->id : -1) != (b.parent ? b.parent->id : -1)) return false;
    if (a.type().name == "dot") {
        const auto& p = static_cast<const dots::dot&>(a).p0;
        const auto& q = static_cast<const dots::dot&>(b).p0;
        return p.center == q.center && p.radius == q.radius;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    long reference_elements = 1000;
    int resolution = 1024;
    std::string png;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--reference-elements" && k + 1 < argc) {
            reference_elements = std::atol(argv[++k]);
        } else if (arg == "--resolution" && k + 1 < argc) {
            resolution = std::atoi(argv[++k]);
        } else if (arg == "--png" && k + 1 < argc) {
            png = argv[++k];
        } else {
            std::fprintf(stderr,
                         "usage: %s [--reference-elements N] [--resolution PX] [--png OUT.png]\n",
                         argv[0]);
            return 2;
        }
    }

    const acanthus::Pattern pattern = dots::pattern();
    const acanthus::Region region = acanthus::Region::from_spec("rect:1000,1000");

    // Incremental engine, grown until the square is full.
    acanthus::GrowthOptions options;
    options.resolution = resolution;
    dots::dot_count = 0;
    acanthus::GrowthEngine engine(pattern, region, options);
    std::vector<Sample> samples;
    const auto start = Clock::now();
    engine.on_progress([&](long, long elements) {
        samples.push_back({elements, std::chrono::duration<double>(Clock::now() - start).count()});
    });
    engine.run();
    const auto& stats = engine.stats();
    const auto placed = engine.elements();
    const long elements = static_cast<long>(placed.size());
    const double eps = static_cast<double>(elements) / stats.seconds;
    const double cost_2k = cost_between(samples, 1000, 3000);
    const double cost_20k = cost_between(samples, 19000, 21000);
    std::fprintf(stderr,
                 "incremental: %ld elements, %ld iterations in %.3f s (%s), %.0f elements/s\n",
                 elements, stats.iterations, stats.seconds, stats.stop_reason.c_str(), eps);
    std::fprintf(stderr, "  seconds per element around 2k: %.3g, around 20k: %.3g\n", cost_2k,
                 cost_20k);
    const double incremental_rss = peak_rss_mb();
    if (std::getenv("ACANTHUS_BENCH_TRACE"))
        for (const Sample& s : samples)
            std::fprintf(stderr, "  %ld elements at %.3f s\n", s.elements, s.seconds);

    // Reference engine over the first elements of the same growth.
    options.reference_engine = true;
    options.max_elements = reference_elements;
    dots::dot_count = 0;
    acanthus::GrowthEngine reference(pattern, region, options);
    reference.run();
    const auto ref_placed = reference.elements();
    const double ref_eps = static_cast<double>(ref_placed.size()) / reference.stats().seconds;
    bool identical = ref_placed.size() <= placed.size();
    for (std::size_t k = 0; identical && k < ref_placed.size(); ++k)
        identical = same_element(*ref_placed[k], *placed[k]);
    // The incremental engine's rate over the same first elements, for comparison.
    double inc_first = -1;
    for (const Sample& s : samples)
        if (s.elements >= static_cast<long>(ref_placed.size())) {
            inc_first = static_cast<double>(s.elements) / s.seconds;
            break;
        }
    std::fprintf(stderr, "reference: %zu elements in %.3f s, %.1f elements/s; same elements: %s\n",
                 ref_placed.size(), reference.stats().seconds, ref_eps, identical ? "yes" : "NO");

    if (!png.empty()) {
        acanthus::RenderOptions render;
        render.style = "order";
        render.width = 1024;
        acanthus::render_to_file(png, pattern, region, placed, render);
    }

    std::printf(
        "{\"benchmark\":\"growth-loop\",\"elements\":%ld,\"iterations\":%ld,\"resolution\":%d,"
        "\"elements_per_second\":%.1f,\"reference_elements\":%zu,\"reference_elements_per_second\":"
        "%.3f,"
        "\"speedup\":%.1f,\"incremental_elements_per_second_same_elements\":%.1f,"
        "\"identical_to_reference\":%s,\"seconds_per_element_2k\":%.4g,\"seconds_per_element_20k\":"
        "%.4g,"
        "\"peak_rss_mb\":%.1f,\"incremental_peak_rss_mb\":%.1f}\n",
        elements, stats.iterations, resolution, eps, ref_placed.size(), ref_eps, eps / ref_eps,
        inc_first, identical ? "true" : "false", cost_2k, cost_20k, peak_rss_mb(), incremental_rss);
    return identical ? 0 : 1;
}
