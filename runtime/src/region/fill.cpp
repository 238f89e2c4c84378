#include "region/fill.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <polyclipping/clipper.hpp>
#include <unordered_map>

#include "region/trace.hpp"

namespace acanthus::detail {
namespace {

struct IntPointHash {
    std::size_t operator()(const ClipperLib::IntPoint& p) const noexcept {
        return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(p.X) * 0x9E3779B97F4A7C15ULL ^
                                          static_cast<std::uint64_t>(p.Y));
    }
};

// A ring that passes through one point twice (two parts touching at a vertex, or a hole
// touching its outer loop) becomes one loop per visit, each keeping its direction. Clipper's
// StrictlySimple does the same but is quadratic in the ring's length.
void split_at_repeated_points(const ClipperLib::Path& ring, ClipperLib::Paths& out) {
    ClipperLib::Path stack;
    std::unordered_map<ClipperLib::IntPoint, std::size_t, IntPointHash> at;
    for (const ClipperLib::IntPoint& p : ring) {
        auto it = at.find(p);
        if (it == at.end()) {
            at.emplace(p, stack.size());
            stack.push_back(p);
            continue;
        }
        const std::size_t start = it->second;
        ClipperLib::Path loop(stack.begin() + static_cast<std::ptrdiff_t>(start), stack.end());
        for (std::size_t k = start + 1; k < stack.size(); ++k) at.erase(stack[k]);
        stack.resize(start + 1);
        if (loop.size() >= 3) out.push_back(std::move(loop));
    }
    if (stack.size() >= 3) out.push_back(std::move(stack));
}

}  // namespace

Geom::PathVector filled_area(const std::vector<FilledShape>& shapes) {
    Geom::OptRect frame;
    for (const FilledShape& s : shapes) frame.unionWith(s.paths.boundsFast());
    if (!frame || !(frame->width() > 0 || frame->height() > 0)) return {};
    const double size = std::max(frame->width(), frame->height());
    BoundaryTrace trace(*frame, kFillTolerance * size);

    // Each shape by its own rule: Clipper's union of a shape with itself resolves its
    // crossings and leaves outer rings positive and holes negative, which the nonzero union
    // of all shapes then reads as a renderer paints them one over another.
    ClipperLib::Paths all;
    for (const FilledShape& s : shapes) {
        ClipperLib::Paths rings = trace.add(s.paths);
        if (rings.empty()) continue;
        const ClipperLib::PolyFillType rule =
            s.evenodd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero;
        ClipperLib::Clipper clipper;
        clipper.PreserveCollinear(true);
        clipper.AddPaths(rings, ClipperLib::ptSubject, true);
        ClipperLib::Paths filled;
        clipper.Execute(ClipperLib::ctUnion, filled, rule, rule);
        all.insert(all.end(), filled.begin(), filled.end());
    }
    ClipperLib::Clipper clipper;
    clipper.PreserveCollinear(true);
    clipper.AddPaths(all, ClipperLib::ptSubject, true);
    ClipperLib::Paths united, result;
    clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    for (const ClipperLib::Path& ring : united) split_at_repeated_points(ring, result);

    // Specks far below anything drawable (1e-9 of the bounding square) are rounding debris.
    std::erase_if(result, [](const ClipperLib::Path& ring) {
        return std::abs(ClipperLib::Area(ring)) < 1e-9 * 1e18;
    });
    std::vector<std::uint64_t> keys;
    for (const ClipperLib::Path& ring : result) keys.push_back(trace.first_source(ring));
    std::vector<std::size_t> order(result.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&keys](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });

    Geom::PathVector out;
    for (std::size_t i : order) out.push_back(trace.rebuild(result[i]));
    return out;
}

}  // namespace acanthus::detail
