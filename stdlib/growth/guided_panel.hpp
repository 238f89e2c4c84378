// The spray and boundary tools (section 3) as a panel that wraps the room synthesis grows in.
#pragma once

#include <acanthus/stdlib/growth.hpp>
#include <vector>

#include "panel.hpp"

namespace acanthus::growth::detail {

// Section 3's tools over another panel: growth stops at boundary strokes (a motif may neither
// touch one nor step across it) and, when there are spray strokes, stays within their brushes.
class GuidedPanel : public Panel {
  public:
    GuidedPanel(const Panel& base, const Options& options);
    bool contains(Point p) const override;
    bool admits(Circle motif, double tolerance) const override;
    bool reaches(Point from, Point to) const override;
    Rect bounds() const override { return base_.bounds(); }
    double clearance(Point p) const override { return base_.clearance(p); }
    double area() const override { return base_.area(); }

  private:
    struct Segment {
        Point a, b;
        double half_width = 0;  // spray brushes
    };
    const Panel& base_;
    std::vector<Segment> boundary_, spray_;
};

}  // namespace acanthus::growth::detail
