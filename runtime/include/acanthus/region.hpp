// The panel R to be filled: closed paths with holes, from SVG or a built-in shape.
// Coordinates are SVG user units, y pointing down as in SVG.
#pragma once

#include <acanthus/corner.hpp>
#include <acanthus/point.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus {

namespace detail {
struct RegionData;
}

class Region {
  public:
    // Loads every filled shape of an SVG file (path, polygon, polyline, rect, circle, ellipse,
    // nested g with transform, fill-rule). Throws InputError naming the file (and element).
    static Region from_svg_file(const std::string& path);
    static Region from_svg_string(std::string_view svg, const std::string& name);
    // "rect:W,H", "circle:R", "ellipse:RX,RY"; bounds start at (0, 0). Throws InputError.
    static Region from_spec(std::string_view spec);
    // --region argument: a spec when it looks like one, else an SVG file.
    static Region from_argument(std::string_view arg);
    // The panel used when --region is not given.
    static Region default_panel();

    Region(const Region&);
    Region(Region&&) noexcept;
    Region& operator=(const Region&);
    Region& operator=(Region&&) noexcept;
    ~Region();

    const std::string& name() const;
    Rect bounds() const;
    double area() const;
    bool contains(Point p) const;
    // Unsigned distance from p to the nearest point of the boundary.
    double distance_to_boundary(Point p) const;
    // Boundary flattened to closed rings (tolerance in user units), for rasterizing and drawing.
    std::vector<std::vector<Point>> rings(double tolerance) const;
    // True when the fill rule is even-odd (else nonzero).
    bool evenodd() const;
    // SVG path data of the exact boundary ("M ... Z ...").
    std::string path_data() const;
    // Centre and radius of the largest circle inside the region (within `tolerance`).
    Circle largest_inscribed_circle(double tolerance) const;
    // The connected pieces of the region, each an outer boundary loop with the holes directly
    // inside it, in the order of their outer loops. A region in one piece gives one part.
    std::vector<Region> parts() const;
    // The corners of the boundary, in path order: where it turns by at least `min_turn`
    // radians at once (between two curves), convex or concave.
    std::vector<Corner> corners(double min_turn = 0.35) const;

    const detail::RegionData& data() const { return *data_; }

  private:
    explicit Region(std::unique_ptr<detail::RegionData> data);
    std::unique_ptr<detail::RegionData> data_;
};

}  // namespace acanthus
