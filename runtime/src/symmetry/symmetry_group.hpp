// The transformations of a symmetry group and its fundamental domain, the part of the plane the
// growth loop chooses its empty circles in (docs/symmetry.md): a rosette about its centre
// (a wedge), or a group with translations (a frieze, a wallpaper group) as the finite list of
// its isometries that reach the region (the Dirichlet domain of a point with no symmetry).
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/region.hpp>
#include <acanthus/symmetry.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "symmetry/isometry.hpp"

namespace acanthus::detail {

// A group with translations, cut down to the isometries whose images reach the region.
struct TranslationGroup {
    std::string name;                  // "frieze p2mg", "wallpaper p4m"
    std::vector<Isometry> transforms;  // the identity first
    // A point that no transformation but the identity fixes: the fundamental domain is the
    // set of points nearer to it than to any of its images.
    Point generic;
    // Periodic (a wallpaper tile, a closed band): images whose bounds meet this box are kept,
    // across its edges too. None: an image is kept only when it lies wholly inside the region
    // (a frieze's band ends there).
    std::optional<Rect> window;
    Rect frame;  // where domain_edges() clips the domain (the region's or the window's bounds)
    // The whole group (moves_apart()): these isometries composed with the translations
    // i a + j b (b zero for a frieze); empty when not known.
    std::vector<Isometry> cosets;
    Vector a{0, 0}, b{0, 0};
};

class SymmetryGroup {
  public:
    SymmetryGroup(const Symmetry& spec, Point center);
    // `region` (kept by reference, it must outlive the group) decides which images are kept
    // when `group.window` is none.
    SymmetryGroup(TranslationGroup group, const Region& region);

    // True for a rosette (cN, dN), false for a group with translations.
    bool rosette() const { return !lattice_; }
    const std::string& name() const { return name_; }
    const Symmetry& spec() const { return spec_; }
    // The rosette's centre; the Dirichlet domain's point for a group with translations.
    Point center() const { return center_; }
    // Every transformation, the identity first (a rosette: then the rotations by 2 pi k / N,
    // then (dN) the reflections).
    const std::vector<Isometry>& transforms() const { return transforms_; }
    std::size_t size() const { return transforms_.size(); }
    // The rosette's domain's angle: 2 pi / N (cN) or pi / N (dN).
    double wedge() const { return wedge_; }

