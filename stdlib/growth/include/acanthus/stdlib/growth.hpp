// growth: example-based element arrangement after Ijiri, Mech, Igarashi and Miller, "An
// Example-based Procedural System for Element Arrangement" (2008). A small reference arrangement
// is analysed into 1-rings and grown into a panel seed by seed (docs/stdlib/growth.md).
#pragma once

#include <acanthus/body.hpp>
#include <acanthus/canvas.hpp>
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
// "flower=2, leaf=1" (symbol=integer, comma separated; "" for none); throws InputError.
std::map<std::string, int> parse_priority(std::string_view text);

// One element of a reference arrangement. size <= 0 means the default collision radius,
// 0.35 x the mean reference edge length.
struct ReferenceElement {
    std::string symbol;
    // The author's label: a drawn variant carried to the motif. Not the paper's sub-id: every
    // reference element is its own sub-id (section 3), whatever its label.
    std::string label;
    Point position;
    double angle = 0;  // radians
    double size = 0;
};

// One shape of an SVG reference element, as drawn, relative to the element's centre: subpaths of
// cubic Béziers (points[0] the start, then three points per curve).
struct OutlinePath {
    std::vector<Point> points;
    bool closed = true;
};
struct Outline {
    std::vector<OutlinePath> paths;
    Color fill{0, 0, 0, 1};
    Color stroke{0, 0, 0, 0};  // alpha 0: not stroked
    double stroke_width = 1;
};

namespace detail {
struct ReferenceData;
}

// An analysed reference arrangement: Delaunay connectivity without skewed triangles, the author's
// flips applied, a counter-clockwise 1-ring per element. Bad input throws InputError naming the
// source and, where there is one, the element index.
class Reference {
  public:
    // {"elements": [{"symbol", "x", "y", optional "label" (or its old name "sub"), "angle",
    // "size"}], "flips": [[i, j]]}
    static Reference from_json_file(const std::string& path);
    static Reference from_json_string(std::string_view text, const std::string& name);
    // An SVG drawing: every shape or group with data-symbol (optional data-label or data-sub,
    // data-angle in degrees, data-size) is one element at the centre of its bounding box; its
    // shapes are its outline. Flips: data-flips="i j; k l" on the root.
    static Reference from_svg_file(const std::string& path);
    static Reference from_svg_string(std::string_view text, const std::string& name);
    // By content: an SVG when the file's first non-blank character is '<', else JSON.
    static Reference from_file(const std::string& path);
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
    // Element i's drawn shapes (SVG references; empty for JSON ones).
    const std::vector<Outline>& outlines(std::size_t i) const;
    std::size_t symbol_count() const;
    int symbol_index(std::size_t i) const;  // element i's symbol among the sorted symbol names
    const detail::ReferenceData& data() const { return *data_; }

  private:
    explicit Reference(std::shared_ptr<const detail::ReferenceData> data);
    std::shared_ptr<const detail::ReferenceData> data_;
};

