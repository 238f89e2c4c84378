// dartfill: the fill-gap method against naive dart throwing (Sakurai & Miyata, Table 1), and our
// medial variant, on the same shapes, panel and seed in one run.
//   bench_dartfill [--panel SPEC] [--naive-cancellations N] [--seed S] [--runs K] [--resolution PX]
// Each method runs with seeds S .. S+K-1; elements and seconds are summed over the runs, and
// seconds are CPU time of the fill call, so a loaded machine does not skew the ratio.
// Last line: {"benchmark":"dartfill", ...}.
#include <acanthus/dartfill.hpp>
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <string>

using namespace acanthus;

namespace {

// The three concave pebbles of rules/pebbles.acr.
dartfill::ShapeSet pebbles() {
    dartfill::ShapeSet set;
    set.add_path("bean",
                 "M 0 7 C 0 0 8 -2 12 2 C 14 4 16 4 18 2 C 22 -1 27 4 25 10 "
                 "C 23 16 4 17 0 7 Z");
    set.add_path("peanut",
                 "M 0 6 C 0 -1 10 -1 12 3 C 14 -1 24 -1 24 6 C 24 13 14 13 12 9 "
                 "C 10 13 0 13 0 6 Z");
    set.add_path("kidney",
                 "M 2 0 C 10 -3 20 2 21 10 C 21 14 17 15 15 12 C 13 9 8 9 6 13 "
                 "C 4 16 -1 14 0 9 C 0 5 -1 1 2 0 Z");
    return set;
}

struct Run {
    std::size_t elements = 0;
    double seconds = 0;
    double coverage = 0;
    long trials = 0;
};

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Run measure(const dartfill::ShapeSet& shapes, const Region& region, dartfill::Options options,
            dartfill::Method method, std::uint64_t seed, int runs) {
    options.method = method;
    Run total;
    for (int k = 0; k < runs; ++k) {
        double start = cpu_seconds();
        dartfill::FillResult r = dartfill::fill(shapes, region, options, seed + k);
        double seconds = cpu_seconds() - start;
        total.elements += r.placements.size();
        total.seconds += seconds;
        total.coverage += r.stats.coverage / runs;
        total.trials += r.stats.trials;
        std::printf(
            "%-8s seed %3llu  elements %5zu  cpu seconds %8.4f  coverage %.3f  trials %ld\n",
            std::string(dartfill::to_string(method)).c_str(),
            static_cast<unsigned long long>(seed + k), r.placements.size(), seconds,
            r.stats.coverage, r.stats.trials);
    }
    return total;
}

}  // namespace

int main(int argc, char** argv) {
    std::string panel = "rect:300,300";
    dartfill::Options options;
    std::uint64_t seed = 1;
    int runs = 5;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::string flag = argv[i];
        const char* value = argv[i + 1];
        if (flag == "--panel")
            panel = value;
        else if (flag == "--naive-cancellations")
            options.naive_cancellations = std::atol(value);
        else if (flag == "--seed")
            seed = std::strtoull(value, nullptr, 10);
        else if (flag == "--resolution")
            options.resolution = std::atoi(value);
        else if (flag == "--runs")
            runs = std::max(1, std::atoi(value));
        else {
            std::fprintf(stderr, "bench_dartfill: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    try {
        Region region = Region::from_argument(panel);
        dartfill::ShapeSet shapes = pebbles();
        std::printf(
            "panel %s, %zu shapes, naive stops after %ld consecutive cancellations, "
            "%d runs\n",
            panel.c_str(), shapes.size(), options.naive_cancellations, runs);
        Run naive = measure(shapes, region, options, dartfill::Method::naive, seed, runs);
        Run gap = measure(shapes, region, options, dartfill::Method::fill_gap, seed, runs);
        Run third = measure(shapes, region, options, dartfill::Method::medial, seed, runs);
        std::printf(
            "{\"benchmark\":\"dartfill\",\"panel\":\"%s\",\"runs\":%d,\"naive_elements\":%zu,"
            "\"naive_seconds\":%.4f,\"naive_coverage\":%.4f,\"fillgap_elements\":%zu,"
            "\"fillgap_seconds\":%.4f,\"fillgap_coverage\":%.4f,\"speedup\":%.2f,"
            "\"fillgap_element_ratio\":%.3f,\"third_method\":\"medial\",\"third_elements\":%zu,"
            "\"third_seconds\":%.4f,\"third_coverage\":%.4f,\"third_speedup\":%.2f}\n",
            panel.c_str(), runs, naive.elements, naive.seconds, naive.coverage, gap.elements,
            gap.seconds, gap.coverage, naive.seconds / gap.seconds,
            static_cast<double>(gap.elements) / static_cast<double>(naive.elements), third.elements,
            third.seconds, third.coverage, naive.seconds / third.seconds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_dartfill: %s\n", e.what());
        return 1;
    }
    return 0;
}
