// Our variant: no random candidates. The ridge maxima of the same distance field are the centres
// of the largest empty circles; each is tried largest first, with the shape's pole (its most
// interior point) on the maximum and several rotations, before a cancellation is counted.
#include <algorithm>
#include <cmath>

#include "gap_field.hpp"
#include "methods.hpp"

namespace acanthus::dartfill {
namespace {

struct Candidate {
    int index;
    std::int64_t d2;
};

std::vector<Candidate> ridge_maxima(const GapField& gaps, const std::vector<std::uint8_t>& tried) {
    const GridFrame& g = gaps.grid();
    std::vector<Candidate> out;
    for (int j = 0; j < g.height; ++j) {
        for (int i = 0; i < g.width; ++i) {
            int idx = j * g.width + i;
            std::int64_t d2 = gaps.squared_distance(idx);
            if (d2 == 0 || tried[idx]) continue;
            bool maximum = true;
            for (int dj = -1; dj <= 1 && maximum; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    int ni = i + di, nj = j + dj;
                    if (ni < 0 || nj < 0 || ni >= g.width || nj >= g.height) continue;
                    if (gaps.squared_distance(nj * g.width + ni) > d2) {
                        maximum = false;
                        break;
                    }
                }
            if (maximum) out.push_back({idx, d2});
        }
    }
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
        return a.d2 != b.d2 ? a.d2 > b.d2 : a.index < b.index;
    });
    return out;
}

// A failed maximum's plateau neighbours would fail alike: retire a disc around it.
void retire(const GapField& gaps, std::vector<std::uint8_t>& tried, int index, std::int64_t d2) {
    const GridFrame& g = gaps.grid();
    int r = std::max(1, static_cast<int>(0.25 * std::sqrt(static_cast<double>(d2))));
    int ci = index % g.width, cj = index / g.width;
    for (int j = std::max(0, cj - r); j <= std::min(g.height - 1, cj + r); ++j)
        for (int i = std::max(0, ci - r); i <= std::min(g.width - 1, ci + r); ++i)
            if ((i - ci) * (i - ci) + (j - cj) * (j - cj) <= r * r) tried[j * g.width + i] = 1;
}

// Moves a fitting pose towards the obstacle nearest the candidate until it (almost) touches,
// by bisection: a shape pressed against a neighbour leaves the rest of the gap in one piece.
Pose slide_to_contact(FillContext& context, const Layout& layout, const GapField& gaps,
                      const Candidate& c, Pose pose) {
    int site = gaps.field().nearest_site(c.index);
    if (site < 0) return pose;
    Vector toward = gaps.point_in(site, 0.5, 0.5) - gaps.point_in(c.index, 0.5, 0.5);
    double reach = toward.length();
    if (reach == 0) return pose;
    Vector unit = toward / reach;
    Point start = pose.position;
    double lo = 0, hi = reach;
    for (int step = 0; step < 6; ++step) {
        double mid = (lo + hi) / 2;
        pose.position = start + unit * mid;
        if (context.fits(layout, pose))
            lo = mid;
        else
            hi = mid;
    }
    pose.position = start + unit * lo;
    return pose;
}

}  // namespace

void medial_fill(FillContext& context, Layout& layout, long& rounds) {
    const Options& options = context.options();
    GapField gaps(context.container(), layout, context.resolution());
    std::vector<std::uint8_t> tried(static_cast<std::size_t>(gaps.size()), 0);
    int rotations = std::max(1, options.rotations);
    double span = options.rotation_max - options.rotation_min;
    long cancellations = 0;
    while (cancellations < options.gap_cancellations && !context.full(layout)) {
        std::vector<Candidate> maxima = ridge_maxima(gaps, tried);
        if (maxima.empty()) break;
        ++rounds;
        if (maxima.size() > static_cast<std::size_t>(std::max(options.candidates, 1)))
            maxima.resize(static_cast<std::size_t>(std::max(options.candidates, 1)));
        for (const Candidate& c : maxima) {
            // Stale once a placement this round changed its distance.
            if (gaps.squared_distance(c.index) != c.d2 || tried[c.index]) continue;
            Point target = gaps.point_in(c.index, 0.5, 0.5);
            Pose pose = context.random_pose(target);
            double base = pose.rotation;
            const PlacedShape* placed = nullptr;
            for (int r = 0; r < rotations && !placed; ++r) {
                pose.rotation = options.rotation_min +
                                std::fmod(base - options.rotation_min + span * r / rotations,
                                          span > 0 ? span : 1.0);
                pose.position = target - context.pole_offset(pose);
                if (context.fits(layout, pose))
                    placed =
                        context.place(layout, slide_to_contact(context, layout, gaps, c, pose));
            }
            if (placed) {
                gaps.add(*placed);
                cancellations = 0;
                if (context.full(layout)) break;
            } else {
                retire(gaps, tried, c.index, c.d2);
                if (++cancellations >= options.gap_cancellations) break;
            }
        }
    }
}

}  // namespace acanthus::dartfill
