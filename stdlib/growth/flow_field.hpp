// Section 3 and 5.3: the flow field tool. Stroke directions (first point to last) are sampled
// along each stroke and interpolated over the plane with radial basis functions (a thin-plate
// spline with a linear part), so that the reference's x axis can follow the field.
#pragma once

#include <acanthus/point.hpp>
#include <string>
#include <vector>

namespace acanthus::growth::detail {

class FlowField {
  public:
    // Samples every `spacing` along each stroke, never more than `max_samples` in all (fewer
    // per stroke, and with more strokes than that, evenly chosen ones).
    // Throws InputError naming `source` and the stroke for one with no length or a non-finite
    // point.
    FlowField(const std::vector<std::vector<Point>>& strokes, double spacing,
              const std::string& source, std::size_t max_samples = 600);

    // Direction of the field at p (radians, counter-clockwise from +x in y-up terms).
    double angle(Point p) const;
    Vector vector(Point p) const;
    const std::vector<Point>& samples() const { return samples_; }
    const std::vector<Vector>& directions() const { return directions_; }

  private:
    std::vector<Point> samples_;
    std::vector<Vector> directions_;       // unit tangents at the samples
    std::vector<Vector> weights_;          // per sample, for x and y
    Vector constant_, along_x_, along_y_;  // the linear part
    Point origin_;                         // samples are centred here for conditioning
    double scale_ = 1;
};

}  // namespace acanthus::growth::detail
