// growth synthesis (Ijiri et al.) with and without relaxation: 1,000 to 10,000 elements of an
// irregular two-symbol reference in a rectangle. The bar (docs/stdlib/growth.md): 10,000 elements
// with relaxation in under 5 s, cost per element flat from 1,000 to 10,000. Best of three runs.
// Then the relaxation variants, and Options::two_ring against 1-ring matching. Last, end to end:
// rules/arrangement.acr built into a program and run on the stones reference in a 300 x 200
// rectangle at 512, 1024 and 2048 px (program_* figures, medians of three runs).
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "program_run.hpp"
#include "stdlib/growth/growth_fixtures.hpp"

using namespace acanthus;

namespace {

struct Run {
    long elements = 0;
    double seconds = 0;
};

Run best_of_three(const growth::Reference& ref, long count, bool relax) {
    // A rectangle of about count / density, 3:2; max_elements stops at `count` exactly.
    const double a = ref.mean_edge_length();
    const double area = 1.1 * static_cast<double>(count) * a * a * std::sqrt(3.0) / 2;
    const double w = std::sqrt(area * 1.5), h = area / w;
    Region panel = Region::from_spec("rect:" + std::to_string(w) + "," + std::to_string(h));
    growth::Options o;
    o.relax = relax;
    o.max_elements = count;
    Run best{0, INFINITY};
    for (int k = 0; k < 3; ++k) {
        growth::SynthesisResult r = growth::synthesize(ref, panel, o, {}, 1);
        best.elements = static_cast<long>(r.motifs.size());
        best.seconds = std::min(best.seconds, r.stats.seconds);
    }
    return best;
}

struct Relaxation {
    const char* name;
    double seconds;
    double link_error;  // SynthesisStats::link_error
};

// The paper's global solve per step against the windowed one (and none), on the irregular
// reference: time, and how far the result is from the reference's offsets, with every link
// pulled to its offset (relax_slack 0), what eq. 5 minimizes.
std::vector<Relaxation> compare_relaxations() {
    growth::Reference ref = growth::Reference::from_elements(
        growth_fixtures::jittered_lattice(8, 8, 10, 1.5, {"a", "b"}));
    Region panel = Region::from_spec("rect:360,280");
    std::vector<Relaxation> out;
    for (int variant = 0; variant < 3; ++variant) {
        growth::Options o;
        o.max_elements = 1000;
        o.relax = variant > 0;
        o.relax_global = variant == 2;
        o.relax_slack = 0;
        double best = INFINITY;
        growth::SynthesisResult r;
        for (int k = 0; k < 3; ++k) {
            r = growth::synthesize(ref, panel, o, {}, 1);
            best = std::min(best, r.stats.seconds);
        }
        out.push_back({variant == 0   ? "none"
                       : variant == 1 ? "window"
                                      : "global",
                       best, r.stats.link_error});
    }
    return out;
}

struct Matching {
    const char* reference;
    double one_ring, two_ring;        // two_ring_consistency, mean over three seeds
    double one_seconds, two_seconds;  // synthesis time, summed over the seeds
};

// Options::two_ring against the paper's 1-ring matching: how often a grown motif's
// neighbourhood within two spacings appears in the reference, and what it costs.
std::vector<Matching> compare_matchings() {
    std::vector<Matching> out;
    const std::string refs = std::string(ACANTHUS_SOURCE_DIR) + "/examples/references/";
    for (const char* name : {"stripes.json", "tricolour.json", "checker.json", "lattice.json"}) {
        growth::Reference ref = growth::Reference::from_file(refs + name);
        std::vector<growth::ReferenceElement> elements;
        for (std::size_t i = 0; i < ref.size(); ++i) elements.push_back(ref.element(i));
        const double a = ref.mean_edge_length();
        Region panel =
            Region::from_spec("rect:" + std::to_string(20 * a) + "," + std::to_string(16 * a));
        Matching m{name, 0, 0, 0, 0};
        for (unsigned long long seed = 1; seed <= 3; ++seed)
            for (bool two : {false, true}) {
                growth::Options o;
                o.two_ring = two;
                growth::SynthesisResult r = growth::synthesize(ref, panel, o, {}, seed);
                std::vector<growth_fixtures::Placed> placed;
                for (const growth::Motif& motif : r.motifs)
                    placed.push_back({motif.position, motif.symbol});
                double c = growth_fixtures::two_ring_consistency(elements, placed) / 3;
                (two ? m.two_ring : m.one_ring) += c;
                (two ? m.two_seconds : m.one_seconds) += r.stats.seconds;
            }
        out.push_back(m);
    }
    return out;
}

constexpr int kResolutions[] = {512, 1024, 2048};

// The arrangement program at each resolution, the sizes taking turns so that a change in the
// machine's load touches all of them alike.
std::vector<bench::ProgramMedian> program_resolutions() {
    bench::TempDir dir;
    const bench::fs::path program = bench::build_program("arrangement", dir.path());
    const std::string reference =
        "reference=" + std::string(ACANTHUS_SOURCE_DIR) + "/examples/references/stones.json";
    auto args = [&](int resolution) {
        return std::vector<std::string>{"--param",      reference,
                                        "--region",     "rect:300,200",
                                        "--resolution", std::to_string(resolution),
                                        "-o",           (dir.path() / "arrangement.png").string()};
    };
    bench::run_program(program, args(512));  // warm up (page cache, libraries)
    std::vector<bench::ProgramMedian> out(std::size(kResolutions));
    for (int k = 0; k < 3; ++k)
        for (std::size_t i = 0; i < out.size(); ++i)
            out[i].add(bench::run_program(program, args(kResolutions[i])),
                       "arrangement at " + std::to_string(kResolutions[i]) + " px");
    return out;
}

}  // namespace

