// The images of an element under a symmetry group, and whether it may be placed with them: an
// element on a mirror or the centre has fewer distinct images (those that coincide with it);
// every other image must stay clear of it and inside the region (docs/symmetry.md).
#pragma once

#include <acanthus/element.hpp>
#include <acanthus/region.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "symmetry/image_element.hpp"
#include "symmetry/isometry.hpp"
#include "symmetry/symmetry_group.hpp"

namespace acanthus::detail {

// The bounds of every proxy of `e` (an empty rectangle at the origin without one).
Rect bounds_of(const Element& e);
// True when the two closed rectangles meet.
bool boxes_meet(const Rect& a, const Rect& b);

// True when the two proxies are the same shape in the same place, within `tolerance` (a
// segment or a curve may run the other way, a polygon start at another corner).
bool same_place(const Proxy& a, const Proxy& b, double tolerance);
// The same for every proxy of two elements of the same type, in order.
bool same_place(const Element& a, const Element& b, double tolerance);

struct Orbit {
    // The transformations giving the element's distinct images other than itself.
    std::vector<Isometry> images;
    // Those images, in the same order: the growth loop places them (they refer to the
    // element, which must outlive them).
    std::vector<std::unique_ptr<ImageElement>> elements;
    // False when an image that does not coincide with the element overlaps it.
    bool clear = true;
};
Orbit orbit_of(const Element& e, const SymmetryGroup& group, double tolerance);

// True when an image of the element, or of the proxy, other than itself overlaps it or leaves
// the region (touching within `tolerance` is not overlap). A null region: the group maps the
// region onto itself (maps_onto_itself()), so no image leaves it unless its element does.
bool orbit_intersects(const Element& e, const SymmetryGroup& group, const Region* region,
                      double tolerance);
bool orbit_intersects(const Proxy& p, const SymmetryGroup& group, const Region* region,
                      double tolerance);

// The elements one rule success commits, in order: the orbit of each that may be placed, or
// nothing for one whose images clash with it, leave the region, or overlap an element kept
// before it or an image of one, or that overlaps a placed image (`hits_placed_image`).
// (Elements overlapping each other, or placed fundamental ones, are the rule's business, as
// without symmetry.)
//
// With translations an image may be left out (beyond a frieze's ends, outside a tile's box):
// then an image of the element may overlap an element whose matching image is missing, so
// every kept image is checked too, against placed elements and the batch's earlier elements
// and images under another transformation (`hits_placed(element, proxy, transform)`: a placed
// element that is not the image of a fundamental one under that transformation overlaps the
// proxy, of the element's image under it).
std::vector<std::optional<Orbit>> placeable_orbits(
    const std::vector<const Element*>& batch, const SymmetryGroup& group, const Region* region,
    double tolerance, const std::function<bool(const Proxy&)>& hits_placed_image,
    const std::function<bool(const Element&, const Proxy&, const Isometry&)>& hits_placed =
        nullptr);

// True when the two isometries are the same within `tolerance` (on the translation; the
// matrix within 1e-9).
bool same_isometry(const Isometry& a, const Isometry& b, double tolerance);

}  // namespace acanthus::detail
