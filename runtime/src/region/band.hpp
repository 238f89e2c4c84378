// A band along a centre line (--band PATH.svg --band-width W; docs/symmetry.md): the ornament
// grows in the straight band [0, L] x [-W/2, W/2], L the centre line's length, and is bent onto
// the centre line when drawn: (s, t) -> C(s) + t N(s), C parametrized by arc length, N its
// normal (the tangent turned a quarter clockwise on the page, y pointing down).
#pragma once

#include <acanthus/point.hpp>
#include <acanthus/region.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus::detail {

class Band {
  public:
    // The centre line is the one path (one subpath) of the SVG file or text `svg`, named `name`
    // in messages. Throws InputError when the file holds no path or more than one, or a path of
    // no length; UsageError when `width` is not positive, or larger than twice the centre
    // line's smallest radius of curvature (the band's inner edge would fold; a corner has radius
    // 0).
    static Band from_svg_file(const std::string& path, double width);
    static Band from_svg_string(std::string_view svg, const std::string& name, double width);

    double length() const { return length_; }
    double width() const { return width_; }
    // A closed centre line: the band wraps in x with period length().
    bool closed() const { return closed_; }
    // The smallest radius of curvature, measured over arc-length steps of length() / samples.
    double min_radius() const { return min_radius_; }

    // The straight band [0, L] x [-W/2, W/2], the region the ornament grows in.
    Region straight_region() const;
    // (s, t) of the straight band -> the page: C(s) + t N(s). Beyond the ends of an open centre
    // line, C goes on straight along its end tangent; a closed one wraps.
    Point map(Point st) const;
    // The bent band's bounds.
    Rect bounds() const;
    // The bent band's outline, flattened to within `tolerance`: one ring for an open centre
    // line, the two edges for a closed one (an annulus, even-odd).
    std::vector<std::vector<Point>> outline(double tolerance) const;
    // The largest step along s between two points of a drawn path for its bent image to stay
    // within `tolerance` of the exact bend.
    double step(double tolerance) const;

  private:
    Band(const std::string& name, double width, std::vector<Point> points,
         std::vector<Point> normals, double length, bool closed);

    double width_, length_;
    bool closed_;
    double min_radius_ = 0;
    std::vector<Point> points_, normals_;  // C and N at s = k * length / (samples - 1)
};

}  // namespace acanthus::detail