int main() {
    growth::Reference ref = growth::Reference::from_elements(
        growth_fixtures::jittered_lattice(8, 8, 10, 1.5, {"a", "b"}));
    std::printf("%8s %10s %12s %14s %14s\n", "target", "elements", "seconds", "no relax s",
                "us/element");
    Run small, large, large_no_relax;
    for (long n : {1000L, 3000L, 10000L}) {
        Run with = best_of_three(ref, n, true), without = best_of_three(ref, n, false);
        std::printf("%8ld %10ld %12.3f %14.3f %14.1f\n", n, with.elements, with.seconds,
                    without.seconds, 1e6 * with.seconds / static_cast<double>(with.elements));
        if (n == 1000) small = with;
        if (n == 10000) large = with, large_no_relax = without;
    }
    std::vector<Relaxation> relax = compare_relaxations();
    for (const Relaxation& r : relax)
        std::printf(
            "relaxation %-7s 1,000 elements of the irregular reference: %.3f s, link error %.4f\n",
            r.name, r.seconds, r.link_error);
    std::vector<Matching> matching = compare_matchings();
    std::string matching_json;
    for (const Matching& m : matching) {
        std::printf(
            "matching %-15s 2-ring consistency 1-ring %.3f (%.2f s), 2-ring %.3f (%.2f s)\n",
            m.reference, m.one_ring, m.one_seconds, m.two_ring, m.two_seconds);
        char buffer[200];
        std::snprintf(buffer, sizeof buffer, "%s\"%s\": [%.3f, %.3f, %.3f]",
                      matching_json.empty() ? "" : ", ", m.reference, m.one_ring, m.two_ring,
                      m.two_seconds / m.one_seconds);
        matching_json += buffer;
    }
    std::vector<bench::ProgramMedian> program;
    try {
        program = program_resolutions();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_growth: %s\n", e.what());
        return 1;
    }
    std::string program_json;
    for (std::size_t i = 0; i < program.size(); ++i) {
        const bench::ProgramMedian& p = program[i];
        std::printf("program arrangement %4d px: %ld elements, growth %.4f s, wall %.4f s\n",
                    kResolutions[i], p.elements, p.growth_seconds, p.wall_seconds);
        char buffer[300];
        std::snprintf(buffer, sizeof buffer,
                      ", \"program_elements_%d\": %ld, \"program_growth_seconds_%d\": %.4f, "
                      "\"program_wall_seconds_%d\": %.4f",
                      kResolutions[i], p.elements, kResolutions[i], p.growth_seconds,
                      kResolutions[i], p.wall_seconds);
        program_json += buffer;
    }
    const double per_small = small.seconds / static_cast<double>(small.elements);
    const double per_large = large.seconds / static_cast<double>(large.elements);
    std::printf(
        "{\"bench\": \"growth\", \"elements\": %ld, \"seconds\": %.4f, \"seconds_no_relax\": "
        "%.4f, \"us_per_element_1000\": %.2f, \"us_per_element_10000\": %.2f, "
        "\"cost_ratio_10000_to_1000\": %.3f, \"target_seconds\": 5, \"relax_1000\": {"
        "\"none\": [%.3f, %.4f], \"window\": [%.3f, %.4f], \"global\": [%.3f, %.4f]}, "
        "\"two_ring\": {%s}%s, \"program_ratio_2048_to_512\": %.3f, \"program_runs\": %zu, "
        "\"program_target_ratio_2048_to_512\": 1.5}\n",
        large.elements, large.seconds, large_no_relax.seconds, 1e6 * per_small, 1e6 * per_large,
        per_large / per_small, relax[0].seconds, relax[0].link_error, relax[1].seconds,
        relax[1].link_error, relax[2].seconds, relax[2].link_error, matching_json.c_str(),
        program_json.c_str(), program[2].growth_seconds / program[0].growth_seconds,
        program[0].growth.size());
    return large.seconds < 5 ? 0 : 1;
}