    // True when p lies in the fundamental domain widened by `tolerance` on each side: for a
    // rosette the wedge whose first edge points up from the centre, else the Dirichlet domain.
    bool in_domain(Point p, double tolerance) const;
    // For a rosette whose wedge is narrower than a half-plane: no more than the distance from
    // p to the wedge (0 inside it and within rounding of its edges). 0 for any other group.
    double domain_gap(Point p) const;
    // p moved onto the nearest rotation centre, or else onto the nearest mirror, when it lies
    // within `tolerance` of one, so that its images coincide with it exactly; else p.
    Point snap(Point p, double tolerance) const;
    // Half the distance from c to its nearest image farther than `tolerance` (infinite when
    // every image coincides with c): a circle about c no larger stays clear of its images.
    // With `at_most` > 0 the answer may be any value no larger than it once the clearance is
    // known to be below it (the search for the roomiest point needs no more).
    // `hint` (may be null) names the transformation that ended the last such search: tried
    // first, it usually ends the next one, for nearby points, at once.
    double clearance(Point c, double tolerance, double at_most = 0,
                     std::size_t* hint = nullptr) const;
    // The largest circles inside `c` (other than `c`) each of which stays clear of its images
    // (radius at most the clearance of its centre): the one touching `c` where `c` is nearest
    // `toward`; then one centred on a mirror and one off every mirror, found on a polar sample
    // of `c` and on the mirrors through the samples, each of the equivalent circles (the
    // images under the transformations fixing c's centre) the one nearest `toward`. At a rotation
    // centre with mirrors, where an element fits on `c` only if its images coincide with it, these
    // hold an element beside the centre.
    std::vector<Circle> clear_circles_in(const Circle& c, Point toward, double tolerance) const;
    // The part of the disc `c` in the fundamental domain widened by `tolerance`, as a polygon
    // (the circle flattened within `flatness`, counter-clockwise in y-down coordinates as the
    // disc's); empty when they do not meet. A fill offered a hole fills this part alone: the
    // images fill the rest.
    std::vector<Point> domain_part(const Circle& c, double tolerance, double flatness) const;
    // With translations: one rotation centre of each class (a point and its images under the
    // group), each the representative lying in the fundamental domain (widened by `tolerance`),
    // in the order found; a rosette's centre alone.
    std::vector<Point> centre_classes(double tolerance) const;
    // With translations: the fundamental domain's edges (domain_edges()) that lie on a mirror
    // (within `tolerance`); a hole on a mirror away from the rotation centres is one of these
    // edges' points. None for a rosette.
    std::vector<std::pair<Point, Point>> mirror_edges(double tolerance) const;
    // The domain's edges: a rosette's two, from the centre out to `radius` (none for c1); the
    // Dirichlet domain's polygon clipped to the frame.
    std::vector<std::pair<Point, Point>> domain_edges(double radius) const;
    // A group with translations: the Dirichlet domain as half-planes, each a point m and a unit
    // normal n, the domain being where (p - m) . n <= 0 for all (what in_domain() measures).
    const std::vector<std::pair<Point, Vector>>& halfplanes() const { return halfplanes_; }
    // True when an image of an element is placed: always for a rosette; for a group with
    // translations when it meets the window, or without one lies inside the region.
    bool keeps(const Element& image, double tolerance) const;
    // True when every isometry of the group but the identity (the whole group, not only those
    // listed) moves p by more than `d`: then no two images of p are within d / 2 of each
    // other... nor within d of p. False when it cannot tell.
    bool moves_apart(Point p, double d) const;
    // keeps() for an image known only to lie within `box`, where the box alone decides: 1 kept,
    // 0 not, -1 when only the image itself can tell (`margin` covers rounding). Inline:
    // orbit_of() asks it of every transformation, hundreds for a tile's window.
    int keeps_within(const Rect& box, double margin) const {
        if (!lattice_) return 1;
        if (!window_) return -1;
        const Rect& w = *window_;
        if (box.x0 > w.x1 + margin || w.x0 > box.x1 + margin || box.y0 > w.y1 + margin ||
            w.y0 > box.y1 + margin)
            return 0;
        // An element has a proxy, and each proxy's bounds then meet the window.
        if (box.x0 >= w.x0 + margin && box.x1 <= w.x1 - margin && box.y0 >= w.y0 + margin &&
            box.y1 <= w.y1 - margin)
            return 1;
        return -1;
    }

  private:
    Symmetry spec_;
    std::string name_;
    Point center_;
    double wedge_ = 0;  // the rosette's domain's angle
    // domain_gap()'s wedge: its edges' and its bisector's directions, the cosine of its half
    // angle less a margin.
    Vector gap_edges_[2] = {{0, 0}, {0, 0}};
    Vector gap_bisector_{0, 0};
    double gap_cos_ = 1;
    std::vector<Isometry> transforms_;
    // Groups with translations.
    bool lattice_ = false;
    std::optional<Rect> window_;
    Rect frame_;
    const Region* region_ = nullptr;
    std::vector<Isometry> cosets_;  // TranslationGroup's, for moves_apart()
    Vector lattice_a_{0, 0}, lattice_b_{0, 0};
    std::vector<Point> centres_;                        // rotation centres
    std::vector<std::pair<Point, Vector>> mirrors_;     // a point and the unit direction
    std::vector<std::pair<Point, Vector>> halfplanes_;  // the domain: (p - m) . n <= 0
};

}  // namespace acanthus::detail