struct Options {
    Mode mode = Mode::none;
    bool relax = true;  // section 5.5 least squares after every growth step
    double w1 = 1.0;    // position difference, per mean reference edge length
    double w2 = 1.0;    // symbol differs
    double w3 = 100.0;  // the same reference element (sub-id): avoids copying it verbatim
    // Beyond the paper: per neighbour a candidate would add, how far that neighbour's symbol is
    // already over its reference share (in shares: 0.05 is 5 points), so the mix stays the
    // reference's in small panels too. 0: the paper's error.
    double w4 = 20.0;
    long max_elements = 0;  // 0: until no seed is left
    // A panel estimated to hold more motifs than this (its area over the reference's density,
    // or max_elements when smaller) is refused before growth starts, with the estimate.
    long max_motifs = 1'000'000;
    // When the growth front stops, restart it in the largest empty circle that holds a motif at
    // the reference's spacing, until none is left (false: stop with the front, as the paper).
    bool fill_holes = true;
    std::map<std::string, int> priority;  // per symbol, higher grows first (default 0)
    double priority_radius = 5.0;         // x mean edge length: where a higher priority blocks
    double short_factor = 0.5;            // l_short = factor x shortest reference edge
    double angle_factor = 0.5;            // drop a new edge under factor x the original angle
    double long_factor = 1.5;             // l_long = factor x the original edge
    // Off a lattice, no two motifs (nor a new seed and a node) closer than this times the
    // shortest reference edge between their symbols; 0: off (the paper, which merges only within
    // l_short).
    double gap_factor = 0.9;
    // Irregular references, after growth: motifs of two symbols exchange their reference elements
    // (positions kept) until the share of close neighbour pairs with one symbol is the
    // reference's; false: as grown.
    bool neighbour_share = true;
    double relax_radius = 3.0;  // x mean edge length: the window each step re-solves
    bool relax_global = false;  // the paper's global solve each step (slow; for comparison)
    // x mean edge length: a link within this of its reference offset is left as it stands, one
    // further off is pulled back to this distance, so relaxation removes accumulated misfits but
    // keeps the reference's own variation (its jitter). 0: every link pulled to its offset.
    double relax_slack = 1.0;
    // In mode none, a near-regular reference (a jittered triangular, square or honeycomb lattice:
    // its interior first shells point along four or six directions) is fitted to that lattice,
    // which the first motif puts down; each motif goes on the lattice site nearest its seed plus
    // the copied element's own jitter (docs/stdlib/growth.md).
    bool fit_to_ring = true;
    // After growth on such a lattice, the fitted motifs' jitter about their sites is scaled by
    // one factor (0.6 to 1.5) so that the NN median is the reference's; false: as copied.
    bool match_spacing = true;
    // Match each candidate's 2-ring too (its neighbours' neighbours, by nearest position), not
    // only the 1-ring: more context at the growth front, for near-regular references.
    bool two_ring = false;
    // A regular reference (two translations map every element onto one of its kind) grows on its
    // lattice: seeds go to lattice points, each takes its site's elements, and motifs whose ring
    // matches no reference ring are removed and grown again (mode none only; false: the paper's
    // growth alone, which lets domains slip where fronts meet).
    bool lattice = true;
    // On a lattice with more than one symbol, the first motif goes where (its seed's place or a
    // quarter or half cell from it) and takes the site whose lattice the panel holds most of,
    // with the symbols' shares nearest the reference's per cell; false: on its seed, the site
    // its match gives.
    bool lattice_phase = true;
    double scale_min = 1.0;  // random scale per motif, uniform
    double scale_max = 1.0;
    double angle_jitter = 0.0;     // radians: random turn of each motif, uniform in +-jitter
    double color_variation = 0.0;  // each motif's tint, uniform in +-variation (0..1)
    // Flow mode: polylines whose direction (first point to last) the field follows; RBF
    // interpolated between them. At least one is needed in flow mode.
    std::vector<std::vector<Point>> flow_strokes;
    // Section 3's boundary tool: growth never crosses these polylines.
    std::vector<std::vector<Point>> boundary_strokes;
    // Section 3's spray tool: when there is any, growth happens only within width/2 of one, and
    // starts at each spray stroke's first point too.
    struct Spray {
        std::vector<Point> points;
        double width = 0;
    };
    std::vector<Spray> spray_strokes;
    // Where the strokes came from, for messages (Guides::add_to sets it to the guides file).
    std::string guides_name;
};

// The tools drawn in an SVG: paths, polylines and lines with class `flow` (direction from start
// to end), `boundary`, or `spray` (its stroke width is the brush diameter). Curves are
// flattened. Throws InputError naming the file and element on bad input or when none is found.
struct Guides {
    std::vector<std::vector<Point>> flow, boundary;
    std::vector<Options::Spray> spray;
    std::string name;  // the file, for messages

    static Guides from_svg_file(const std::string& path);
    static Guides from_svg_string(std::string_view text, const std::string& name);
    // Adds the strokes to the options' flow, boundary and spray strokes and names the file.
    void add_to(Options& options) const;
};

// One synthesized element: the reference element `source` copied at `position`, turned by
// `angle` (its reference angle plus the ring's rotation), its collision circle `radius`.
struct Motif {
    Point position;
    std::string symbol;
    std::string label;  // the reference element's label
    double angle = 0;
    double scale = 1;
    double radius = 0;
    int source = -1;
    double tint = 0;  // colour variation: > 0 lighter, < 0 darker (Options::color_variation)
};

struct SynthesisStats {
    long steps = 0;          // seeds taken from the queue
    long seeds = 0;          // seeds made (start, ring and l_long seeds)
    long dropped = 0;        // seeds dropped: outside, no match, motif does not fit
    long merged = 0;         // l_short merges
    long restarts = 0;       // seeds planted in empty circles after the growth front stopped
    long fruitless = 0;      // restarts from which no motif grew (each circle then closed for good)
    long hole_searches = 0;  // searches for the largest empty circle
    int lattice_sites = 0;   // sites per cell of the reference's lattice (0: none, or not used)
    long completed = 0;      // seeds planted on empty lattice points next to motifs
    long repaired = 0;       // motifs removed by the lattice repair (and grown again)
    long exchanges = 0;      // pairs of motifs that exchanged elements (Options::neighbour_share)
    // Off a lattice: the bond-orientational order of the reference's interior first shells (1:
    // every shortest ring offset on one of four or six lattice directions; a scatter: near 0).
    // From 0.4 the reference is near-regular: fitted to the lattice it jitters (`jitter`: its
    // RMS offset from its sites, in spacings; 0 when no lattice fits), each motif is put on its
    // lattice site plus its copied element's offset as it is placed (`fitted` of them moved).
    double ring_order = 0;
    bool near_regular = false;
    bool honeycomb = false;  // its first shell of three edges stands apart from the next ones
    double jitter = 0;
    long fitted = 0;
    // Options::match_spacing: the factor the fitted motifs' jitter was scaled by (1: none), and
    // the motifs moved by it (one whose move would overlap or crowd stays as copied).
    double jitter_scale = 1;
    long rescaled = 0;
    double seconds = 0;  // wall time (reported only, never used)
    double relax_seconds = 0;
    // How far the result is from the reference's offsets: RMS over the links between motifs of
    // |actual offset - wanted offset|, in mean reference edge lengths (what eq. 5 minimizes).
    double link_error = 0;
};

