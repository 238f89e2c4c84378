// Skeletal strokes (after Hsu and Lee): a vector shape defined along a unit skeleton, warped
// along any proxy curve, with a width profile.
#pragma once

#include <acanthus/canvas.hpp>
#include <acanthus/proxy.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace acanthus {

class SkeletalStroke {
  public:
    // Built-in strokes: "tapered", "calligraphic", "leafy", "beaded" (at least).
    static const SkeletalStroke& builtin(std::string_view name);  // throws UsageError if unknown
    static std::vector<std::string> builtin_names();
    // A user stroke from SVG path data (closed shapes, filled nonzero). The shape's bounding box
    // is the stroke's frame: its left edge sits at the skeleton's start, its right edge at the
    // end, its top and bottom edges `width`/2 either side. Throws InputError naming `name`.
    static SkeletalStroke from_svg_path(std::string_view path_data, const std::string& name);
    // Loads every <path> of an SVG file (with group transforms and fill-rule); their joint
    // bounding box defines the frame. Throws InputError naming the file.
    static SkeletalStroke from_svg_file(const std::string& path);

    SkeletalStroke();
    SkeletalStroke(const SkeletalStroke&);
    SkeletalStroke(SkeletalStroke&&) noexcept;
    SkeletalStroke& operator=(const SkeletalStroke&);
    SkeletalStroke& operator=(SkeletalStroke&&) noexcept;
    ~SkeletalStroke();

    const std::string& name() const;
    // Fills the stroke shape warped along `curve` (arc, linesegment, bezier; a circle or
    // polygon is followed along its outline) with the current colour, `width` user units wide.
    void draw(Canvas& canvas, const Proxy& curve, double width) const;
    // Same, along an arbitrary polyline skeleton.
    void draw(Canvas& canvas, const std::vector<Point>& skeleton, double width) const;
    // One stroke along several curves followed end to end (a spiral made of Bézier segments),
    // gaps bridged straight; curves that are not finite are left out.
    void draw(Canvas& canvas, const std::vector<const Proxy*>& chain, double width) const;

    struct Data;  // defined in runtime/src/skeletal_stroke_data.hpp
    explicit SkeletalStroke(Data data);

  private:
    std::unique_ptr<Data> data_;
};

}  // namespace acanthus
