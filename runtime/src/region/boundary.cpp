#include "region/boundary.hpp"

#include "region/curves.hpp"
#include "region/region_data.hpp"

namespace acanthus::detail {

RegionBoundary::RegionBoundary(const Geom::PathVector& paths, bool evenodd)
    : loops_(paths), evenodd_(evenodd) {
    for (Geom::Path& p : loops_) p.close(true);
    if (Geom::OptRect b = loops_.boundsFast()) right_ = b->right();
    std::vector<const Geom::Curve*> curves;
    for (const Geom::Path& p : loops_)
        for (const Geom::Curve* c : path_curves(p)) curves.push_back(c);
    outside_ = std::make_unique<BoundaryDistance>(std::move(curves),
                                                  [this](Geom::Point q) { return !contains(q); });
}

int RegionBoundary::winding(Geom::Point p) const {
    const Geom::Rect ray(p, Geom::Point(std::max(right_, p[Geom::X]), p[Geom::Y]));
    int w = 0;
    outside_->for_each_curve_meeting(
        ray, [&](std::size_t i) { w += winding_number(*outside_->curves()[i], p); });
    return w;
}

void set_boundary(RegionData& data) {
    data.boundary = std::make_shared<const RegionBoundary>(data.paths, data.evenodd);
}

bool RegionBoundary::contains(Geom::Point p) const {
    const int w = winding(p);
    return evenodd_ ? (w % 2) != 0 : w != 0;
}

}  // namespace acanthus::detail
