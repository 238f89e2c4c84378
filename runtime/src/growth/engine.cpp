// The main loop of Wong et al. section 4.1 (see docs/engine.md):
//
//   place seeds; render the boundary and the seeds; compute the distance field
//   repeat
//     C = FindEmptyCircle()                       (largest eligible medial-axis circle)
//     try non-sterile elements within epsilon of C, nearest first, and their rules in file order
//     first SUCCESS: commit children, render them, update the field, drop exclude points near C
//     no SUCCESS: C's centre joins the exclude list
//   until no circle (and %exhausted says STOP), or a limit is reached.
#include <acanthus/error.hpp>
#include <acanthus/growth.hpp>
#include <acanthus/rule_call.hpp>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "field/circle_source.hpp"
#include "field/distinct_circles.hpp"
#include "field/empty_circle_finder.hpp"
#include "field/memory_budget.hpp"
#include "field/raster_buffer.hpp"
#include "growth/engine_environment.hpp"
#include "growth/exclude_list.hpp"
#include "growth/filling_hole.hpp"
#include "growth/ornament.hpp"
#include "pattern/running_body.hpp"
#include "proxy/overlap.hpp"
#include "symmetry/image_element.hpp"
#include "symmetry/orbit.hpp"
#include "symmetry/symmetric_core.hpp"
#include "symmetry/symmetry_group.hpp"
#include "symmetry/translation_groups.hpp"

namespace acanthus {

bool detail::filling_hole(const Environment& env) {
    const auto* growth = dynamic_cast<const GrowthEnvironment*>(&env);
    return growth && growth->filling_hole();
}

// This file builds public types from private (detail) parts.
using namespace detail;
namespace {

using Clock = std::chrono::steady_clock;

// The panel a fill library sees during a restart (centre_seed()): the part of the disc `c` in
// the group's fundamental domain, since the images fill the rest of the hole and what the fill
// tries outside the domain only clashes with them; the whole disc when the two do not meet (a
// circle beside a rotation centre may lie off the domain).
Region hole_region(const SymmetryGroup& group, const Circle& c, double tolerance, double flatness) {
    const std::vector<Point> part = group.domain_part(c, tolerance, flatness);
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
    char text[256];
    if (part.empty()) {
        std::snprintf(text, sizeof text, "<circle cx=\"%.17g\" cy=\"%.17g\" r=\"%.17g\"/>",
                      c.center.x, c.center.y, c.radius);
        svg += text;
    } else {
        svg += "<path d=\"M";
        for (const Point p : part) {
            std::snprintf(text, sizeof text, " %.17g %.17g", p.x, p.y);
            svg += text;
        }
        svg += " Z\"/>";
    }
    return Region::from_svg_string(svg + "</svg>", "the hole of a restart");
}

// Consecutive %exhausted CONTINUE rounds that place nothing before the engine gives up.
constexpr int kMaxFruitlessRounds = 16;
// Candidate pixels a debug frame looks at (every one, in practice), before distinct_circles.
constexpr std::size_t kDebugCandidates = 1'000'000;
constexpr long kProgressEvery = 1000;
// Under symmetry, commits of up to this many elements enter the field image by image.
constexpr std::size_t kOneByOne = 16;
// The ornament's near zone under symmetry: the cells of 8 x 8 pixels within this many cells of
// a pixel of the fundamental domain. Images farther away are indexed only when a query reaches
// them.
constexpr int kNearCellShift = 3;
constexpr int kNearCells = 4;

std::string format_number(double v) {
    char buf[64];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

// What growth runs on: the region, or under a periodic group (a wallpaper tile, a closed band)
// the box round it, at the resolution that gives the region its pixels.
struct Setup {
    Region region;
    GrowthOptions options;
    std::optional<TranslationSetup> translations;
};

Setup set_up(const Region& region, GrowthOptions options) {
    const int groups =
        (options.symmetry ? 1 : 0) + (options.frieze ? 1 : 0) + (options.wallpaper ? 1 : 0);
    if (groups > 1) throw UsageError("--symmetry, --frieze and --wallpaper exclude one another");
    if (options.wrap_x && !options.frieze) throw UsageError("a closed band needs a frieze group");
    std::optional<TranslationSetup> t;
    if (options.frieze) t = frieze_setup(*options.frieze, region, options.wrap_x);
    if (options.wallpaper) t = wallpaper_setup(*options.wallpaper);
    if (!t || !t->box) return {region, std::move(options), std::move(t)};
    const Rect inner = region.bounds(), outer = t->box->bounds();
    const double scale =
        std::max(outer.width(), outer.height()) / std::max(inner.width(), inner.height());
    const int r = options.resolution;
    if (r >= RasterBuffer::kMinResolution && r <= RasterBuffer::kMaxResolution)
        options.resolution = std::min(RasterBuffer::kMaxResolution,
                                      static_cast<int>(std::lround(options.resolution * scale)));
    Region box = *t->box;
    return {std::move(box), std::move(options), std::move(t)};
}

// The setup, once the buffer it asks for is known to fit in memory (nothing is allocated
// before): UsageError for a resolution out of range, InputError when too large for memory.
Setup checked(const Region& region, const GrowthOptions& options) {
    Setup s = set_up(region, options);
    const int r = s.options.resolution;
    if (r >= RasterBuffer::kMinResolution && r <= RasterBuffer::kMaxResolution)
        check_growth_memory(RasterBuffer::grid_for(s.region.bounds(), r), r);
    return s;  // RasterBuffer refuses a resolution out of range
}

}  // namespace

struct GrowthEngine::Impl {
    Impl(const Pattern& p, Setup s)
        : pattern(p),
          region(std::move(s.region)),
          options(std::move(s.options)),
          translations(std::move(s.translations)),
          raster(region, options.resolution),
          epsilon(options.epsilon < 0 ? 2 * raster.grid().pixel : options.epsilon),
          min_radius(options.min_radius < 0 ? raster.grid().pixel : options.min_radius),
          group(make_group()),
          circles(make_source()),
          ornament(region, 1e-6 * std::max(region.bounds().width(), region.bounds().height())),
          env(region, ornament, exclude, options.rng_seed, group.get(), &core_region) {
        if (group && group->rosette() &&
            !maps_onto_itself(region, *group, raster.grid().pixel / 4)) {
            raster.add_boundary(pixels_outside_core(raster, *group));
            core_region = &region;  // images may leave it
        }
        if (!near_cells.empty()) {
            const GridFrame& g = raster.grid();
            const double cell = g.pixel * (1 << kNearCellShift);
            static_assert(kNearCellShift == 3, "the near zone's cells are the field's tiles");
            ornament.set_near_zone({g.x0 - kNearCells * cell, g.y0 - kNearCells * cell}, cell,
                                   ((g.width - 1) >> kNearCellShift) + 1 + 2 * kNearCells,
                                   near_cells);
            near_cells.clear();
        }
        stats.rules.resize(pattern.rules.size());
        for (std::size_t k = 0; k < pattern.rules.size(); ++k)
            rules_by_parent[pattern.rules[k].parent].push_back(static_cast<int>(k));
    }

