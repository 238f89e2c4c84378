// growth: example-based element arrangement after Ijiri, Mech, Igarashi and Miller, "An
// Example-based Procedural System for Element Arrangement" (2008). A small reference arrangement
// is analysed into 1-rings and grown into a panel seed by seed (docs/stdlib/growth.md).
#pragma once

#include <acanthus/body.hpp>
#include <acanthus/point.hpp>
#include <acanthus/region.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace acanthus::growth {

enum class Mode {
    none,      // section 5.3: reference rings are used as they are
    rotation,  // section 5.3: each ring is turned to its best fit with the target neighbourhood
    flow,      // section 5.3: the reference's x axis follows a field interpolated from strokes
};
// "none" (or "non-rotation"), "rotation", "flow"; throws InputError otherwise.
Mode parse_mode(std::string_view text);
std::string_view to_string(Mode mode);

// One element of a reference arrangement. size <= 0 means the default collision radius,
// 0.35 x the mean reference edge length.
struct ReferenceElement {
    std::string symbol;
    std::string sub;
    Point position;
    double angle = 0;  // radians
    double size = 0;
};

namespace detail {
struct ReferenceData;
}

// An analysed reference arrangement: Delaunay connectivity without skewed triangles, the author's
// flips applied, a counter-clockwise 1-ring per element. Bad input throws InputError naming the
// source and, where there is one, the element index.
class Reference {
  public:
    // {"elements": [{"symbol", "x", "y", optional "sub", "angle", "size"}], "flips": [[i, j]]}
    static Reference from_json_file(const std::string& path);
    static Reference from_json_string(std::string_view text, const std::string& name);
    static Reference from_elements(std::vector<ReferenceElement> elements,
                                   std::vector<std::pair<int, int>> flips = {},
                                   const std::string& name = "reference");

    std::size_t size() const;
    const ReferenceElement& element(std::size_t i) const;
    // Collision radius of element i (its size, or the default).
    double radius(std::size_t i) const;
    // The kept connectivity edges (i < j, sorted) and each element's neighbours, CCW.
    const std::vector<std::pair<int, int>>& edges() const;
    const std::vector<int>& ring(std::size_t i) const;
    // True for elements on the boundary of the kept triangles: never matched against.
    bool boundary(std::size_t i) const;
    double mean_edge_length() const;
    double shortest_edge_length() const;
    const std::string& name() const;
    const detail::ReferenceData& data() const { return *data_; }

  private:
    explicit Reference(std::shared_ptr<const detail::ReferenceData> data);
    std::shared_ptr<const detail::ReferenceData> data_;
};

struct Options {
    Mode mode = Mode::none;
    bool relax = true;      // section 5.5 least squares after every growth step
    double w1 = 1.0;        // position difference
    double w2 = 1.0;        // symbol differs
    double w3 = 100.0;      // sub-id the same (the paper: avoids repeating one element)
    long max_elements = 0;  // 0: until no seed is left
    std::map<std::string, int> priority;  // per symbol, higher grows first (default 0)
    double priority_radius = 5.0;         // x mean edge length: where a higher priority blocks
    double short_factor = 0.5;            // l_short = factor x shortest reference edge
    double angle_factor = 0.5;            // drop a new edge under factor x the original angle
    double long_factor = 1.5;             // l_long = factor x the original edge
    double relax_radius = 3.0;            // x mean edge length: the window each step re-solves
    double scale_min = 1.0;               // random scale per motif, uniform
    double scale_max = 1.0;
    double angle_jitter = 0.0;  // radians: random turn of each motif, uniform in +-jitter
    // Flow mode: polylines whose direction (first point to last) the field follows; RBF
    // interpolated between them. At least one is needed in flow mode.
    std::vector<std::vector<Point>> flow_strokes;
};

// One synthesized element: the reference element `source` copied at `position`, turned by
// `angle` (its reference angle plus the ring's rotation), its collision circle `radius`.
struct Motif {
    Point position;
    std::string symbol;
    std::string sub;
    double angle = 0;
    double scale = 1;
    double radius = 0;
    int source = -1;
};

struct SynthesisStats {
    long steps = 0;      // seeds taken from the queue
    long seeds = 0;      // seeds made (start, ring and l_long seeds)
    long dropped = 0;    // seeds dropped: outside, no match, motif does not fit
    long merged = 0;     // l_short merges
    double seconds = 0;  // wall time (reported only, never used)
    double relax_seconds = 0;
};

struct SynthesisResult {
    std::vector<Motif> motifs;
    std::vector<std::pair<int, int>> edges;  // connectivity between motifs (indices), i < j
    SynthesisStats stats;
};

// Grows the reference in a whole region from `starts` (none: the centre of the largest inscribed
// circle). Deterministic for the same inputs and `seed`.
SynthesisResult synthesize(const Reference& reference, const Region& region, const Options& options,
                           const std::vector<Point>& starts, std::uint64_t seed);
// Inside a rule body: grows from `start` in the room the ornament leaves (the panel and placed
// elements through the running Environment), with the program's --rng-seed. Throws
// std::logic_error outside a rule body.
SynthesisResult synthesize(const Reference& reference, const Options& options, Point start);
// As above, starting at the centre of the body's empty circle.
SynthesisResult synthesize(const Reference& reference, const Options& options);

// Inside a rule body: one element of type T per motif (T has a circle proxy p0 and fields symbol,
// sub, angle, scale and source, as `motif` in growth.acr), each added with new_child(). Returns
// how many were added.
template <class T>
int add_motifs(const SynthesisResult& result, bool sterile = true) {
    int added = 0;
    for (const Motif& m : result.motifs) {
        T* e = new T;
        e->p0.set(m.position, m.radius);
        e->symbol = m.symbol;
        e->sub = m.sub;
        e->angle = m.angle;
        e->scale = m.scale;
        e->source = m.source;
        e->sterile = sterile;
        acanthus::body::new_child(*e);
        ++added;
    }
    return added;
}

}  // namespace acanthus::growth
