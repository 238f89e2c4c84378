// Refusals up front: a face thinner than a course has no place for one brick (the growth engine
// would only find that the seed misses it), and a facade whose estimate passes max_cells would
// run out of memory or time long after starting.
#include "facade_limits.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "facade_data.hpp"
#include "relieving_arch.hpp"
#include "ring_check.hpp"
#include "voussoirs.hpp"

namespace acanthus::cells::detail {

long expected_cells(const Facade& facade, const Options& o) {
    double quarters = 4;  // mean cell length along a course, in quarter bricks
    if (o.bond == Bond::header) quarters = 2;
    if (o.bond == Bond::english) quarters = 8.0 / 3;  // a course of each: 1/4 + 1/2 per quarter
    if (o.bond == Bond::flemish) quarters = 3;        // a stretcher and a header per 6 quarters
    double cell = quarters / 4 * (o.brick_length + o.mortar) * (o.brick_height + o.mortar);
    if (o.bond == Bond::ashlar) {
        const double unit = o.ashlar_unit > 0 ? o.ashlar_unit : o.brick_height + o.mortar;
        // Random sizes up to the maximum: about half of it each way, on average.
        cell = unit * unit * (o.ashlar_max_width + 1) / 2 * (o.ashlar_max_height + 1) / 2;
    }
    const double cells = std::round(facade.wall_area() / cell);
    return std::isfinite(cells) && cells > 0 ? static_cast<long>(std::min(cells, 1e15)) : 0;
}

namespace {

std::string with_commas(long n) {
    std::string s = std::to_string(n), out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (i > 0 && (s.size() - i) % 3 == 0) out += ',';
        out += s[i];
    }
    return out;
}

std::string number(double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

// True when every point of the face lies within half a course of its outline: shrunk by (just
// under) that, nothing is left.
bool thinner_than(const FacadeData& data, int face, double course) {
    // The rings are even-odd; a union orients holes against outer rings, as offsetting needs.
    ClipperLib::Clipper c;
    c.AddPaths(data.face_rings[face], ClipperLib::ptSubject, true);
    ClipperLib::Paths rings;
    c.Execute(ClipperLib::ctUnion, rings, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    ClipperLib::ClipperOffset offset;
    offset.AddPaths(rings, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
    ClipperLib::Paths inner;
    offset.Execute(inner, -0.49 * course * data.scale);
    double area = 0;
    for (const ClipperLib::Path& r : inner) area += ClipperLib::Area(r);
    return !(area > 0);
}

}  // namespace

void check_limits(const Facade& facade, const Options& o) {
    const FacadeData& data = facade.data();
    const long cells = expected_cells(facade, o);
    if (cells > o.max_cells)
        throw InputError(
            facade.name() + ": the wall would take about " + with_commas(cells) + " cells (" +
            number(facade.wall_area()) + " square units of wall), more than the limit of " +
            with_commas(o.max_cells) + " (cells_max_cells); is the drawing in the brick's units?");
    // An opening smaller than a tenth of a brick's face, or narrower than a joint, cannot be
    // left in brickwork (no piece that small is cut, and cells have no holes): a drawing error,
    // named rather than covered by a brick.
    // One box per outline (edges joined end to end), not per name: two shapes drawn touching
    // are one opening, and the part of the outline one of them keeps may be a line.
    const std::vector<Edge>& edges = facade.edges();
    std::vector<std::size_t> root(edges.size());
    for (std::size_t i = 0; i < root.size(); ++i) root[i] = i;
    auto find = [&](std::size_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    // Joined also where one's end is another's start (a jamb meets a round head smoothly, at
    // no corner): the outline's own vertices, shared by the two edges.
    std::map<std::pair<long long, long long>, std::size_t> at_end;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const Edge& e = edges[i];
        if (!e.opening || e.segments.empty()) continue;
        for (Point p : {e.segments.front().a, e.segments.back().b}) {
            const std::pair<long long, long long> key{std::llround(p.x * 1e6),
                                                      std::llround(p.y * 1e6)};
            auto [it, fresh] = at_end.try_emplace(key, i);
            if (!fresh) root[find(i)] = find(it->second);
        }
    }
    std::map<std::size_t, std::pair<std::string, Rect>> boxes;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const Edge& e = edges[i];
        if (!e.opening) continue;
        auto [it, fresh] = boxes.try_emplace(find(i), names_of(e), e.bounds);
        auto& [names, b] = it->second;
        if (fresh) continue;
        if (const std::string n = names_of(e); names.find(n) == std::string::npos)
            names += "\" and \"" + n;
        b = {std::min(b.x0, e.bounds.x0), std::min(b.y0, e.bounds.y0), std::max(b.x1, e.bounds.x1),
             std::max(b.y1, e.bounds.y1)};
    }
    const double face = o.brick_length * o.brick_height;
    for (const auto& [root_edge, box] : boxes) {
        const auto& [names, b] = box;
        if (b.width() * b.height() < 0.1 * face || std::min(b.width(), b.height()) < o.mortar)
            throw InputError(
                facade.name() + ": the opening \"" + names + "\" (" + number(b.width()) + " x " +
                number(b.height()) +
                ") is smaller than a tenth of a brick's face or narrower than a "
                "joint: no brickwork can be cut round it; remove it or draw it to size");
    }
    // A relieving arch stands over a lintel: an opening labelled so needs a straight level head,
    // wide enough that the arch rises a course over it.
    std::map<std::string, std::pair<const Edge*, bool>> relief;  // a straight head, an arc
    for (const Edge& e : facade.edges()) {
        if (!e.opening || !relieving(e)) continue;
        auto& [head, arc] = relief[names_of(e)];
        if (e.arc) arc = true;
        if (!e.arc && e.part == Part::top) head = &e;
    }
    for (const auto& [names, shape] : relief) {
        const auto [head, arc] = shape;
        if (!head || arc)
            throw InputError(facade.name() + ": the opening \"" + names +
                             "\" is labelled relieving but has " +
                             (head ? "an arched head too" : "no straight head") +
                             ": a relieving arch is turned over the lintel of a flat head; leave "
                             "out the label relieving");
        if (head->bounds.width() < relieving_least_span(o))
            throw InputError(facade.name() + ": the opening \"" + names +
                             "\" is labelled relieving but is " + number(head->bounds.width()) +
                             " wide, under the " + number(relieving_least_span(o)) +
                             " (six courses) a relieving arch needs to rise a course over its "
                             "lintel; leave out the label relieving");
    }
    // An arch needs wall beside its springing for its ring to bear on: where not even a
    // half-brick ring fits (an arched opening at the wall's very end), the opening is refused.
    const double ring =
        (o.arch_depth > 0 ? o.arch_depth : o.brick_length + o.mortar) * std::max(1, o.arch_rows);
    const RingPlan rings = plan_rings(facade, o, ring);
    for (const Edge& e : facade.edges()) {
        if (!e.arc || !e.opening) continue;
        auto it = rings.depth.find(arch_key(facade, e));
        if (it == rings.depth.end() || it->second > 0) continue;
        const std::string names = names_of(e);
        // Into another opening (two arches a few centimetres apart): both are named.
        const double half = (o.brick_length + o.mortar) / 2;
        const Edge* other = nullptr;
        for (const Edge* a : arch_arcs(facade, e))
            if (!other) other = opening_in_ring(facade, *a, half);
        if (other)
            throw InputError(facade.name() + ": the openings \"" + names + "\" and \"" +
                             names_of(*other) +
                             "\" are too close: the ring of the first's arch, even one half-brick "
                             "ring (" +
                             number(half) +
                             " deep), would reach into the second; move them apart or give one a "
                             "flat head");
        throw InputError(facade.name() + ": the opening \"" + names +
                         "\": the ring of its arch would reach past the wall, even one half-brick "
                         "ring (" +
                         number((o.brick_length + o.mortar) / 2) +
                         " deep): an arch needs wall beside its springing to bear on; move the "
                         "opening further from the wall's end or the other opening, or give it a "
                         "flat head");
    }
    // Two rings that meet even as half-brick rings: one would cut the other's stones.
    if (!rings.clash_a.empty())
        throw InputError(facade.name() + ": the openings \"" + rings.clash_a + "\" and \"" +
                         rings.clash_b +
                         "\" are too close: the rings of their arches would meet even as "
                         "half-brick rings (" +
                         number((o.brick_length + o.mortar) / 2) +
                         " deep); move them apart or give one a flat head");
    const double course = o.brick_height + o.mortar;
    for (std::size_t f = 0; f < data.faces.size(); ++f) {
        if (!thinner_than(data, static_cast<int>(f), course)) continue;
        std::string names;
        for (const std::string& n : data.face_walls[f]) names += (names.empty() ? "" : ", ") + n;
        throw InputError(facade.name() + ": " + (names.empty() ? "the wall" : names) +
                         ": the wall is thinner than a course (" + number(course) +
                         ": brick height and joint) everywhere in it: no brick fits");
    }
}

}  // namespace acanthus::cells::detail
