// cells: feature-based cellular texturing of facades after Legakis, Dorsey and Gortler,
// "Feature-Based Cellular Texturing for Architectural Models" (2001), in 2-D. A facade's wall,
// openings, edges and corners are textured by a tree of pattern generators, corners first, then
// edges, then faces, each claiming space in occupancy maps (docs/stdlib/cells.md).
#pragma once

#include <acanthus/body.hpp>
#include <acanthus/point.hpp>
#include <acanthus/random.hpp>
#include <acanthus/region.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace acanthus::cells {

// The reader's output, one per SVG shape: <acanthus/stdlib/cells/facade_shape.hpp> (lib2geom).
struct FacadeShape;

enum class FeatureKind { corner, edge, face };
std::string_view to_string(FeatureKind kind);

// Window analysis [5.3]: the part of its shape a feature is on. For an opening, `bottom` is the
// sill side (wall below); for the wall's outline, `top` is the side with the wall below it.
enum class Part { top, bottom, side };
std::string_view to_string(Part part);

enum class Bond { running, stack, english, flemish, header, ashlar };
// "running" (or "stretcher"), "stack", "english", "flemish", "header", "ashlar"; InputError else.
Bond parse_bond(std::string_view text);
std::string_view to_string(Bond bond);

// A piece of an edge, exact: a line segment, or a circular arc about `center` from `a` (at angle
// `start`) sweeping `sweep` radians (signed, counter-clockwise in x-right y-down numbers).
struct Segment {
    Point a, b;
    bool arc = false;
    Point center;
    double radius = 0;
    double start = 0;
    double sweep = 0;

    double length() const;
    Point at(double s) const;        // s: arc length from a, in [0, length()]
    Vector tangent(double s) const;  // unit, towards b
    double project(Point p) const;   // arc length of the nearest point
};

struct Corner {
    Point position;
    Vector in, out;  // unit tangents of the edge arriving and the edge leaving
    bool convex = true;
    Part part = Part::side;
    int edge_in = -1, edge_out = -1, face = 0;
    bool opening = false;             // on an opening's outline (else the wall's)
    std::vector<std::string> labels;  // class words, then the id, of its shape
};

// A maximal run of segments of one kind (straight or arc) between corners or kind changes;
// parameterized by arc length [3.2]. A whole circle is one closed edge without corners.
struct Edge {
    std::vector<Segment> segments;
    std::vector<double> offsets;  // arc length at the start of each segment
    double length = 0;
    bool closed = false;
    bool arc = false;  // its segments are arcs
    Part part = Part::side;
    int corner_start = -1, corner_end = -1, face = 0;
    bool opening = false;
    bool interior_left = true;  // the wall lies left of the direction of travel
    Rect bounds;
    std::vector<std::string> labels;

    Point at(double s) const;
    Vector tangent(double s) const;
    Vector inward(double s) const;  // unit normal into the wall
    double project(Point p) const;
    // The paper's orientation test: vertical when the chord's largest component is along y.
    bool vertical() const;
};

// A connected part of the wall with its holes. (s, t) [3.2]: s = x - bounds.x0, t = bounds.y1 -
// y, so t points up the facade (SVG's y points down).
struct Face {
    std::vector<std::vector<Point>> loops;  // flattened boundary, for drawing and tests
    Rect bounds;
    double area = 0;
    std::vector<int> corners, edges;
    std::vector<std::string> labels;
    Point map(Point st) const { return {bounds.x0 + st.x, bounds.y1 - st.y}; }
    Point project(Point p) const { return {p.x - bounds.x0, bounds.y1 - p.y}; }
};

namespace detail {
struct FacadeData;
struct ContextData;
}  // namespace detail

