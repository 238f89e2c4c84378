// The public API: shape sets, method names, and fill() over a region or the running ornament.
#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <acanthus/stdlib/dartfill.hpp>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "growth/filling_hole.hpp"
#include "methods.hpp"
#include "shape_list.hpp"

namespace acanthus::dartfill {

Method parse_method(std::string_view text) {
    if (text == "naive") return Method::naive;
    if (text == "fillgap" || text == "fill-gap" || text == "fill_gap") return Method::fill_gap;
    if (text == "medial") return Method::medial;
    throw InputError("dartfill: unknown method '" + std::string(text) +
                     "' (expected naive, fillgap or medial)");
}

std::string_view to_string(Method method) {
    switch (method) {
        case Method::naive:
            return "naive";
        case Method::fill_gap:
            return "fillgap";
        case Method::medial:
            return "medial";
    }
    return "?";
}

ShapeSet::ShapeSet() : shapes_(std::make_shared<detail::ShapeList>()) {}
ShapeSet::~ShapeSet() = default;
ShapeSet::ShapeSet(const ShapeSet&) = default;
ShapeSet::ShapeSet(ShapeSet&&) noexcept = default;
ShapeSet& ShapeSet::operator=(const ShapeSet&) = default;
ShapeSet& ShapeSet::operator=(ShapeSet&&) noexcept = default;

namespace {
// Shapes are shared between copies; adding to one copy must not change another.
detail::ShapeList& writable(std::shared_ptr<detail::ShapeList>& list) {
    if (list.use_count() > 1) list = std::make_shared<detail::ShapeList>(*list);
    return *list;
}
}  // namespace

ShapeSet& ShapeSet::add_points(std::string name, std::vector<Point> outline) {
    writable(shapes_).shapes.push_back(Shape::from_points(std::move(name), std::move(outline)));
    return *this;
}

ShapeSet& ShapeSet::add_path(std::string name, std::string_view path_data, double tolerance) {
    writable(shapes_).shapes.push_back(
        Shape::from_path_data(std::move(name), path_data, tolerance));
    return *this;
}

ShapeSet& ShapeSet::add_svg_file(const std::string& file, double tolerance) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw InputError(file + ": dartfill: cannot open shape file");
    Region region = Region::from_svg_file(file);
    Rect b = region.bounds();
    if (!(tolerance > 0)) tolerance = std::max(b.width(), b.height()) / 500;
    auto rings = region.rings(tolerance);
    if (rings.empty()) throw InputError(file + ": dartfill: the file holds no filled outline");
    std::vector<Shape> loaded;
    for (std::size_t k = 0; k < rings.size(); ++k) {
        std::string name = file + "#" + std::to_string(k);
        // A ring inside another would be a hole; exclusive regions have none.
        for (std::size_t m = 0; m < rings.size(); ++m) {
            if (m == k || rings[m].size() < 3) continue;
            Shape outer = Shape::from_points(file + "#" + std::to_string(m), rings[m]);
            PlacedShape probe(outer, 0, {outer.center(), 0, 1});
            if (!rings[k].empty() && probe.contains(rings[k].front()))
                throw InputError(file + ": dartfill: outline " + std::to_string(k) +
                                 " lies inside outline " + std::to_string(m) +
                                 "; shapes with holes are not supported");
        }
        loaded.push_back(Shape::from_points(name, rings[k]));
    }
    auto& list = writable(shapes_).shapes;
    for (auto& s : loaded) list.push_back(std::move(s));
    return *this;
}

std::size_t ShapeSet::size() const { return shapes_->shapes.size(); }
const std::string& ShapeSet::name(std::size_t i) const { return shapes_->shapes.at(i).name(); }
const std::vector<Point>& ShapeSet::outline(std::size_t i) const {
    return shapes_->shapes.at(i).outline();
}
std::size_t ShapeSet::triangle_count(std::size_t i) const {
    return shapes_->shapes.at(i).triangles().size();
}
double ShapeSet::area(std::size_t i) const { return shapes_->shapes.at(i).area(); }
Rect ShapeSet::bounds(std::size_t i) const { return shapes_->shapes.at(i).bounds(); }
double ShapeSet::radius(std::size_t i) const { return shapes_->shapes.at(i).radius(); }

