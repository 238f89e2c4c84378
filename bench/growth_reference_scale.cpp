// growth with a huge reference: 100,000 elements (a jittered two-symbol lattice, irregular, and
// an exact 3-colour lattice, regular), each grown to its first 1,000 motifs in a rectangle.
// The bar (docs/stdlib/growth.md, "Speed"): under 1 s for the first synthesis call (which also
// works out the reference's lattice and its side of the fidelity report, once), reading the
// reference aside. Prints a line per reference on stderr, last one JSON object: the first call
// and the best of three.
//
//   bench_growth_reference_scale [ELEMENTS]   (default 100000)
#include <acanthus/region.hpp>
#include <acanthus/stdlib/growth.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "stdlib/growth/growth_fixtures.hpp"
#include "stdlib/growth/growth_lattices.hpp"

using namespace acanthus;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Figures {
    std::string name;
    long elements = 0;
    double analyse_seconds = 0;      // Reference::from_elements: Delaunay, rings
    double first_seconds = 0;        // the first synthesize(): with the reference's one-time
                                     // work (its lattice, its side of the fidelity report)
    double grow_seconds = INFINITY;  // synthesize(), best of three
    double loop_seconds = 0;         // of which the growth loop (SynthesisStats::seconds)
    long motifs = 0;
    int lattice_sites = 0;
    long interior = 0, defects = 0;
};

Figures measure(const std::string& name, std::vector<growth::ReferenceElement> elements) {
    Figures f;
    f.name = name;
    f.elements = static_cast<long>(elements.size());
    auto t = Clock::now();
    growth::Reference ref = growth::Reference::from_elements(std::move(elements), {}, name);
    f.analyse_seconds = since(t);
    const double a = ref.mean_edge_length();
    // Room for about 1,200 motifs, 3:2; max_elements stops at 1,000.
    const double area = 1200 * a * a * std::sqrt(3.0) / 2;
    const double w = std::sqrt(area * 1.5), h = area / w;
    Region panel = Region::from_spec("rect:" + std::to_string(w) + "," + std::to_string(h));
    growth::Options o;
    o.max_elements = 1000;
    for (int k = 0; k < 3; ++k) {
        t = Clock::now();
        growth::SynthesisResult r = growth::synthesize(ref, panel, o, {}, 1);
        double s = since(t);
        if (k == 0) f.first_seconds = s;
        if (s < f.grow_seconds) {
            f.grow_seconds = s;
            f.loop_seconds = r.stats.seconds;
        }
        f.motifs = static_cast<long>(r.motifs.size());
        f.lattice_sites = r.stats.lattice_sites;
        f.interior = r.fidelity.interior;
        f.defects = r.fidelity.defects;
    }
    std::fprintf(stderr,
                 "%-12s %ld elements: analysed in %.2f s; %ld motifs in %.3f s the first time, "
                 "%.3f s after (loop %.3f s), lattice sites %d, defects %ld of %ld\n",
                 name.c_str(), f.elements, f.analyse_seconds, f.motifs, f.first_seconds,
                 f.grow_seconds, f.loop_seconds, f.lattice_sites, f.defects, f.interior);
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    const long n = argc > 1 ? std::atol(argv[1]) : 100000;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    std::vector<Figures> all;
    all.push_back(
        measure("irregular", growth_fixtures::jittered_lattice(side, side, 10, 1.5, {"a", "b"})));
    all.push_back(measure(
        "regular", growth_lattices::lattice(growth_lattices::Kind::three_colour, side, 10, 3)));
    std::printf("{");
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Figures& f = all[i];
        std::printf(
            "%s\"%s\": {\"elements\": %ld, \"analyse_seconds\": %.3f, "
            "\"first_seconds\": %.3f, \"seconds\": %.3f, \"loop_seconds\": %.3f, "
            "\"motifs\": %ld, \"lattice_sites\": %d, \"defects\": %ld}",
            i ? ", " : "", f.name.c_str(), f.elements, f.analyse_seconds, f.first_seconds,
            f.grow_seconds, f.loop_seconds, f.motifs, f.lattice_sites, f.defects);
    }
    std::printf("}\n");
    return 0;
}
