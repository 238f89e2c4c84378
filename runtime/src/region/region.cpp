#include <2geom/curve.h>
#include <2geom/elliptical-arc.h>
#include <2geom/path.h>
#include <2geom/svg-path-writer.h>

#include <acanthus/region.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "region/boundary.hpp"
#include "region/build.hpp"
#include "region/curves.hpp"
#include "region/region_data.hpp"

namespace acanthus {
namespace {

Point to_point(Geom::Point p) { return {p[Geom::X], p[Geom::Y]}; }

// Appends points of `c` (excluding its initial point) so that no chord strays more than
// `tolerance` from the curve, by recursive bisection checked at the quarter points.
void flatten(const Geom::Curve& c, double t0, double t1, Geom::Point p0, Geom::Point p1,
             double tolerance, int depth, std::vector<Point>& out) {
    auto off_chord = [&](double t) {
        Geom::Point q = c.pointAt(t);
        Geom::Point d = p1 - p0;
        double len = Geom::L2(d);
        if (len == 0) return Geom::distance(q, p0);
        return std::abs(Geom::cross(q - p0, d)) / len;
    };
    double tm = (t0 + t1) / 2;
    bool flat = off_chord(t0 + (t1 - t0) / 4) <= tolerance && off_chord(tm) <= tolerance &&
                off_chord(t1 - (t1 - t0) / 4) <= tolerance;
    if (flat || depth >= 18) {
        out.push_back(to_point(p1));
        return;
    }
    Geom::Point pm = c.pointAt(tm);
    flatten(c, t0, tm, p0, pm, tolerance, depth + 1, out);
    flatten(c, tm, t1, pm, p1, tolerance, depth + 1, out);
}

}  // namespace

Region::Region(std::unique_ptr<detail::RegionData> data) : data_(std::move(data)) {}
Region::Region(const Region& other) : data_(std::make_unique<detail::RegionData>(*other.data_)) {}
Region::Region(Region&&) noexcept = default;
Region& Region::operator=(const Region& other) {
    if (this != &other) data_ = std::make_unique<detail::RegionData>(*other.data_);
    return *this;
}
Region& Region::operator=(Region&&) noexcept = default;
Region::~Region() = default;

const std::string& Region::name() const { return data_->name; }
Rect Region::bounds() const { return data_->bounds; }
double Region::area() const { return data_->area; }
bool Region::evenodd() const { return data_->evenodd; }

bool Region::contains(Point p) const {
    if (!p.finite() || !data_->bounds.contains(p)) return false;
    return data_->boundary->contains(Geom::Point(p.x, p.y));
}

double Region::distance_to_boundary(Point p) const {
    return data_->boundary->outside().nearest(Geom::Point(p.x, p.y)).distance;
}

std::vector<std::vector<Point>> Region::rings(double tolerance) const {
    double tol =
        tolerance > 0 ? tolerance : 1e-3 * std::max(data_->bounds.width(), data_->bounds.height());
    std::vector<std::vector<Point>> out;
    for (const Geom::Path& path : data_->paths) {
        std::vector<Point> ring;
        ring.push_back(to_point(path.initialPoint()));
        for (std::size_t i = 0; i < path.size_closed(); ++i) {
            const Geom::Curve& c = path[i];
            if (c.isLineSegment() || c.isDegenerate()) {
                ring.push_back(to_point(c.finalPoint()));
            } else {
                flatten(c, 0, 1, c.initialPoint(), c.finalPoint(), tol, 0, ring);
            }
        }
        // The closing point repeats the first; rings are implicitly closed.
        if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
        if (ring.size() >= 3) out.push_back(std::move(ring));
    }
    return out;
}

// Subpaths are oriented (region_build.hpp): outer loops have positive signed area, holes
// negative. A hole belongs to the smallest outer loop around it; an island inside a hole is an
// outer loop of its own, so it is a part of its own.
std::vector<Region> Region::parts() const {
    const Geom::PathVector& paths = data_->paths;
    std::vector<std::size_t> outers;
    std::vector<double> areas(paths.size());
    for (std::size_t k = 0; k < paths.size(); ++k) {
        areas[k] = detail::signed_area(paths[k]);
        if (areas[k] > 0) outers.push_back(k);
    }
    if (outers.size() <= 1) return {*this};
    std::vector<Geom::PathVector> pieces(outers.size()), loops(outers.size());
    for (std::size_t o = 0; o < outers.size(); ++o) {
        pieces[o].push_back(paths[outers[o]]);
        loops[o].push_back(paths[outers[o]]);
    }
    for (std::size_t k = 0; k < paths.size(); ++k) {
        if (areas[k] > 0 || paths[k].empty()) continue;
        // Subpaths do not cross, so any point of the hole's boundary tells which loops hold it.
        const Geom::Point probe = paths[k][0].pointAt(0.5);
        std::size_t owner = outers.size();
        for (std::size_t o = 0; o < outers.size(); ++o) {
            if (detail::winding_number(loops[o], probe) == 0) continue;
            if (owner == outers.size() || areas[outers[o]] < areas[outers[owner]]) owner = o;
        }
        if (owner < outers.size()) pieces[owner].push_back(paths[k]);
    }
    std::vector<Region> out;
    for (std::size_t o = 0; o < outers.size(); ++o) {
        auto data = std::make_unique<detail::RegionData>();
        data->name = data_->name + " (part " + std::to_string(o + 1) + ")";
        data->paths = std::move(pieces[o]);
        data->evenodd = data_->evenodd;
        const Geom::OptRect b = data->paths.boundsExact();
        if (!b) continue;
        data->bounds = Rect{b->left(), b->top(), b->right(), b->bottom()};
        data->area = detail::signed_area(data->paths);
        detail::set_boundary(*data);
        out.push_back(Region(std::move(data)));
    }
    return out;
}

std::string Region::path_data() const { return Geom::write_svg_path(data_->paths); }

}  // namespace acanthus