namespace {

// How often a fill in a hole of a symmetric ornament halves its shapes when none fits.
constexpr int kHoleHalvings = 2;

void check_options(const ShapeSet& shapes, const Options& o) {
    auto bad = [](const std::string& why) { throw InputError("dartfill: " + why); };
    if (shapes.empty()) bad("no shapes to place");
    if (!(o.scale_min > 0) || !(o.scale_max >= o.scale_min) || !std::isfinite(o.scale_max))
        bad("scale range must satisfy 0 < scale_min <= scale_max");
    if (!(o.rotation_max >= o.rotation_min) || !std::isfinite(o.rotation_max) ||
        !std::isfinite(o.rotation_min))
        bad("rotation range must satisfy rotation_min <= rotation_max");
    if (!(o.exponent >= 0) || !std::isfinite(o.exponent)) bad("exponent must be >= 0");
    if (o.candidates < 1) bad("candidates must be at least 1");
    if (o.naive_cancellations < 1 || o.gap_cancellations < 1 || o.sparse_cancellations < 0)
        bad("cancellation limits must be positive");
    if (o.rotations < 1) bad("rotations must be at least 1");
    if (o.resolution != 0 && (o.resolution < 8 || o.resolution > 8192))
        bad("resolution must be 0 (automatic) or 8 to 8192 pixels");
}

FillResult run(const ShapeSet& shapes, const Container& container, const Options& options,
               Random& random) {
    check_options(shapes, options);
    auto start = std::chrono::steady_clock::now();
    FillContext context(shapes.list().shapes, container, options, random);
    Layout layout(context.tolerance());
    FillResult result;
    result.method = options.method;
    switch (options.method) {
        case Method::naive:
            naive_dart_throwing(context, layout);
            break;
        case Method::fill_gap:
            fill_gap(context, layout, result.stats.rounds);
            break;
        case Method::medial:
            medial_fill(context, layout, result.stats.rounds);
            break;
    }
    double placed_area = 0;
    for (const PlacedShape& s : layout.shapes()) {
        result.placements.push_back(placement_of(s));
        placed_area += s.area();
    }
    result.stats.trials = context.trials();
    result.stats.space_area = container.area();
    result.stats.coverage = container.area() > 0 ? placed_area / container.area() : 0;
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace

FillResult fill(const ShapeSet& shapes, const Region& region, const Options& options,
                std::uint64_t seed) {
    auto container = RingContainer::from_region(region);
    Random random(seed);
    return run(shapes, *container, options, random);
}

FillResult fill_room(const ShapeSet& shapes, const Options& options, Environment& env,
                     bool in_hole) {
    Circle goal = env.goal();
    double cell = goal.radius > 0 ? goal.radius / 2 : 1.0;
    EnvironmentContainer container(env, goal.center, cell);
    if (container.area() == 0) {
        // area() is measured by the first raster; the naive method never makes one.
        container.rasterize(make_grid(container.bounds(), 256));
    }
    FillResult result = run(shapes, container, options, env.random());
    // In a hole the engine offers at a rotation centre or on a mirror, a shape of the options'
    // size may not clear its own images anywhere (by a 6-fold centre with mirrors it must lie in
    // a 30 degree wedge): smaller ones, down to a quarter of the size, may.
    Options smaller = options;
    for (int k = 0; k < kHoleHalvings && in_hole && result.placements.empty(); ++k) {
        smaller.scale_min /= 2;
        smaller.scale_max /= 2;
        result = run(shapes, container, smaller, env.random());
    }
    return result;
}

FillResult fill(const ShapeSet& shapes, const Options& options) {
    Environment* env = Environment::current();
    if (!env) throw std::logic_error("dartfill::fill(shapes, options) needs a running rule body");
    return fill_room(shapes, options, *env, acanthus::detail::filling_hole(*env));
}

}  // namespace acanthus::dartfill