// The features of a facade [3.1]: the wall (union of shapes with class `wall`) minus the openings
// (every other shape), as faces, edges and corners with labels and window analysis.
class Facade {
  public:
    // Throws InputError naming `source_name` and the shape: no wall, an opening crossing the
    // wall's outline, a shape without area, non-finite coordinates.
    static Facade from_shapes(std::vector<FacadeShape> shapes, const std::string& source_name);
    // A facade drawing (docs/stdlib/cells.md, "Facade SVG"): labels are the class words of each
    // shape and of its ancestor groups, then its id (else its nearest ancestor's); the wall is
    // the filled shapes whose nearest element with a class has `wall`, every other filled shape
    // is an opening; lines and unfilled shapes are ignored. Throws InputError naming the file
    // and the element, as from_shapes does, and on unreadable or malformed SVG.
    static Facade from_svg_file(const std::string& path);
    static Facade from_svg_string(std::string_view text, const std::string& name);
    // A panel as a wall: all of the region is wall (labels `wall panel`), its holes are holes
    // in the wall's outline, not openings.
    static Facade from_region(const Region& region);
    // The facade of --region: its SVG file read as a facade (a file without a filled `wall`
    // shape is an InputError naming it, unless `whole_panel`: then it is all wall, every filled
    // shape labelled `wall panel`, arcs exact); a built-in shape (rect:W,H, ...) goes to
    // from_region().
    static Facade for_panel(const Region& region, bool whole_panel = false);

    const std::vector<Corner>& corners() const;
    const std::vector<Edge>& edges() const;
    const std::vector<Face>& faces() const;
    const std::string& name() const;
    Rect bounds() const;
    // Total wall area and the openings' outlines (flattened), for checks and drawing.
    double wall_area() const;
    const std::vector<std::vector<Point>>& openings() const;
    const detail::FacadeData& data() const { return *data_; }

  private:
    explicit Facade(std::shared_ptr<const detail::FacadeData> data);
    std::shared_ptr<const detail::FacadeData> data_;
};

// How ashlar fills a face: `rules`, the default, beyond the paper (the face's layout takes the
// edges' units too; stones laid in reading order, none on end, so that no four stones meet at a
// point, counted against the lintels, sills and voussoirs laid before, no unit squares touch and
// no straight joint runs along more than ashlar_max_seam stones, wherever some size allows it);
// `merge`, the paper's (edge stones, then a stone per free grid unit, random neighbours merged up
// to the maximum size).
enum class AshlarMethod { merge, rules };
AshlarMethod parse_ashlar_method(std::string_view text);  // "merge" or "rules"; InputError else
std::string_view to_string(AshlarMethod method);

struct Options {
    double brick_length = 215;  // user units; bricks and the grid tool's module
    double brick_height = 65;
    double mortar = 10;  // joint width: drawn cells are claims shrunk by half of it
    // How far a head or bed joint may open or close so that whole bricks and courses keep their
    // nominal size and still meet openings and the wall's ends; beyond it, cut bricks and courses.
    double joint_tolerance = 3;
    Bond bond = Bond::running;
    double ashlar_unit = 0;    // grid of the ashlar tool; 0: brick_height + mortar
    int ashlar_max_width = 4;  // ashlar stones, in grid units
    int ashlar_max_height = 2;
    AshlarMethod ashlar_method = AshlarMethod::rules;
    int ashlar_max_seam = 4;    // rules: no straight joint along more stones than this
    double voussoir_width = 0;  // arch stones along the arc; 0: 2 x (brick_height + mortar)
    double arch_depth = 0;      // each row's depth; 0: brick_length + mortar
    int arch_rows = 1;          // rows of arch stones
    int lintel_bearing = 2;     // lintel past each jamb, in quarter bricks
    int lintel_courses = 2;     // lintel depth, in courses
    // brick_tree(): heads up to this span get a soldier course, wider ones a lintel; 0: six
    // brick lengths.
    double soldier_span = 0;
    int quoin_long = 4, quoin_short = 2;  // jamb quoins, in quarter bricks, alternating by course
    double arc_tolerance = 0;  // chord error of drawn arcs; 0: mortar / 20 (at least 1e-3)
    // texture() refuses a facade estimated above this many cells before laying any: a million
    // cells are about 200 MB, and a program's elements and drawing several times that.
    long max_cells = 1000000;
};

// A placed cell: its drawn polygon (the claim shrunk by half the joint), who placed it, the
// feature's kind and labels (space-separated) and the row where it has one (else -1).
struct Cell {
    std::vector<Point> polygon;
    std::string generator;
    FeatureKind feature = FeatureKind::face;
    std::string label;
    int course = -1;
    int feature_index = -1;
    // What a mason calls the piece when its face alone does not say ("king closer"); else empty.
    std::string piece;
};

struct FeatureRef {
    FeatureKind kind = FeatureKind::face;
    int index = 0;
};