    std::unique_ptr<SymmetryGroup> make_group() const;
    std::unique_ptr<CircleSource> make_source() {
        CircleSourceOptions o{options.distance, min_radius, options.lazy_field_pixels, {}};
        if (group) o.centres = domain_pixels(raster.grid(), *group);
        // Without a window (a frieze's open band) every kept image is checked against the
        // placed elements by a query where it lies (placeable_orbits()): queries reach all
        // over the band, and nothing would be deferred. A periodic group checks them through
        // the families near the element (per_orbit()).
        if (group && (group->rosette() || (translations && translations->group.window)))
            near_cells = near_zone(raster.grid(), o.centres, kNearCells);
        return options.reference_engine ? reference_circle_source(raster, o)
                                        : incremental_circle_source(raster, o);
    }
    std::vector<Point> default_seeds() const;
    void place_seeds();
    void grow();
    std::optional<EmptyCircle> find();
    std::optional<Circle> refine(const EmptyCircle& found);
    std::optional<Circle> find_goal();
    bool can_parent(const Element& e) const {
        return !e.sterile && rules_by_parent.count(&e.type()) != 0;
    }
    bool any_parent_left();
    void iterate(const Circle& goal);
    bool commit(std::vector<std::unique_ptr<Element>> children, Element* parent);
    std::vector<Circle> rule_goals(const Circle& goal, Point toward, bool beside) const;
    bool second_seed();
    bool tried_second_seed = false;
    bool centre_seed();
    bool restart_goal = false;  // iterate() runs on a hole at a rotation centre (centre_seed())
    bool can_parent_type(const Element& e) const { return rules_by_parent.count(&e.type()) != 0; }
    // The restarts centre_seed() has left: a rotation centre and whether the seed goes beside it.
    std::optional<std::vector<std::pair<Point, bool>>> centre_restarts;
    double centre_bar = 0;     // a hole no larger than this is as well filled (centre_seed())
    long exhausted_calls = 0;  // how often %exhausted was called
    long centre_round = -1;    // exhausted_calls when the last round of restarts began
    std::size_t centre_round_size = 0;  // the ornament's size when that round ended
    // Each restart on a centre: the hole, whether the seed grew, and whom the hole was offered.
    struct CentreOffer {
        Point centre;
        double hole = 0;
        bool grew = false;
        std::vector<const Element*> offered;
    };
    std::vector<CentreOffer> centre_offered;
    const std::vector<const Element*>* restart_skip = nullptr;  // iterate() offers them nothing
    std::vector<const Element*>* restart_offered = nullptr;     // iterate() lists its parents
    EmptyCircle goal_found;  // the circle find_goal() refined last
    // C's centre and its distinct images (C's centre alone without symmetry).
    std::vector<Point> orbit_of_point(Point p) const;
    // Under a periodic group (a tile, a closed band), each fundamental element (by id) and its
    // placed images, in placement order.
    std::vector<std::vector<const Element*>> families;
    bool families_whole = true;  // every fundamental element lies inside the window
    // The proxies' bounds of the elements found near one so far: from family_bounds_at[id] on.
    mutable std::vector<Rect> family_bounds;
    mutable std::vector<long> family_bounds_at;  // by id, -1 until measured
    bool per_orbit(const Element& e) const;
    struct NearProxy {
        const Element* element;
        std::size_t proxy;
        Rect bounds;
    };
    // The proxies of the families near e, by their bounds' left edge.
    std::vector<NearProxy> family_near(const Element& e) const;
    double near_margin() const;
    // The pixels an element with these bounds covers, with a margin.
    PixelBox pixel_box(const Rect& bounds) const;
    std::vector<Rect> image_bounds;  // commit()'s scratch
    // Per image of a commit, whether it lies too far from the domain to meet the ornament's
    // near zone or to reach a distance the field reads (commit()'s scratch).
    std::vector<std::uint8_t> far_images;
    void mark_far_images(const std::vector<std::unique_ptr<Element>>& children,
                         const std::vector<Orbit>& orbits);
    std::optional<Point> roomiest_in_domain() const;
    void sync_exclude_clears();
    Flow call_exhausted();

    const Pattern& pattern;
    Region region;
    GrowthOptions options;
    std::optional<TranslationSetup> translations;  // a frieze or wallpaper group
    RasterBuffer raster;
    double epsilon;
    double min_radius;
    std::unique_ptr<SymmetryGroup> group;  // null without --symmetry
    // The region when an image may leave it; null when the group maps it onto itself.
    const Region* core_region = nullptr;
    std::vector<bool> near_cells;  // the ornament's near zone (make_source())
    std::unique_ptr<CircleSource> circles;
    ExcludeList exclude;
    Ornament ornament;
    GrowthEnvironment env;
    std::map<const ElementType*, std::vector<int>> rules_by_parent;
    GrowthStats stats;

    long seen_clears = 0;
    // Placed elements a rule may still be invoked on (can_parent), counted as they change
    // through the loop; a body that changes other elements makes it a guess that
    // any_parent_left() checks when it reaches 0.
    long parents_left = 0;
    bool ran = false;
    std::vector<int> fresh;
    // The elements refine() found near the goal's centre, by (distance, id), within this radius.
    std::vector<std::pair<Element*, double>> near_goal;
    double near_goal_radius = 0;

