#include "region_uncross.hpp"

#include <2geom/bezier-curve.h>
#include <2geom/path.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace acanthus::detail {
namespace {

constexpr double kTimeEps = 1e-9;
constexpr std::size_t kMaxCrossings = 10000;

struct CurveRef {
    std::size_t path;
    std::size_t index;
    Geom::Rect box;
};

struct Cut {
    std::size_t path;
    double time;  // flat path time in [0, size)
    std::size_t partner;
    Geom::Point point;
};

class Uncrosser {
  public:
    explicit Uncrosser(const Geom::PathVector& paths) : paths_(paths) {}

    Geom::PathVector run() {
        if (!find_crossings()) return paths_;
        if (cuts_.empty()) return paths_;
        // Cuts of each path in time order; coincident cuts mean a multiple point: give up.
        std::vector<std::vector<std::size_t>> by_path(paths_.size());
        for (std::size_t c = 0; c < cuts_.size(); ++c) by_path[cuts_[c].path].push_back(c);
        next_on_path_.assign(cuts_.size(), 0);
        for (auto& list : by_path) {
            std::sort(list.begin(), list.end(), [this](std::size_t a, std::size_t b) {
                return cuts_[a].time < cuts_[b].time;
            });
            for (std::size_t k = 0; k < list.size(); ++k) {
                std::size_t next = list[(k + 1) % list.size()];
                if (list.size() > 1 && std::abs(cuts_[next].time - cuts_[list[k]].time) < kTimeEps)
                    return paths_;
                next_on_path_[list[k]] = next;
            }
        }
        Geom::PathVector out;
        for (std::size_t p = 0; p < paths_.size(); ++p)
            if (by_path[p].empty()) out.push_back(paths_[p]);
        // Each piece runs from a cut to the next cut on its path, then continues on the
        // other strand of that crossing.
        std::vector<bool> used(cuts_.size(), false);
        for (std::size_t start = 0; start < cuts_.size(); ++start) {
            if (used[start]) continue;
            std::vector<std::unique_ptr<Geom::Curve>> curves;
            std::size_t c = start;
            for (std::size_t guard = 0; !used[c] && guard <= cuts_.size(); ++guard) {
                used[c] = true;
                std::size_t end = next_on_path_[c];
                append_piece(cuts_[c], cuts_[end], curves);
                c = cuts_[end].partner;
            }
            if (curves.empty()) continue;
            // Pieces meet at crossing points computed on either strand: make them meet exactly.
            for (std::size_t i = 0; i < curves.size(); ++i)
                curves[i]->setFinal(curves[(i + 1) % curves.size()]->initialPoint());
            Geom::Path loop(curves.front()->initialPoint());
            for (auto& curve : curves) loop.append(curve.release());
            loop.close(true);
            out.push_back(std::move(loop));
        }
        return out;
    }

  private:
    double normalize(std::size_t path, double flat) const {
        double n = static_cast<double>(paths_[path].size_default());
        double index = std::floor(flat);
        if (flat - index > 1 - kTimeEps) flat = index + 1;
        if (flat >= n - kTimeEps) flat = 0;
        return flat;
    }

    bool same_time(std::size_t path, double a, double b) const {
        double n = static_cast<double>(paths_[path].size_default());
        double d = std::abs(a - b);
        return d < kTimeEps || std::abs(d - n) < kTimeEps;
    }

    void add(std::size_t pa, double ta, std::size_t pb, double tb, Geom::Point point) {
        ta = normalize(pa, ta);
        tb = normalize(pb, tb);
        if (pa == pb && same_time(pa, ta, tb)) return;  // consecutive curves' shared vertex
        for (std::size_t c = 0; c < cuts_.size(); c += 2) {
            const Cut &x = cuts_[c], &y = cuts_[c + 1];
            if ((x.path == pa && same_time(pa, x.time, ta) && y.path == pb &&
                 same_time(pb, y.time, tb)) ||
                (x.path == pb && same_time(pb, x.time, tb) && y.path == pa &&
                 same_time(pa, y.time, ta)))
                return;  // a vertex on another strand is found from both its curves
        }
        std::size_t c = cuts_.size();
        cuts_.push_back({pa, ta, c + 1, point});
        cuts_.push_back({pb, tb, c, point});
    }

    bool find_crossings() {
        std::vector<CurveRef> refs;
        for (std::size_t p = 0; p < paths_.size(); ++p)
            for (std::size_t i = 0; i < paths_[p].size_default(); ++i)
                if (!paths_[p][i].isDegenerate()) refs.push_back({p, i, paths_[p][i].boundsFast()});
        std::sort(refs.begin(), refs.end(),
                  [](const CurveRef& a, const CurveRef& b) { return a.box.left() < b.box.left(); });
        for (std::size_t a = 0; a < refs.size(); ++a) {
            const Geom::Curve& ca = paths_[refs[a].path][refs[a].index];
            auto bez = dynamic_cast<const Geom::BezierCurve*>(&ca);
            if (bez && bez->order() >= 3) {
                for (const auto& x : ca.intersectSelf())
                    if (std::abs(x.first - x.second) > kTimeEps)
                        add(refs[a].path, refs[a].index + x.first, refs[a].path,
                            refs[a].index + x.second, x.point());
            }
            for (std::size_t b = a + 1;
                 b < refs.size() && refs[b].box.left() <= refs[a].box.right(); ++b) {
                if (!refs[a].box.intersects(refs[b].box)) continue;
                const Geom::Curve& cb = paths_[refs[b].path][refs[b].index];
                for (const auto& x : ca.intersect(cb))
                    add(refs[a].path, refs[a].index + x.first, refs[b].path,
                        refs[b].index + x.second, x.point());
                if (cuts_.size() > 2 * kMaxCrossings) return false;
            }
        }
        return true;
    }

    // Curves of path `from.path` between the two cut times, going forward (wrapping).
    void append_piece(const Cut& from, const Cut& to,
                      std::vector<std::unique_ptr<Geom::Curve>>& out) const {
        const Geom::Path& path = paths_[from.path];
        double n = static_cast<double>(path.size_default());
        double s = from.time, end = to.time;
        if (end <= s + kTimeEps) end += n;  // wraps (or goes all round for a single cut)
        while (s < end - kTimeEps) {
            double index = std::floor(s);
            double stop = std::min(end, index + 1);
            auto k = static_cast<std::size_t>(std::fmod(index, n));
            double t0 = s - index, t1 = stop - index;
            if (t1 - t0 > kTimeEps) out.emplace_back(path[k].portion(t0, t1));
            s = stop;
        }
    }

    const Geom::PathVector& paths_;
    std::vector<Cut> cuts_;
    std::vector<std::size_t> next_on_path_;
};

}  // namespace

Geom::PathVector uncross(const Geom::PathVector& paths) { return Uncrosser(paths).run(); }

}  // namespace acanthus::detail