// 1-D occupancy of an edge [3.3]: claimed arc-length intervals, merged and sorted.
class EdgeOccupancy {
  public:
    explicit EdgeOccupancy(double length = 0) : length_(length) {}
    void claim(double s0, double s1);
    bool is_free(double s0, double s1) const;
    std::vector<std::pair<double, double>> free_intervals(double min_length = 0) const;
    const std::vector<std::pair<double, double>>& claimed() const { return runs_; }
    double length() const { return length_; }

  private:
    double length_;
    std::vector<std::pair<double, double>> runs_;
};

namespace detail {
class FaceOccupancyData;
}

// 2-D occupancy of a face [3.3], exact: the face's polygon less the claims (Clipper booleans).
class FaceOccupancy {
  public:
    FaceOccupancy(const Facade& facade, int face);
    ~FaceOccupancy();
    FaceOccupancy(FaceOccupancy&&) noexcept;
    FaceOccupancy& operator=(FaceOccupancy&&) noexcept;

    void claim(const std::vector<Point>& polygon);
    void claim(Rect rect);
    // The parts of `polygon` inside the face and not claimed (each a simple polygon).
    std::vector<std::vector<Point>> free_part(const std::vector<Point>& polygon) const;
    // True when `rect` lies in the face and touches no claim (a cheap test, exact when true).
    bool rect_is_free(Rect rect) const;
    double claimed_area() const;
    const detail::FaceOccupancyData& data() const { return *data_; }

  private:
    std::unique_ptr<detail::FaceOccupancyData> data_;
};

// What a generator gets with the feature: the facade, the options, the seeded random numbers,
// the occupancy maps and place(), which records a cell for the running generator.
class Context {
  public:
    Context(const Facade& facade, const Options& options, std::uint64_t seed);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    const Facade& facade() const;
    const Options& options() const;
    Random& random();
    EdgeOccupancy& edge_occupancy(int edge);
    FaceOccupancy& face_occupancy(int face);

    // Claims `claim` (clipped to what is free in the face when `clip`), and adds the drawn cells:
    // the claim shrunk by half the joint, or `drawn` when given and the claim was wholly free (a
    // brick of nominal size whose joints took up a difference). Returns how many cells were added
    // (0 when nothing was free).
    int place(const std::vector<Point>& claim, int course = -1, bool clip = true,
              const Rect* drawn = nullptr);
    // A rectangle known to be free: no clipping.
    int place_free_rect(Rect rect, int course = -1, const Rect* drawn = nullptr);

    // Set by the tree while a generator runs.
    void begin(const std::string& generator, const FeatureRef& feature);
    const FeatureRef& feature() const;
    std::vector<Cell>& cells();
    detail::ContextData& data() { return *data_; }

  private:
    std::unique_ptr<detail::ContextData> data_;
};

// A pattern generator: places cells on one feature through the context.
using Generator = std::function<void(const FeatureRef&, Context&)>;

// A node of a pattern generator tree [4.1]: gets a feature, places cells or passes it on.
class Node {
  public:
    using Fn = std::function<void(const FeatureRef&, Context&)>;
    Node() = default;
    explicit Node(Fn fn) : fn_(std::make_shared<const Fn>(std::move(fn))) {}
    void operator()(const FeatureRef& feature, Context& context) const {
        if (fn_) (*fn_)(feature, context);
    }

  private:
    std::shared_ptr<const Fn> fn_;
};

Node leave();  // places nothing
Node generator(std::string name, Generator g);
Node generator(std::string name, Generator g, Node then);  // places cells and passes it on
Node by_kind(Node corner, Node edge, Node face);
Node by_label(std::string label, Node with, Node without);
// Edges by the chord, faces always vertical (a facade), corners by `corners_horizontal`.
Node by_orientation(Node horizontal, Node vertical, bool corners_horizontal = false);
// Window analysis; features of the wall's outline go to `sides` unless `outline` is set.
Node by_part(Node top, Node bottom, Node sides);
// Edges made of arcs, and corners on one (a springing or an apex, from which the arch is set out
// before any brick is laid), go to `arc`; faces are straight.
Node by_curve(Node arc, Node straight);
Node by_convexity(Node convex, Node concave);  // corners; edges and faces go to `convex`