// How faithfully the result keeps the reference (docs/stdlib/growth.md, "Fidelity report"):
// lengths in units of the reference's median nearest-neighbour (NN) distance.
struct Fidelity {
    double spacing = 0;    // the reference's NN median, in drawing units
    double nn_median = 0;  // the result's NN median / spacing
    // The NN median of the reference elements growth copies (its interior ones, whose rings are
    // whole) / spacing: what nn_median is compared with, like for like.
    double reference_nn_median = 1;
    // The same away from edges, where an NN is measured from one side only: the NN median of the
    // motifs at least 1.5 NN inside the panel (nn_median when there are none), and of the
    // reference's interior elements at least 1.5 NN from its boundary elements
    // (reference_nn_median when there are none), both / spacing.
    double nn_median_inner = 0;
    double reference_nn_median_inner = 1;
    double histogram_bin = 0.1;  // NN histograms: shares per bin of this width from 0, the last
    std::vector<double> nn_histogram, reference_nn_histogram;  // bin holding everything beyond
    std::map<std::string, double> symbol_mix, reference_symbol_mix;  // share per symbol
    // Pairs within 1.2 NN with one symbol, among all pairs within 1.2 NN.
    double same_symbol_share = 0, reference_same_symbol_share = 0;
    // Motifs at least 1.5 NN inside the panel whose neighbours (within 1.2 NN) match no full
    // reference ring of their symbol within 0.15 NN: 0 for a perfect regular lattice.
    long interior = 0;
    long defects = 0;
    double defect_share = 0;
    // The largest empty circle where a motif fits: its radius to the nearest motif's centre.
    double largest_hole = 0;
};

struct SynthesisResult {
    std::vector<Motif> motifs;
    std::vector<std::pair<int, int>> edges;  // connectivity between motifs (indices), i < j
    SynthesisStats stats;
    Fidelity fidelity;
};
// The fidelity report as a JSON object (the `growth` section of the program's --metrics).
std::string fidelity_json(const SynthesisResult& result);

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

// A reference loaded once per path and kept for the run (by Reference::from_file), so that rule
// bodies and %draw share it.
const Reference& load_reference(const std::string& path);
const Guides& load_guides(const std::string& path);

// Draws reference element `source` at `centre`, turned to `angle` (radians) and scaled: its
// outline for an SVG reference, else a glyph in its symbol's colour with a tick along the angle.
void draw_motif(Canvas& canvas, const Reference& reference, int source, Point centre, double angle,
                double scale, double tint = 0);

// Inside a rule body: one element of type T per motif (T has a circle proxy p0 and fields symbol,
// sub (the label), angle, scale and source, as `motif` in growth.acr), each added with
// new_child(). Returns how many were added.
// A new element of type T for motif `m` (see add_motifs), not yet added to anything.
template <class T>
T* new_motif(const Motif& m, bool sterile = true) {
    T* e = new T;
    e->p0.set(m.position, m.radius);
    e->symbol = m.symbol;
    e->sub = m.label;
    e->angle = m.angle;
    e->scale = m.scale;
    e->source = m.source;
    if constexpr (requires { e->tint; }) e->tint = m.tint;
    e->sterile = sterile;
    return e;
}

template <class T>
int add_motifs(const SynthesisResult& result, bool sterile = true) {
    int added = 0;
    for (const Motif& m : result.motifs) {
        acanthus::body::new_child(*new_motif<T>(m, sterile));
        ++added;
    }
    return added;
}

namespace detail {
// The motifs a running synthesis placed so far are shown in the program's partial pictures (its
// --partial, acanthus preview) as elements made by this (growth.acr sets it: `motif`).
using PartialMaker = const Element* (*)(const Motif&);
bool set_partial_maker(PartialMaker maker) noexcept;
}  // namespace detail

}  // namespace acanthus::growth