    long debug_iteration = 0;
    std::function<void(const DebugFrame&)> debug_callback;
    long frame_every = 0;
    std::function<void(long, const std::vector<const Element*>&)> frame_callback;
    long iteration_every = 0;
    std::function<void(long)> iteration_callback;
    std::function<void(long, long)> progress_callback;
};

std::unique_ptr<SymmetryGroup> GrowthEngine::Impl::make_group() const {
    if (translations) return std::make_unique<SymmetryGroup>(translations->group, region);
    if (!options.symmetry) return nullptr;
    Point center;
    if (options.symmetry->center) {
        center = *options.symmetry->center;
        if (!center.finite()) throw InputError("--symmetry-center must be two finite numbers");
    } else {
        center = region.largest_inscribed_circle(raster.grid().pixel / 4).center;
    }
    return std::make_unique<SymmetryGroup>(*options.symmetry, center);
}

// The circles a rule is offered in turn under symmetry, each inside C (so as empty): C itself
// and C's largest circle centred on the nearest mirror; then both shrunk to clear their own
// images, and halved again and again down to the minimum radius (at most 8 times); last
// (`beside`: made only when the tries reach them, as most rules succeed before), C's largest
// circles clear of their own images on and off the mirrors (on the side of `toward`, the
// parent: beside a rotation centre, where C holds only an element whose images coincide with
// it), each halved likewise. Children that clash with their images on one (or a rule that
// failed because intersection() found such a clash) try the next.
std::vector<Circle> GrowthEngine::Impl::rule_goals(const Circle& goal, Point toward,
                                                   bool beside) const {
    const double tol = ornament.tolerance();
    std::vector<Circle> out;
    auto halve = [&](const std::vector<Circle>& from) {
        // Each circle's clearance once (it measures every transformation of the group).
        std::vector<double> reach;
        for (const Circle& c : from)
            reach.push_back(std::min(c.radius, group->clearance(c.center, tol)));
        double scale = 1;
        for (int halvings = 0; halvings <= 8; ++halvings, scale /= 2)
            for (std::size_t k = 0; k < from.size(); ++k) {
                const double r = reach[k] * scale;
                if (r < from[k].radius && (halvings == 0 || r >= min_radius))
                    out.push_back({from[k].center, r});
            }
    };
    if (!beside) {
        std::vector<Circle> bases{goal};
        const Point on_mirror = group->snap(goal.center, goal.radius);
        const double moved = distance(on_mirror, goal.center);
        if (moved > tol && moved < goal.radius) bases.push_back({on_mirror, goal.radius - moved});
        out = bases;
        halve(bases);
        return out;
    }
    std::vector<Circle> clear;
    for (const Circle& c : group->clear_circles_in(goal, toward, tol))
        if (c.radius >= min_radius) clear.push_back(c);
    out = clear;
    halve(clear);
    return out;
}

// A pattern whose first element leaves the centre along a curve (a vine, a stem) cannot grow
// from a seed on the centre of a dN rosette: every curve crosses a mirror. When growth from the
// default seed ends with nothing beyond the seed's own children, a second seed goes inside the
// fundamental domain, on its bisector half way to the core's boundary, with its images.
bool GrowthEngine::Impl::second_seed() {
    if (!group || !group->rosette() || tried_second_seed || !options.seeds.empty()) return false;
    tried_second_seed = true;
    for (const Element* e : ornament.view())
        if (e->depth > 1) return false;
    const auto edges = group->domain_edges(1);
    if (edges.empty()) return false;
    const Point c = group->center();
    const Vector bisector = (edges[0].second - c) + (edges[1].second - c);
    if (bisector.length() < 1e-9) return false;
    const double reach = core_distance_to_boundary(region, *group, c);
    const Point s = c + bisector.normalized() * (reach / 2);
    if (!core_contains(region, *group, s)) return false;
    std::unique_ptr<Element> e(pattern.seed->create());
    static_cast<PointProxy&>(e->proxy(0)).set(s);
    std::vector<std::unique_ptr<Element>> one;
    one.push_back(std::move(e));
    if (!commit(std::move(one), nullptr)) return false;
    exclude.clear();
    sync_exclude_clears();
    return true;
}

// Growth from the default seed reaches the special points of a group (its rotation centres, its
// mirrors) worse than the rest: a hole stays on the corner of a p4m tile while the tile's
// centre, of the same kind, fills; the centre of a rosette, where the seed's curves leave,
// stays empty. When growth ends, each such point whose hole is larger than the bar gets a seed
// of its own, with its images, and the hole as C: first on the point (an element there
// coinciding with its images, a fill called again on the hole), then, for the holes that stay,
// beside it, at the largest circle in the hole clear of its own images (an element that is
// not symmetric fits only there). One restart per call; one round of restarts per stretch of
// growth between two calls of %exhausted (a phase of a pattern with phases: the flowers of a
// later phase may fill what the vines could not). Under a group with translations the points
// are one rotation centre of each class and, on each mirror edge of the fundamental domain,
// its point with the largest hole; the bar is 1.1 times the best-filled class's hole (plus
// epsilon) as the round begins. A rosette's centre, the first thing an artist fills, is
// offered whenever anything fits there. Where the rules fail in the hole a restart costs a
// synthesis on each circle offered, so the restart beside a point is skipped or asks only the
// elements not asked on it.
bool GrowthEngine::Impl::centre_seed() {
    if (!group || !options.seeds.empty()) return false;
    const double tol = ornament.tolerance();
    // The hole on c: its distance to the nearest element that is not a seed, or to the
    // region's boundary (a frieze's band). With `bar`, a hole no larger than it may be
    // answered by the boundary's distance alone.
    auto hole = [&](Point c, double bar = -std::numeric_limits<double>::infinity()) {
        const double wall = region.distance_to_boundary(c);
        if (!(wall > bar)) return wall;
        for (double reach = 4 * epsilon; reach < wall; reach *= 2)
            for (const auto& [e, d] : ornament.within(c, reach))
                if (&e->type() != pattern.seed) return std::min(d, wall);
        return wall;
    };
    if (!centre_restarts || (centre_restarts->empty() && centre_round != exhausted_calls &&
                             ornament.size() != centre_round_size)) {
        centre_round = exhausted_calls;
        centre_offered.clear();
        centre_restarts.emplace();
        std::vector<Point> points = group->centre_classes(raster.grid().pixel / 4);
        if (group->rosette()) {
            centre_bar = std::max(2 * epsilon, min_radius + epsilon);
        } else {
            double best = std::numeric_limits<double>::infinity();
            for (Point c : points)
                if (region.contains(c)) best = std::min(best, hole(c));
            centre_bar = std::max(2 * epsilon, 1.1 * best + epsilon);
            // On each mirror edge, the sample (a pixel apart, the ends left out: they are
            // rotation centres or the frame's edge) with the largest hole; only where the plane
            // is periodic (a tile, a closed band): on an open band's mirrors the hole is mostly
            // the band's edge.
            const double step = raster.grid().pixel;
            const bool periodic = translations && translations->group.window;
            for (const auto& [a, b] : periodic ? group->mirror_edges(raster.grid().pixel / 4)
                                               : std::vector<std::pair<Point, Point>>{}) {
                const int n = static_cast<int>(std::ceil(distance(a, b) / step));
                double room = centre_bar;
                std::optional<Point> at;
                for (int k = 1; k < n; ++k) {
                    const Point p = a + (b - a) * (static_cast<double>(k) / n);
                    // Whether the region holds p last: the dearer test, the same answer.
                    const double r = hole(p, room);
                    if (r > room && region.contains(p)) {
                        room = r;
                        at = p;
                    }
                }
                if (at) points.push_back(*at);
            }
        }
        for (bool beside : {false, true})
            for (Point c : points) centre_restarts->emplace_back(c, beside);
    }
    while (!centre_restarts->empty()) {
        const auto [c, beside] = centre_restarts->front();
        centre_restarts->erase(centre_restarts->begin());
        if (!region.contains(c)) continue;
        const double r = hole(c);
        if (r <= centre_bar) continue;
        // A seed on the point that grew while the hole stayed fills elsewhere, not the hole:
        // one beside it would do the same.
        const CentreOffer* on_centre = nullptr;
        for (const CentreOffer& o : centre_offered)
            if (distance(o.centre, c) <= epsilon) on_centre = &o;
        if (beside && on_centre && on_centre->grew && r >= on_centre->hole - epsilon) continue;
        Point s = c;
        if (beside) {
            const std::vector<Circle> clear = group->clear_circles_in({c, r}, c, tol);
            if (clear.empty() || clear.back().radius < min_radius) continue;
            // On that circle's rim nearest the point: a rule that starts a curve from its seed
            // and winds it round C (a spiral) can, offered that circle; an element round the
            // seed fits there as well, between the mirrors.
            const Circle& room = clear.back();
            const Vector in = c - room.center;
            s = in.length() > tol ? room.center - in * (room.radius / in.length()) : room.center;
        }
        if (!region.contains(s)) continue;
        std::unique_ptr<Element> e(pattern.seed->create());
        static_cast<PointProxy&>(e->proxy(0)).set(s);
        Element* seed = e.get();
        std::vector<std::unique_ptr<Element>> one;
        one.push_back(std::move(e));
        if (!commit(std::move(one), nullptr)) continue;
        // The hole itself is the restart's C: the seed and every element round the hole are
        // offered it, and the circles inside it (rule_goals()). The seed is asked there only.
        // An element the hole was offered to on the point, it refused or grew elsewhere
        // (the hole stays): the restart beside the point offers it to the others only.
        ++stats.iterations;
        restart_goal = true;
        if (beside && on_centre) restart_skip = &on_centre->offered;
        if (!beside)
            restart_offered = &centre_offered.emplace_back(CentreOffer{c, r, false, {}}).offered;
        const std::size_t before = ornament.size();
        near_goal_radius = 0;
        iterate({c, r});
        restart_goal = false;
        if (!beside) centre_offered.back().grew = ornament.size() > before;
        restart_skip = nullptr;
        restart_offered = nullptr;
        if (!seed->sterile) {
            seed->sterile = true;
            if (can_parent_type(*seed)) --parents_left;
        }
        return true;
    }
    centre_round_size = ornament.size();
    return false;
}

// Under a group with translations the default seed goes where its first element has the most
// room: the point of the fundamental domain (sampled on a 64 x 64 grid over the domain's
// bounds) farthest from its own images and from the region's boundary. A seed near a mirror or
// a rotation centre would leave its first element no room beside its images.
std::optional<Point> GrowthEngine::Impl::roomiest_in_domain() const {
    constexpr int kSamples = 64;
    Rect box{1e300, 1e300, -1e300, -1e300};
    for (const auto& [a, b] : group->domain_edges(0))
        for (Point p : {a, b})
            box = {std::min(box.x0, p.x), std::min(box.y0, p.y), std::max(box.x1, p.x),
                   std::max(box.y1, p.y)};
    std::optional<Point> best;
    double room = 0;
    const double tol = ornament.tolerance();
    std::size_t hint = 0;  // the image that ruled out the last point (clearance())
    for (int j = 0; j < kSamples; ++j)
        for (int i = 0; i < kSamples; ++i) {
            const Point p{box.x0 + (i + 0.5) / kSamples * box.width(),
                          box.y0 + (j + 0.5) / kSamples * box.height()};
            if (!group->in_domain(p, 0)) continue;
            // Only a point with more room than the best so far matters: the boundary's distance
            // first, the images only while it can beat it, whether the region holds it last
            // (the dearest test, and the same answer in any order).
            const double boundary = region.distance_to_boundary(p);
            if (!(boundary > room)) continue;
            const double r = std::min(group->clearance(p, tol, room, &hint), boundary);
            if (r > room && region.contains(p)) {
                room = r;
                best = p;
            }
        }
    return best;
}

// The pixels (inclusive) an element may cover, with two pixels to spare; clamped far beyond
// the grid.
PixelBox GrowthEngine::Impl::pixel_box(const Rect& b) const {
    const GridFrame& g = raster.grid();
    auto at = [&](double v, double origin, int size, int spare) {
        const double i = std::floor((v - origin) / g.pixel) + spare;
        return static_cast<int>(std::clamp(i, -2.0 - size, 2.0 + 2 * size));
    };
    return {at(b.x0, g.x0, g.width, -2), at(b.y0, g.y0, g.height, -2), at(b.x1, g.x0, g.width, 2),
            at(b.y1, g.y0, g.height, 2)};
}

std::vector<Point> GrowthEngine::Impl::orbit_of_point(Point p) const {
    if (!group) return {p};
    return point_orbit(*group, p, ornament.tolerance(), region.bounds());
}

// An image g(e) overlaps a placed y = t(f) just when e overlaps h(f), h = g^-1 t: an element
// (or image) of f's family near e, when e lies inside the window and every fundamental element
// does (then h is among the group's transformations and h(f) meets the window, so it is
// placed). The images' checks then need only the families of the elements placed near e: the
// same pairs tested as by a query over the whole box, so the same answer to the bit, and the
// images far from the domain need not be indexed.
bool GrowthEngine::Impl::per_orbit(const Element& e) const {
    return translations && translations->group.window && families_whole && e.proxy_count() > 0 &&
           group->keeps_within(bounds_of(e), near_margin()) == 1;
}

// How far apart two proxies may seem by their bounds and still meet after carrying both by an
// isometry (rounding, and the curve solvers' resolution), with room to spare.
double GrowthEngine::Impl::near_margin() const {
    const Rect& w = *translations->group.window;
    const double scale =
        1 + std::max({std::abs(w.x0), std::abs(w.x1), std::abs(w.y0), std::abs(w.y1)});
    return 1e-4 * scale + 10 * ornament.tolerance();
}

std::vector<GrowthEngine::Impl::NearProxy> GrowthEngine::Impl::family_near(const Element& e) const {
    const double m = near_margin();
    std::vector<NearProxy> out;
    std::vector<int> seen;
    for (std::size_t k = 0; k < e.proxy_count(); ++k) {
        const Rect b = e.proxy(k).bounds();
        ornament.for_each_meeting({b.x0 - m, b.y0 - m, b.x1 + m, b.y1 + m}, [&](const Element& z) {
            const int f = original_of(z).id;
            if (std::find(seen.begin(), seen.end(), f) != seen.end()) return;
            seen.push_back(f);
            for (const Element* y : families[static_cast<std::size_t>(f)]) {
                // A curve's bounds cost a solve: each element's measured once, when first near.
                const auto id = static_cast<std::size_t>(y->id);
                if (family_bounds_at.size() <= id) family_bounds_at.resize(id + 1, -1);
                if (family_bounds_at[id] < 0) {
                    family_bounds_at[id] = static_cast<long>(family_bounds.size());
                    for (std::size_t p = 0; p < y->proxy_count(); ++p)
                        family_bounds.push_back(y->proxy(p).bounds());
                }
                const auto at = static_cast<std::size_t>(family_bounds_at[id]);
                for (std::size_t p = 0; p < y->proxy_count(); ++p)
                    out.push_back({y, p, family_bounds[at + p]});
            }
        });
    }
    std::sort(out.begin(), out.end(),
              [](const NearProxy& a, const NearProxy& b) { return a.bounds.x0 < b.bounds.x0; });
    return out;
}

// far_images[k] for the k-th image of a commit: true when the image lies too far from a
// rosette's wedge to meet the ornament's near zone or to reach a distance the field reads, so
// that neither test is made. The image lies within `reach` of g(middle) (its element within
// `reach` of the middle of its bounds), so its bounds within reach * sqrt(2) of it. A domain
// pixel's centre lies within a pixel of the wedge; pixel_box() widens a box by 2 pixels and
// rounds it out by a third.
void GrowthEngine::Impl::mark_far_images(const std::vector<std::unique_ptr<Element>>& children,
                                         const std::vector<Orbit>& orbits) {
    far_images.clear();
    if (!group->rosette() || debug_callback) return;
    const double px = raster.grid().pixel;
    const double zone = near_zone_reach(kNearCells) + 2;
    const double field = circles->centre_reach_pixels() + 3 * std::sqrt(2.0) + 2;
    const double apart = std::max(zone, field) * px;
    if (!std::isfinite(apart)) return;
    for (std::size_t k = 0; k < orbits.size(); ++k) {
        const Element& e = *children[k];
        const bool boxed = e.proxy_count() > 0;
        const Rect b = boxed ? bounds_of(e) : Rect{};
        const Point middle = b.center();
        const double reach = 0.5 * std::hypot(b.width(), b.height());
        const double margin = px + 1e-9 * (1 + std::abs(middle.x) + std::abs(middle.y) + reach);
        for (const Isometry& g : orbits[k].images)
            far_images.push_back(boxed && group->domain_gap(g.apply(middle)) >
                                              apart + reach * std::sqrt(2.0) + margin);
    }
}

// Commits the children of one success. Under symmetry each comes with its images, after them
// in id order; a child whose images clash (orbit.hpp) is dropped, and when none is left nothing
// is committed (false).
bool GrowthEngine::Impl::commit(std::vector<std::unique_ptr<Element>> children, Element* parent) {
    fresh.clear();
    std::vector<Orbit> orbits;
    if (group) {
        std::vector<const Element*> batch;
        for (const auto& child : children) batch.push_back(child.get());
        const double tol = ornament.tolerance();
        std::function<bool(const Element&, const Proxy&, const Isometry&)> hits_placed;
        const Element* near_of = nullptr;
        std::vector<NearProxy> near;  // the families of the elements placed near it
        double near_width = 0;        // the widest of their bounds
        bool by_family = false;       // per_orbit() of that element
        if (!group->rosette())
            hits_placed = [&](const Element& e, const Proxy& p, const Isometry& g) {
                auto other = [&](const Element& y) {
                    const ImageElement* image = as_image(y);
                    return !same_isometry(image ? image->transform() : Isometry{}, g, tol);
                };
                if (near_of != &e) {
                    near_of = &e;
                    by_family = per_orbit(e);
                    near = by_family ? family_near(e) : std::vector<NearProxy>();
                    near_width = 0;
                    for (const NearProxy& n : near)
                        near_width = std::max(near_width, n.bounds.x1 - n.bounds.x0);
                }
                if (!by_family) return ornament.overlaps_any(p, other);
                const Rect box = p.bounds();
                // By their left edges: those meeting the box start within the widest one's
                // width left of it, and not beyond its right edge.
                const auto begin =
                    std::lower_bound(near.begin(), near.end(), box.x0 - near_width,
                                     [](const NearProxy& n, double x) { return n.bounds.x0 < x; });
                const auto end =
                    std::upper_bound(begin, near.end(), box.x1,
                                     [](double x, const NearProxy& n) { return x < n.bounds.x0; });
                for (auto it = begin; it != end; ++it)
                    if (boxes_meet(box, it->bounds) && other(*it->element) &&
                        overlaps(p, it->element->proxy(it->proxy), tol))
                        return true;
                return false;
            };
        auto placeable = placeable_orbits(
            batch, *group, core_region, tol,
            [&](const Proxy& p) {
                return ornament.overlaps_any(p, [](const Element& e) { return as_image(e); });
            },
            hits_placed);
        std::vector<std::unique_ptr<Element>> kept;
        for (std::size_t k = 0; k < children.size(); ++k) {
            if (!placeable[k]) continue;
            kept.push_back(std::move(children[k]));
            orbits.push_back(std::move(*placeable[k]));
        }
        if (kept.empty()) return false;
        children = std::move(kept);
    }
    for (auto& child : children) {
        child->parent = parent;
        child->depth = parent ? parent->depth + 1 : 0;
        child->children = 0;
    }
    const std::size_t count = children.size();
    std::size_t images = 0;
    for (const Orbit& orbit : orbits) images += orbit.elements.size();
    children.reserve(count + images);
    for (std::size_t k = 0; k < orbits.size(); ++k)
        for (auto& image : orbits[k].elements) {
            image->depth = children[k]->depth;  // made before the child had its place
            children.push_back(std::move(image));
        }
    const std::size_t placed = children.size();
    if (translations && translations->group.window)
        for (const auto& child : children) {
            const Element& f = original_of(*child);
            if (&f == child.get() && group->keeps_within(bounds_of(f), 0) != 1)
                families_whole = false;  // beyond the window: per_orbit() no longer holds
        }
    // A few elements and their images lie all over the grid: the field takes them one at a
    // time, each a local update, not as one placement spanning the grid (a bulk placement of a
    // library still goes in one).
    const bool one_by_one = group && placed > count && count <= kOneByOne;
    if (group) mark_far_images(children, orbits);
    const bool any_far = !far_images.empty();
    std::size_t n = 0;
    // The images' bounds (from `count` on), taken once for the ornament's zone and the
    // field's test below.
    for (Element* e :
         ornament.add_all(std::move(children), group ? count : placed,
                          group ? &image_bounds : nullptr, any_far ? &far_images : nullptr)) {
        // An image too far from the fundamental domain to change a distance read there stays
        // out of the buffer (it is in the ornament, for the queries and the output); a debug
        // frame shows the buffer, so with one every image goes in.
        if (translations && translations->group.window) {
            const Element& f = original_of(*e);
            if (families.size() <= static_cast<std::size_t>(f.id))
                families.resize(static_cast<std::size_t>(f.id) + 1);
            families[static_cast<std::size_t>(f.id)].push_back(e);
        }
        const std::size_t at = n++;
        if (at >= count && !debug_callback) {
            // Sterile, so no parent either way (images are).
            if (any_far && far_images[at - count]) continue;
            const CircleSource::Reach reach = circles->reach(pixel_box(image_bounds[at - count]));
            if (reach != CircleSource::Reach::tile) {
                // parents_left counts (a guess the loop checks when it reaches 0) as when the
                // coarse test let such an image in: the loop runs as it did.
                if (reach == CircleSource::Reach::block && can_parent(*e)) ++parents_left;
                continue;
            }
        }
        raster.add_element(*e, fresh);
        if (can_parent(*e)) ++parents_left;
        if (one_by_one) {
            circles->add_sites(fresh, 1);
            fresh.clear();
        }
    }
    if (parent) parent->children += static_cast<int>(count);
    if (!one_by_one) circles->add_sites(fresh, placed);
    return true;
}

// One seed per part of the region (an outer loop with its holes) at the centre of the part's
// largest inscribed circle, largest circle first (ties by y, then x); parts too small for a
// circle of the minimum radius get none, unless no part is large enough (then the largest).
std::vector<Point> GrowthEngine::Impl::default_seeds() const {
    const double tolerance = raster.grid().pixel / 4;
    const std::vector<Region> parts = region.parts();
    if (parts.size() <= 1) return {region.largest_inscribed_circle(tolerance).center};
    std::vector<Circle> circles;
    for (const Region& part : parts) {
        const Circle c = part.largest_inscribed_circle(tolerance);
        if (region.contains(c.center)) circles.push_back(c);
    }
    std::sort(circles.begin(), circles.end(), [](const Circle& a, const Circle& b) {
        if (a.radius != b.radius) return a.radius > b.radius;
        if (a.center.y != b.center.y) return a.center.y < b.center.y;
        return a.center.x < b.center.x;
    });
    std::vector<Point> seeds;
    for (const Circle& c : circles)
        if (c.radius >= min_radius) seeds.push_back(c.center);
    if (seeds.empty() && !circles.empty()) seeds.push_back(circles.front().center);
    if (seeds.empty()) seeds.push_back(region.largest_inscribed_circle(tolerance).center);
    return seeds;
}

void GrowthEngine::Impl::place_seeds() {
    if (!pattern.seed) throw InputError(pattern.file + ": the pattern declares no seed type");
    std::vector<Point> seeds = options.seeds;
    if (seeds.empty() && group && !group->rosette()) {
        if (const std::optional<Point> s = roomiest_in_domain()) seeds.push_back(*s);
    } else if (seeds.empty() && group) {
        // The centre (it is its own image); a centre outside the region (a frame round a
        // hole) gives the default seeds whose images stay inside.
        if (core_contains(region, *group, group->center()))
            seeds.push_back(group->center());
        else
            for (Point s : default_seeds())
                if (core_contains(region, *group, s)) seeds.push_back(s);
        if (seeds.empty())
            throw InputError("no room for a seed: every point of the region has an image under " +
                             group->name() + " outside it; give --seed X,Y");
    }
    if (seeds.empty()) seeds = default_seeds();
    for (Point s : seeds)
        if (!s.finite() || !region.contains(s))
            throw InputError("seed " + format_number(s.x) + "," + format_number(s.y) +
                             " is outside the region " + region.name());
    if (group && group->rosette())
        for (Point s : seeds)
            if (!core_contains(region, *group, s))
                throw InputError("seed " + format_number(s.x) + "," + format_number(s.y) +
                                 ": an image of it under " + group->name() +
                                 " is outside the region " + region.name());
    for (Point s : seeds) {
        std::unique_ptr<Element> e(pattern.seed->create());
        if (!e || e->proxy_count() != 1 || e->proxy(0).kind() != ProxyKind::point)
            throw InputError(pattern.file + ": the seed type must have exactly one point proxy");
        static_cast<PointProxy&>(e->proxy(0)).set(s);
        std::vector<std::unique_ptr<Element>> one;
        one.push_back(std::move(e));
        commit(std::move(one), nullptr);
    }
    circles->start();
}

void GrowthEngine::Impl::sync_exclude_clears() {
    if (exclude.clear_count() == seen_clears) return;
    seen_clears = exclude.clear_count();
    circles->release_all();
}

std::optional<EmptyCircle> GrowthEngine::Impl::find() {
    sync_exclude_clears();
    return circles->find(exclude);
}

// The chosen circle, grown to the exact distance from its centre to the nearest element (the
// raster circle is a lower bound of it, within about a pixel). Nothing when, measured exactly,
// the boundary is at least as near: the paper discards circles stopped by the boundary.
std::optional<Circle> GrowthEngine::Impl::refine(const EmptyCircle& found) {
    Circle c = found.circle;
    // On a mirror or the centre, within a pixel: exactly there, so that an element placed on C
    // can coincide with its images.
    if (group) c.center = group->snap(c.center, raster.grid().pixel);
    // The raster radius is within about 1.5 pixels below the exact one; iterate() wants the
    // elements within epsilon of the exact circle too. The nearest obstacle pixel's centre is
    // at most the field's distance away (city-block distances are longer still), an element
    // there about a pixel more: the search widens to that before it widens fourfold (with the
    // Manhattan metric the raster circle is ~0.7 of the exact one, and fourfold would gather
    // some 16 times the elements needed).
    const double likely =
        (std::sqrt(static_cast<double>(found.d2)) + 1.5) * raster.grid().pixel + epsilon;
    // iterate() wants the elements within epsilon of the nearest: no farther one is measured.
    near_goal = ornament.nearest_within(c.center, c.radius + 2 * raster.grid().pixel + epsilon,
                                        &near_goal_radius, likely, epsilon);
    if (near_goal.empty()) return std::nullopt;
    const double r = near_goal.front().second;
    if (!std::isfinite(r)) return std::nullopt;
    const double boundary_floor =
        circles->boundary_radius_pixels(found.pixel) * raster.grid().pixel;
    // The exact distance (lib2geom's nearest points, per image of the centre when the core
    // differs) only when the raster's floor leaves it open.
    if (boundary_floor < r) {
        const double boundary = core_region ? core_distance_to_boundary(region, *group, c.center)
                                            : region.distance_to_boundary(c.center);
        if (boundary <= r) return std::nullopt;
    }
    c.radius = r;
    return c;
}

bool GrowthEngine::Impl::any_parent_left() {
    if (parents_left > 0) return true;
    for (const Element* e : ornament.view())
        if (can_parent(*e)) ++parents_left;
    return parents_left > 0;
}

std::optional<Circle> GrowthEngine::Impl::find_goal() {
    // With no element left that a rule may be invoked on, every circle would only join the
    // exclude list: growth is over.
    if (!any_parent_left()) return std::nullopt;
    for (;;) {
        const std::optional<EmptyCircle> found = find();
        if (!found) return std::nullopt;
        if (const std::optional<Circle> goal = refine(*found)) {
            goal_found = *found;
            return goal;
        }
        circles->discard(*found);
    }
}

// %exhausted runs with the environment installed, like a rule body: it may clear the exclude
// list or draw random numbers.
Flow GrowthEngine::Impl::call_exhausted() {
    ++exhausted_calls;
    if (!pattern.exhausted) return STOP;
    try {
        Flow flow = STOP;
        {
            Environment::Scope scope(&env);
            const detail::RunningBody running(detail::body_label(
                &pattern.exhausted, pattern.file, pattern.exhausted_line, "%exhausted"));
            flow = pattern.exhausted() == CONTINUE ? CONTINUE : STOP;
        }
        sync_exclude_clears();
        return flow;
    } catch (const RuleFailure&) {
        throw;
    } catch (const InputError&) {
        throw;  // bad input found by a library (exit 1), as from a rule body
    } catch (const std::exception& e) {
        throw RuleFailure(pattern.file, pattern.exhausted_line, "%exhausted",
                          std::string("exception thrown: ") + e.what());
    } catch (...) {
        throw RuleFailure(pattern.file, pattern.exhausted_line, "%exhausted",
                          "unknown exception thrown");
    }
}

void GrowthEngine::Impl::iterate(const Circle& goal) {
    std::vector<Element*> parents;
    // Under symmetry, an image near C stands for its original, which sees C carried back.
    std::vector<Circle> goals;
    auto consider = [&](Element* e) {
        if (!group) {
            if (!e->sterile) parents.push_back(e);
            return;
        }
        const ImageElement* image = as_image(*e);
        Element* original = image ? &ornament.at(image->original().id) : e;
        if (original->sterile ||
            std::find(parents.begin(), parents.end(), original) != parents.end())
            return;
        if (restart_skip &&
            std::find(restart_skip->begin(), restart_skip->end(), original) != restart_skip->end())
            return;
        parents.push_back(original);
        Circle g = goal;
        if (image) g.center = image->transform().inverse().apply(goal.center);
        goals.push_back(g);
    };
    const double reach = goal.radius + epsilon;
    if (group) goals.reserve(near_goal.size());
    if (near_goal_radius >= reach) {  // refine() found them all
        for (const auto& [e, d] : near_goal)
            if (d <= reach) consider(e);
    } else {
        for (const auto& [e, d] : ornament.within(goal.center, reach)) consider(e);
    }
    if (restart_offered) restart_offered->assign(parents.begin(), parents.end());

    const bool debugging = debug_callback && stats.iterations == debug_iteration;
    DebugFrame frame;
    if (debugging) {
        frame.iteration = stats.iterations;
        frame.grid = raster.grid();
        frame.occupancy = raster.occupancy();
        for (const Circle& c :
             detail::distinct_circles(circles->candidate_circles(kDebugCandidates)))
            (exclude.any_inside(c) ? frame.excluded : frame.eligible).push_back(c);
        frame.chosen = goal;
        frame.candidates.assign(parents.begin(), parents.end());
        frame.placed = ornament.view();
        if (group) {
            const Rect b = region.bounds();
            frame.domain = group->domain_edges(2 * std::hypot(b.width(), b.height()));
        }
    }

    const std::size_t before = ornament.size();
    bool success = false;
    bool clashed = false;  // some rule's children clashed with their own images
    for (std::size_t n = 0; n < parents.size(); ++n) {
        Element* parent = parents[n];
        const auto rules = rules_by_parent.find(&parent->type());
        if (rules == rules_by_parent.end()) continue;
        const bool could_parent = !parent->sterile;
        for (int r : rules->second) {
            if (parent->sterile) break;  // a failed rule may have made it sterile
            const RuleInfo& rule = pattern.rules[static_cast<std::size_t>(r)];
            // Under symmetry a success whose children clash with their images is tried again
            // on smaller circles inside C (rule_goals(), made only then: most rules succeed
            // or fail on C itself); without, the one goal.
            std::vector<Circle> tries{group ? goals[n] : goal};
            std::size_t clear_from = 1;
            bool beside_due = false;  // the circles beside C's centre, added when reached
            Point toward;
            for (std::size_t t = 0;; ++t) {
                if (t == tries.size() && beside_due) {
                    beside_due = false;
                    const std::vector<Circle> more = rule_goals(tries[0], toward, true);
                    tries.insert(tries.end(), more.begin(), more.end());
                }
                if (t >= tries.size() || parent->sterile) break;
                const Circle tried = tries[t];
                env.set_goal(tried);
                // A restart's fill library fills the circle offered (its part in the
                // fundamental domain), not the region again. Made only for a rule that reads
                // it: the panel steers no other rule.
                std::optional<Region> panel;
                if (restart_goal)
                    env.set_panel([&, tried]() -> const Region* {
                        if (!panel)
                            panel = hole_region(*group, tried, ornament.tolerance(),
                                                0.02 * raster.grid().pixel);
                        return &*panel;
                    });
                const long refusals = env.orbit_refusals();
                const bool was_sterile = parent->sterile;
                Result result = FAILURE;
                std::vector<std::unique_ptr<Element>> children;
                {
                    Environment::Scope scope(&env);
                    RuleCall call(rule, *parent);
                    result = call.run();
                    if (result == SUCCESS) children = call.take_children();
                }
                env.set_panel(nullptr);
                sync_exclude_clears();
                // A failure the element's own images did not cause is the rule's answer for C
                // and the circles about its centre or on its mirror; the circles beside them
                // (clear_from on) are tried still, each for itself.
                if (result != SUCCESS && env.orbit_refusals() == refusals) {
                    if (t == 0) break;
                    if (t < clear_from) t = clear_from - 1;
                    continue;
                }
                if (result == SUCCESS && commit(std::move(children), parent)) {
                    success = true;
                    break;
                }
                clashed = true;
                // The success did not happen: a rule that made its parent sterile with it (a
                // seed's one rule) has not used it up.
                if (result == SUCCESS) parent->sterile = was_sterile;
                if (group && t == 0) {
                    toward = parent->proxy(0).bounds().center();
                    const std::vector<Circle> more = rule_goals(tried, toward, false);
                    tries.insert(tries.end(), more.begin() + 1, more.end());
                    clear_from = tries.size();
                    beside_due = true;
                }
            }
            if (success) {
                ++stats.rules[static_cast<std::size_t>(r)].successes;
                break;
            }
            ++stats.rules[static_cast<std::size_t>(r)].failures;
        }
        if (could_parent && parent->sterile) --parents_left;
        if (success) break;
    }

    if (restart_goal) {
        // Not a circle of the finder: nothing of it to drop or exclude.
    } else if (success) {
        std::vector<int> removed;
        for (Point p : orbit_of_point(goal.center)) exclude.remove_within(p, epsilon, &removed);
        circles->release(removed);
    } else if (clashed) {
        // The rules would place something here, only not clear of its images: this circle is
        // dropped (until its distance changes), its neighbours stay open. An exclude point
        // would close the whole neighbourhood, in a narrow domain all of it.
        circles->discard(goal_found);
    } else {
        for (Point p : orbit_of_point(goal.center)) exclude.add(p);
    }

    if (debugging) {
        const auto all = ornament.view();
        frame.added.assign(all.begin() + static_cast<std::ptrdiff_t>(before), all.end());
        debug_callback(frame);
    }
}

void GrowthEngine::Impl::grow() {
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    int fruitless_rounds = 0;
    long size_at_continue = -1;
    for (;;) {
        if (static_cast<long>(ornament.size()) >= options.max_elements) {
            stats.stop_reason = "max-elements";
            break;
        }
        if (stats.iterations >= options.max_iterations) {
            stats.stop_reason = "max-iterations";
            break;
        }
        if (options.time_limit > 0 && elapsed() >= options.time_limit) {
            stats.stop_reason = "time-limit";
            break;
        }
        std::optional<Circle> goal = find_goal();
        if (!goal && (second_seed() || centre_seed())) continue;
        if (!goal) {
            stats.stop_reason = "exhausted";
            if (call_exhausted() != CONTINUE) break;
            // A round between two CONTINUEs that placed nothing: the next one can only differ
            // through the pattern's own state; give up after a few.
            const long size = static_cast<long>(ornament.size());
            fruitless_rounds = size == size_at_continue ? fruitless_rounds + 1 : 0;
            size_at_continue = size;
            if (fruitless_rounds >= kMaxFruitlessRounds) break;
            exclude.clear();
            // With an empty exclude list and no circle, nothing can ever make one.
            goal = find_goal();
            if (!goal) break;
        }
        ++stats.iterations;
        iterate(*goal);
        if (frame_callback && frame_every > 0 && stats.iterations % frame_every == 0)
            frame_callback(stats.iterations, ornament.view());
        if (iteration_callback && iteration_every > 0 && stats.iterations % iteration_every == 0)
            iteration_callback(stats.iterations);
        if (progress_callback && stats.iterations % kProgressEvery == 0)
            progress_callback(stats.iterations, static_cast<long>(ornament.size()));
    }
    stats.exclude_points = static_cast<long>(exclude.size());
    stats.seconds = elapsed();
    if (progress_callback) progress_callback(stats.iterations, static_cast<long>(ornament.size()));
}

GrowthEngine::GrowthEngine(const Pattern& pattern, const Region& region, GrowthOptions options)
    : impl_(std::make_unique<Impl>(pattern, checked(region, options))) {}

GrowthEngine::~GrowthEngine() = default;

void GrowthEngine::run() {
    if (impl_->ran) throw std::logic_error("GrowthEngine::run() called twice");
    impl_->ran = true;
    const auto start = Clock::now();
    impl_->place_seeds();
    impl_->grow();
    impl_->stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
}

void GrowthEngine::on_debug_frame(long debug_iteration,
                                  std::function<void(const DebugFrame&)> callback) {
    impl_->debug_iteration = debug_iteration;
    impl_->debug_callback = std::move(callback);
}

void GrowthEngine::on_frame(
    long every, std::function<void(long iteration, const std::vector<const Element*>&)> callback) {
    impl_->frame_every = every;
    impl_->frame_callback = std::move(callback);
}

void GrowthEngine::on_iteration(long every, std::function<void(long iteration)> callback) {
    impl_->iteration_every = every;
    impl_->iteration_callback = std::move(callback);
}

void GrowthEngine::on_progress(std::function<void(long iteration, long elements)> callback) {
    impl_->progress_callback = std::move(callback);
}

void GrowthEngine::release_growth_state() {
    Impl& g = *impl_;
    g.circles.reset();
    g.raster.release();
    g.ornament.release_index();
    std::vector<int>().swap(g.fresh);
    std::vector<std::pair<Element*, double>>().swap(g.near_goal);
}

std::vector<const Element*> GrowthEngine::elements() const { return impl_->ornament.view(); }
const GrowthStats& GrowthEngine::stats() const { return impl_->stats; }
const GridFrame& GrowthEngine::grid() const { return impl_->raster.grid(); }

}  // namespace acanthus
