// Running a tree over a facade in the order of [4.2]: all corners, all edges (arcs first), then
// all faces.
#include <acanthus/environment.hpp>
#include <acanthus/error.hpp>
#include <acanthus/partial_maker.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "ashlar_rules.hpp"
#include "context_data.hpp"
#include "facade_limits.hpp"
#include "head_edge.hpp"
#include "relieving_arch.hpp"

namespace acanthus::cells {

std::string_view to_string(FeatureKind kind) {
    switch (kind) {
        case FeatureKind::corner:
            return "corner";
        case FeatureKind::edge:
            return "edge";
        case FeatureKind::face:
            return "face";
    }
    return "face";
}

std::string_view to_string(Part part) {
    switch (part) {
        case Part::top:
            return "top";
        case Part::bottom:
            return "bottom";
        case Part::side:
            return "side";
    }
    return "side";
}

Bond parse_bond(std::string_view text) {
    if (text == "running" || text == "stretcher") return Bond::running;
    if (text == "stack") return Bond::stack;
    if (text == "english") return Bond::english;
    if (text == "flemish") return Bond::flemish;
    if (text == "header") return Bond::header;
    if (text == "ashlar") return Bond::ashlar;
    throw InputError("cells: unknown bond \"" + std::string(text) +
                     "\" (running, stretcher, stack, english, flemish, header or ashlar)");
}

std::string_view to_string(Bond bond) {
    switch (bond) {
        case Bond::running:
            return "running";
        case Bond::stack:
            return "stack";
        case Bond::english:
            return "english";
        case Bond::flemish:
            return "flemish";
        case Bond::header:
            return "header";
        case Bond::ashlar:
            return "ashlar";
    }
    return "running";
}

AshlarMethod parse_ashlar_method(std::string_view text) {
    if (text == "merge") return AshlarMethod::merge;
    if (text == "rules") return AshlarMethod::rules;
    throw InputError("cells: unknown ashlar method \"" + std::string(text) + "\" (merge or rules)");
}

std::string_view to_string(AshlarMethod method) {
    return method == AshlarMethod::rules ? "rules" : "merge";
}

void check(const Options& o, const std::string& source_name) {
    auto bad = [&](const std::string& what) { throw InputError(source_name + ": cells: " + what); };
    auto positive = [](double v) { return std::isfinite(v) && v > 0; };
    if (!positive(o.brick_length) || !positive(o.brick_height))
        bad("the brick size must be positive (cells_brick=LENGTHxHEIGHT), not " +
            std::to_string(o.brick_length) + "x" + std::to_string(o.brick_height));
    if (!std::isfinite(o.mortar) || o.mortar < 0) bad("the mortar joint must be 0 or more");
    if (!std::isfinite(o.joint_tolerance) || o.joint_tolerance < 0)
        bad("the joint tolerance must be 0 or more (cells_joint_tolerance)");
    if (o.mortar >= std::min(o.brick_length, o.brick_height))
        bad("the mortar joint must be thinner than the brick");
    if (!std::isfinite(o.ashlar_unit) || o.ashlar_unit < 0)
        bad("cells_ashlar_unit must be 0 or more");
    if (o.ashlar_max_width < 1 || o.ashlar_max_height < 1)
        bad("the ashlar maximum size must be at least 1x1 grid units");
    if (o.ashlar_max_seam < 1) bad("cells_ashlar_seam must be at least 1");
    if (!std::isfinite(o.voussoir_width) || o.voussoir_width < 0 || !std::isfinite(o.arch_depth) ||
        o.arch_depth < 0)
        bad("arch stone sizes must be 0 (automatic) or more");
    if (o.arch_rows < 1) bad("cells_arch_rows must be at least 1");
    if (o.max_cells < 1) bad("cells_max_cells must be at least 1");
    if (o.lintel_bearing < 0 || o.lintel_courses < 1 || o.quoin_long < 1 || o.quoin_short < 1)
        bad("lintel bearing, lintel depth and quoin lengths must be positive");
}

void check(const Facade& facade, const Options& options) {
    check(options, facade.name());
    detail::check_limits(facade, options);
}

Texture texture(const Facade& facade, const Node& tree, const Options& options,
                std::uint64_t seed) {
    check(facade, options);
    auto start = std::chrono::steady_clock::now();
    Context context(facade, options, seed);
    // Room for a brick bond and its cut bricks at once: growing by doubling copies every cell
    // and touches twice the memory. Only reserved pages cost nothing; capped all the same.
    double bricks = facade.wall_area() / ((options.brick_length + options.mortar) *
                                          (options.brick_height + options.mortar));
    context.cells().reserve(static_cast<std::size_t>(
        std::min(1.25 * bricks + 4.0 * static_cast<double>(facade.corners().size()), 2e6)));
    context.data().expected_cells = detail::expected_cells(facade, options);
    Texture out;
    // The arches first, as they are built: the corners on an arc (springings, apexes), then the
    // arc edges (a ring springing tangent from its jambs has no corner), then the other corners
    // and edges, so no lintel, sill row or jamb brick laid from another opening notches a
    // voussoir: the walling is cut to the rings.
    auto on_arc = [&](const Corner& k) {
        for (int e : {k.edge_in, k.edge_out})
            if (e >= 0 && facade.edges()[static_cast<std::size_t>(e)].arc) return true;
        return false;
    };
    auto corners = [&](bool arcs) {
        for (std::size_t i = 0; i < facade.corners().size(); ++i)
            if (on_arc(facade.corners()[i]) == arcs)
                tree({FeatureKind::corner, static_cast<int>(i)}, context);
    };
    auto edges = [&](bool arcs) {
        for (std::size_t i = 0; i < facade.edges().size(); ++i)
            if (facade.edges()[i].arc == arcs)
                tree({FeatureKind::edge, static_cast<int>(i)}, context);
    };
    const auto laid = [&] { return static_cast<long>(context.cells().size()); };
    corners(true);
    const long arc_corners = laid();
    edges(true);
    // Relieving arches over their lintels next, before any walling or other head near them.
    for (std::size_t i = 0; i < facade.edges().size(); ++i)
        if (detail::head_edge(facade, {FeatureKind::edge, static_cast<int>(i)}) >= 0 &&
            detail::relieving(facade.edges()[i]))
            tree({FeatureKind::edge, static_cast<int>(i)}, context);
    const long arc_edges = laid() - arc_corners;
    corners(false);
    out.stats.corners = laid() - arc_edges;
    edges(false);
    out.stats.edges = laid() - out.stats.corners;
    for (std::size_t i = 0; i < facade.faces().size(); ++i)
        tree({FeatureKind::face, static_cast<int>(i)}, context);
    out.cells = std::move(context.cells());
    out.stats.faces = static_cast<long>(out.cells.size()) - out.stats.corners - out.stats.edges;
    out.stats.ashlar_rounds = context.data().ashlar_rounds;
    out.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

Texture texture(const Facade& facade, const Node& tree, const Options& options) {
    Environment* env = Environment::current();
    if (!env) throw std::logic_error("cells::texture(facade, tree, options) needs a rule body");
    return texture(facade, tree, options, env->random().next_u64());
}

namespace detail {

namespace {
PartialMakerSlot<Cell> g_partial_maker;
}  // namespace

bool set_partial_maker(PartialMaker maker) noexcept { return g_partial_maker.set(maker); }
PartialMaker partial_maker() noexcept { return g_partial_maker.get(); }

}  // namespace detail

}  // namespace acanthus::cells
