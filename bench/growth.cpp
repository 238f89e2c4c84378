// growth synthesis (Ijiri et al.) with and without relaxation: 1,000 to 10,000 elements of an
// irregular two-symbol reference in a rectangle. The bar (DESIGN.md section 12): 10,000 elements
// with relaxation in under 5 s, cost per element flat from 1,000 to 10,000. Best of three runs.
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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
// reference: time, and how far the result is from the reference's offsets.
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
        std::printf("relaxation %-7s 1,000 elements of the irregular reference: %.3f s, link error %.4f\n", r.name,
                    r.seconds, r.link_error);
    const double per_small = small.seconds / static_cast<double>(small.elements);
    const double per_large = large.seconds / static_cast<double>(large.elements);
    std::printf(
        "{\"bench\": \"growth\", \"elements\": %ld, \"seconds\": %.4f, \"seconds_no_relax\": "
        "%.4f, \"us_per_element_1000\": %.2f, \"us_per_element_10000\": %.2f, "
        "\"cost_ratio_10000_to_1000\": %.3f, \"target_seconds\": 5, \"relax_1000\": {"
        "\"none\": [%.3f, %.4f], \"window\": [%.3f, %.4f], \"global\": [%.3f, %.4f]}}\n",
        large.elements, large.seconds, large_no_relax.seconds, 1e6 * per_small, 1e6 * per_large,
        per_large / per_small, relax[0].seconds, relax[0].link_error, relax[1].seconds,
        relax[1].link_error, relax[2].seconds, relax[2].link_error);
    return large.seconds < 5 ? 0 : 1;
}