// The built-in generators [5].
Generator rgb_blocks();
Generator bricks();         // corner, edge and face bricks in options.bond
Generator window_bottom();  // header row under openings; a face is an InputError
// Voussoirs along arc edges, radial joints, set out from the crown: an odd count with a key at
// the crown of a whole arc, a keystone with real width at a pointed apex. Given a corner on an
// arc (by_curve), it lays that arc's whole ring first, and a skewback where an arc springs from a
// straight jamb at an angle (a segmental arch).
Generator arch_stones();
Generator arch_bricks();  // the same in bricks on end, a course wide (a rowlock arch)
Generator ashlar();       // random ashlar on the grid tool, seeded
Generator lintel();       // one stone over an opening, past each jamb
// Bricks on end over an opening's straight head, a brick's length high, from jamb to jamb.
Generator soldier_course();
// Over the lintel of an opening labelled `relieving`: a segmental rowlock ring springing beyond
// the lintel's ends from skewbacks, an odd count with a key at the crown (docs/stdlib/cells.md).
Generator relieving_arch();
Generator quoins();       // long and short stones alternating up the sides
Generator sill_stones();  // window bottom of a stone wall: the ashlar row under each sill

// Ready trees: bricks with window bottoms, arches, heads (a soldier course over a straight head
// up to Options::soldier_span, a lintel over a wider one) and corner bricks; ashlar framed the same
// way (its window bottoms are sill stones, placed as "window_bottom"); RGB blocks. tree_for() picks
// bricks or ashlar from options.bond.
Node brick_tree();
Node ashlar_tree();
Node rgb_tree();
Node framed_tree();  // bricks with lintels and jamb quoins
Node tree_for(const Options& options);

struct TextureStats {
    long corners = 0, edges = 0, faces = 0;
    double seconds = 0;  // wall time, reported only
    // Ashlar (cells_ashlar=rules): the most rounds of repairs any face's layout ran, the last
    // one, which changed nothing, included; the bound is 16, and a 17 says they were stopped
    // there while still changing the layout.
    int ashlar_rounds = 0;
};

struct Texture {
    std::vector<Cell> cells;
    TextureStats stats;
};

// Throws InputError for bad options (a brick of size zero, ...), naming the facade.
void check(const Options& options, const std::string& source_name);
// Throws InputError for what texture() refuses before laying a cell: bad options, a face no
// course fits in (naming its wall shapes), more than options.max_cells (with the estimate).
void check(const Facade& facade, const Options& options);

// Runs the tree over all corners, then all edges, then all faces [4.2]. Deterministic for the
// same facade, tree, options and seed.
Texture texture(const Facade& facade, const Node& tree, const Options& options, std::uint64_t seed);
// Inside a rule body: seeded from the program's --rng-seed.
Texture texture(const Facade& facade, const Node& tree, const Options& options);

// A new element of type T for cell `c` (see add_cells; its tint left alone), not yet added.
template <class T>
T* new_cell(const Cell& c, bool sterile = true) {
    T* e = new T;
    e->p0.set(c.polygon);
    e->generator = c.generator;
    e->feature = std::string(to_string(c.feature));
    e->label = c.label;
    e->course = c.course;
    e->sterile = sterile;
    return e;
}

// Inside a rule body: one element of type T per cell (T has a polygon proxy p0 and fields
// generator, feature, label and course, as `cell` in cells.acr; a field `tint`, when T has one,
// gets a uniform number in [-1, 1] from the program's --rng-seed for colour variation). Returns
// how many were added. Each one is reported as progress ("elements"): a million cells take a
// while, after texture()'s own reports have ended.
template <class T>
int add_cells(const Texture& texture, bool sterile = true) {
    const auto total = static_cast<long>(texture.cells.size());
    int added = 0;
    for (const Cell& c : texture.cells) {
        T* e = new_cell<T>(c, sterile);
        if constexpr (requires { e->tint = 0.0; }) e->tint = acanthus::body::rng.uniform(-1, 1);
        acanthus::body::new_child(*e);
        ++added;
        acanthus::report_progress("elements", added, total);
    }
    return added;
}

namespace detail {
// The cells a running texture laid so far are shown in the program's partial pictures (its
// --partial, acanthus preview) as elements made by this (cells.acr sets it: `cell`).
using PartialMaker = const Element* (*)(const Cell&);
bool set_partial_maker(PartialMaker maker) noexcept;
PartialMaker partial_maker() noexcept;
}  // namespace detail

}  // namespace acanthus::cells
