// dartfill: dense non-periodic aggregates of arbitrary (concave) shapes after Sakurai & Miyata
// (2012), placed naively, by the paper's fill-gap method or along the medial axis, with exact
// overlap tests (docs/stdlib/dartfill.md).
#pragma once

#include <acanthus/body.hpp>
#include <acanthus/point.hpp>
#include <acanthus/region.hpp>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus::dartfill {

enum class Method {
    naive,     // section 3.2: random darts until N consecutive cancellations
    fill_gap,  // section 4: Poisson-disk sparse placement, then candidates drawn by d^n
    medial,    // ours: candidates at the distance field's ridge maxima, largest gap first
};
// "naive", "fillgap" (or "fill-gap", "fill_gap"), "medial"; throws InputError otherwise.
Method parse_method(std::string_view text);
std::string_view to_string(Method method);

struct Options {
    Method method = Method::fill_gap;
    double rotation_min = 0.0;  // radians, drawn uniformly per trial
    double rotation_max = 2 * M_PI;
    double scale_min = 1.0;  // drawn uniformly per trial
    double scale_max = 1.0;
    long naive_cancellations = 10000;  // naive: consecutive cancellations that end the run
    long sparse_cancellations = 100;   // step 1 of fill-gap: ends the Poisson-disk darts
    double exponent = 16;              // fill-gap: probability of a candidate pixel is d^n
    int candidates = 100;              // fill-gap and medial: |P| per round
    long gap_cancellations = 200;      // fill-gap and medial: consecutive cancellations that end it
    int rotations = 6;                 // medial: rotations tried at one candidate point
    int resolution = 0;                // distance-field pixels on the longer side of the panel;
                                       // 0: the smallest shape spans about 8 pixels (64..1024)
    double tolerance = -1;             // touching depth that is not overlap; < 0: 1e-6 x panel size
    long max_elements = 0;             // 0: no limit
};

// One placed exclusive region: shape `shape` rotated, scaled and moved so that its bounding-box
// centre lies at `position`; `outline` is the transformed polygon.
struct Placement {
    int shape = 0;
    Point position;
    double rotation = 0;
    double scale = 1;
    double area = 0;
    std::vector<Point> outline;
};

struct FillStats {
    long trials = 0;        // placement attempts, successful or cancelled
    long rounds = 0;        // fill-gap / medial candidate rounds
    double seconds = 0;     // wall time of the fill (reported only, never used)
    double coverage = 0;    // placed area / area of the space filled
    double space_area = 0;  // area of the space filled
};

struct FillResult {
    Method method = Method::fill_gap;
    std::vector<Placement> placements;
    FillStats stats;
};

namespace detail {
struct ShapeList;
}

// The exclusive regions to place, cycled in the order added. Each is validated and triangulated
// when added; bad shapes throw InputError naming the shape (or file).
class ShapeSet {
  public:
    ShapeSet();
    ~ShapeSet();
    ShapeSet(const ShapeSet&);
    ShapeSet(ShapeSet&&) noexcept;
    ShapeSet& operator=(const ShapeSet&);
    ShapeSet& operator=(ShapeSet&&) noexcept;

    ShapeSet& add_points(std::string name, std::vector<Point> outline);
    // SVG path data ("M 0 0 C ... Z"), one closed outline; curves are flattened to `tolerance`
    // user units (< 0: 1/500 of the shape's size).
    ShapeSet& add_path(std::string name, std::string_view path_data, double tolerance = -1);
    // Every filled outline of an SVG file becomes one shape, named "FILE#k".
    ShapeSet& add_svg_file(const std::string& file, double tolerance = -1);

    std::size_t size() const;
    bool empty() const { return size() == 0; }
    const std::string& name(std::size_t i) const;
    const std::vector<Point>& outline(std::size_t i) const;
    std::size_t triangle_count(std::size_t i) const;
    double area(std::size_t i) const;
    Rect bounds(std::size_t i) const;
    // Radius of the bounding circle about the bounding-box centre.
    double radius(std::size_t i) const;
    const detail::ShapeList& list() const { return *shapes_; }

  private:
    std::shared_ptr<detail::ShapeList> shapes_;
};

// Fills a whole region (tools, tests, benchmarks). Deterministic for a given seed.
FillResult fill(const ShapeSet& shapes, const Region& region, const Options& options,
                std::uint64_t seed);
// Inside a rule body: fills the space the growing ornament leaves in the panel (placed elements
// are obstacles, found through the running Environment), with the program's --rng-seed.
// Throws std::logic_error outside a rule body.
FillResult fill(const ShapeSet& shapes, const Options& options);

// Inside a rule body: makes one element of type T per placement (T has a polygon proxy p0 and
// int/double fields shape, rotation and scale, as `aggregate` in dartfill.acr), adds each with
// new_child() and returns how many were added. Sterile aggregates (the default) end growth
// around them at once; pass false when other rules grow on them.
template <class T>
T* new_aggregate(const Placement& p, bool sterile = true) {
    T* e = new T;
    e->p0.set(p.outline);
    e->shape = p.shape;
    e->rotation = p.rotation;
    e->scale = p.scale;
    e->sterile = sterile;
    return e;
}

template <class T>
int add_aggregates(const FillResult& result, bool sterile = true) {
    int added = 0;
    for (const Placement& p : result.placements) {
        acanthus::body::new_child(*new_aggregate<T>(p, sterile));
        ++added;
    }
    return added;
}

namespace detail {
// The shapes a running fill placed so far are shown in the program's partial pictures (its
// --partial, acanthus preview) as elements made by this (dartfill.acr sets it: `aggregate`).
using PartialMaker = const Element* (*)(const Placement&);
bool set_partial_maker(PartialMaker maker) noexcept;
}  // namespace detail

}  // namespace acanthus::dartfill
