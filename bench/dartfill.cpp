// dartfill: the fill-gap method against naive dart throwing (Sakurai & Miyata, Table 1), and our
// medial variant, on the same shapes, panel and seed in one run.
//   bench_dartfill [--panel SPEC] [--runs K] [--seed S] [--naive-cancellations N]
//                  [--gap-cancellations N] [--exponent n] [--resolution PX]
// Each method runs with seeds S .. S+K-1 (default 1..10); the JSON gives means per run. Seconds
// are CPU time of the fill call (one clock for all methods), so other processes on a loaded
// machine do not skew the ratio; speedup = naive seconds / fill-gap seconds.
// Then end to end: rules/pebbles.acr built into a program and run on the same panel with
// --rng-seed S, its growth (the program's seconds.growth, wall time) and the whole process
// (program_* figures, medians of three runs). Last line: {"benchmark":"dartfill", ...}.
#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <acanthus/stdlib/dartfill.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

#include "program_run.hpp"

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

struct Totals {
    double elements = 0;
    double seconds = 0;
    double coverage = 0;
    double trials = 0;
    int runs = 0;
    // Means over the runs.
    double mean(double Totals::*field) const { return runs ? this->*field / runs : 0; }
};

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// One timed fill; CPU time of the call, the same clock for every method.
void measure(const dartfill::ShapeSet& shapes, const Region& region, dartfill::Options options,
             dartfill::Method method, std::uint64_t seed, Totals& total) {
    options.method = method;
    double start = cpu_seconds();
    dartfill::FillResult r = dartfill::fill(shapes, region, options, seed);
    double seconds = cpu_seconds() - start;
    total.elements += static_cast<double>(r.placements.size());
    total.seconds += seconds;
    total.coverage += r.stats.coverage;
    total.trials += static_cast<double>(r.stats.trials);
    ++total.runs;
    std::printf("%-8s seed %3llu  elements %5zu  cpu seconds %8.4f  coverage %.3f  trials %ld\n",
                std::string(dartfill::to_string(method)).c_str(),
                static_cast<unsigned long long>(seed), r.placements.size(), seconds,
                r.stats.coverage, r.stats.trials);
}

// The pebbles program on `panel`, as a user runs it; `panel` is a spec or an SVG file, which the
// program's --region takes as the bench's --panel does.
bench::ProgramMedian program_pebbles(const std::string& panel, std::uint64_t seed) {
    bench::TempDir dir;
    const bench::fs::path program = bench::build_program("pebbles", dir.path());
    const std::vector<std::string> args{"--region",   panel,
                                        "--rng-seed", std::to_string(seed),
                                        "-o",         (dir.path() / "pebbles.png").string()};
    bench::run_program(program, args);  // warm up (page cache, libraries)
    bench::ProgramMedian m;
    for (int k = 0; k < 3; ++k) m.add(bench::run_program(program, args), "pebbles");
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    std::string panel = "rect:300,300";
    dartfill::Options options;
    std::uint64_t seed = 1;
    int runs = 10;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::string flag = argv[i];
        const char* value = argv[i + 1];
        if (flag == "--panel")
            panel = value;
        else if (flag == "--naive-cancellations")
            options.naive_cancellations = std::atol(value);
        else if (flag == "--gap-cancellations")
            options.gap_cancellations = std::atol(value);
        else if (flag == "--exponent")
            options.exponent = std::atof(value);
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
        const dartfill::Method methods[] = {dartfill::Method::naive, dartfill::Method::fill_gap,
                                            dartfill::Method::medial};
        // One untimed fill per method first (page faults, caches), then the methods in turn on
        // each seed, so a change in the machine's load touches all of them alike.
        for (dartfill::Method m : methods) {
            dartfill::Options warm = options;
            warm.method = m;
            dartfill::fill(shapes, region, warm, seed + runs);
        }
        Totals totals[3];
        for (int k = 0; k < runs; ++k)
            for (int m = 0; m < 3; ++m)
                measure(shapes, region, options, methods[m], seed + k, totals[m]);
        const Totals &naive = totals[0], &gap = totals[1], &third = totals[2];
        const bench::ProgramMedian program = program_pebbles(panel, seed);
        std::printf("program pebbles  elements %5ld  growth seconds %8.4f  wall seconds %8.4f\n",
                    program.elements, program.growth_seconds, program.wall_seconds);
        std::printf(
            "{\"benchmark\":\"dartfill\",\"panel\":\"%s\",\"runs\":%d,\"first_seed\":%llu,"
            "\"naive_cancellations\":%ld,\"gap_cancellations\":%ld,\"candidates\":%d,"
            "\"exponent\":%g,\"naive_elements\":%.1f,\"naive_seconds\":%.5f,"
            "\"naive_trials\":%.0f,\"naive_coverage\":%.4f,\"fillgap_elements\":%.1f,"
            "\"fillgap_seconds\":%.5f,\"fillgap_trials\":%.0f,\"fillgap_coverage\":%.4f,"
            "\"speedup\":%.2f,\"fillgap_element_ratio\":%.3f,\"third_method\":\"medial\","
            "\"third_elements\":%.1f,\"third_seconds\":%.5f,\"third_coverage\":%.4f,"
            "\"third_speedup\":%.2f,\"program_rules\":\"rules/pebbles.acr\","
            "\"program_elements\":%ld,\"program_growth_seconds\":%.5f,"
            "\"program_elements_per_second\":%.0f,\"program_render_seconds\":%.5f,"
            "\"program_wall_seconds\":%.5f,\"program_runs\":%zu}\n",
            panel.c_str(), runs, static_cast<unsigned long long>(seed), options.naive_cancellations,
            options.gap_cancellations, options.candidates, options.exponent,
            naive.mean(&Totals::elements), naive.mean(&Totals::seconds),
            naive.mean(&Totals::trials), naive.mean(&Totals::coverage), gap.mean(&Totals::elements),
            gap.mean(&Totals::seconds), gap.mean(&Totals::trials), gap.mean(&Totals::coverage),
            naive.seconds / gap.seconds, gap.elements / naive.elements,
            third.mean(&Totals::elements), third.mean(&Totals::seconds),
            third.mean(&Totals::coverage), naive.seconds / third.seconds, program.elements,
            program.growth_seconds, static_cast<double>(program.elements) / program.growth_seconds,
            program.render_seconds, program.wall_seconds, program.growth.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_dartfill: %s\n", e.what());
        return 1;
    }
    return 0;
}
