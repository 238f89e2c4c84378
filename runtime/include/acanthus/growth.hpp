// The growth engine of Wong et al. section 4.1: largest empty circle, candidate parents, rules.
#pragma once

#include <acanthus/distance_metric.hpp>
#include <acanthus/grid_frame.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace acanthus {

struct GrowthOptions {
    int resolution = 512;    // render buffer pixels on the longer side of R's bounds
    double epsilon = -1;     // candidate-parent distance; < 0 means 2 pixels
    double min_radius = -1;  // smallest empty circle; < 0 means 1 pixel
    long max_elements = 1000000;
    long max_iterations = 10000000;
    double time_limit = 0;          // seconds of growth; 0 means none
    bool reference_engine = false;  // recompute the whole distance field every iteration
    // Metric of the distance field and its medial axis: exact Euclidean, or the paper's
    // Manhattan MAT (docs/engine.md, "The Manhattan option").
    DistanceMetric distance = DistanceMetric::euclidean;
    // Buffers of at least this many pixels keep the distance field lazily (exact only where it
    // may decide C), in either metric; smaller ones update it eagerly, which is as fast there.
    // The trees are the same either way (docs/field.md, "The lazy far field").
    long long lazy_field_pixels = 512LL * 512;
    std::vector<Point> seeds;  // empty: centre of the largest inscribed circle
    std::uint64_t rng_seed = 1;
    // Grow under a rosette group (docs/symmetry.md): C is chosen in the fundamental domain and
    // every committed element is placed with its images.
    std::optional<Symmetry> symmetry;
    // Grow under a frieze group along x (docs/symmetry.md, "Friezes").
    std::optional<Frieze> frieze;
    // With a frieze: x is periodic with this length (a closed band); the period is adjusted to
    // divide it, and the region's bounds must start at x = 0 and be this long.
    std::optional<double> wrap_x;
    // Grow under a wallpaper group: the region is the tile, the plane periodic (docs/symmetry.md,
    // "Wallpaper").
    std::optional<Wallpaper> wallpaper;
};

// One iteration as Figure 8 shows it (built only for the iteration asked for).
struct DebugFrame {
    long iteration = 0;
    GridFrame grid;
    std::vector<std::uint8_t> occupancy;          // width*height; 0 free, 1 boundary, 2 element
    std::vector<Circle> eligible;                 // candidate circles that could be chosen
    std::vector<Circle> excluded;                 // candidates rejected by the exclude list
    std::optional<Circle> chosen;                 // C
    std::vector<const Element*> candidates;       // elements within epsilon of C, tried in order
    std::vector<const Element*> placed;           // elements before this iteration
    std::vector<const Element*> added;            // children committed in this iteration
    std::vector<std::pair<Point, Point>> domain;  // the fundamental domain's edges (symmetry)
};

struct RuleStats {
    long successes = 0;
    long failures = 0;
};

struct GrowthStats {
    long iterations = 0;
    std::vector<RuleStats> rules;  // parallel to Pattern::rules
    long exclude_points = 0;       // size of the exclude list at the end
    double seconds = 0;            // growth time
    std::string stop_reason;       // "exhausted", "max-elements", "max-iterations", "time-limit"
};

class GrowthEngine {
  public:
    GrowthEngine(const Pattern& pattern, const Region& region, GrowthOptions options);
    ~GrowthEngine();
    GrowthEngine(const GrowthEngine&) = delete;
    GrowthEngine& operator=(const GrowthEngine&) = delete;

    // Throws InputError (seed outside R) or RuleFailure.
    void run();

    // Called with the Figure 8 picture of iteration `debug_iteration` (1-based).
    void on_debug_frame(long debug_iteration, std::function<void(const DebugFrame&)> callback);
    // Called after every `every`-th iteration with the placed elements (growth frames).
    void on_frame(long every,
                  std::function<void(long iteration, const std::vector<const Element*>&)> callback);
    // Called after every `every`-th iteration, without the elements (elements() has them):
    // for a caller that looks at the clock often and draws seldom (the frames' list of every
    // element, made each time, was 4% of spiral's growth at every 8th iteration).
    void on_iteration(long every, std::function<void(long iteration)> callback);
    // Called about every `every` iterations for progress lines.
    void on_progress(std::function<void(long iteration, long elements)> callback);

    // Frees what only the growth needs (the distance field, the render buffer, the spatial
    // index: most of the growth's memory) for the rendering to reuse. Call it after run();
    // elements(), stats() and grid() stay valid.
    void release_growth_state();

    // Placed elements in placement order (seeds first); owned by the engine.
    std::vector<const Element*> elements() const;
    const GrowthStats& stats() const;
    const GridFrame& grid() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace acanthus
