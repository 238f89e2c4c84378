// The jambs of a face: the plumb sides of its openings and ends, where a course's run begins or
// ends. Shared by the runs set out again from their jambs and the run ends laid again there.
#pragma once

#include <acanthus/stdlib/cells.hpp>
#include <vector>

#include "course_grid.hpp"

namespace acanthus::cells::detail {

struct Jamb {
    double x, y0, y1;
    bool left;  // the face to its right: a run's left end
};

// A straight, open edge of no width: a jamb or a wall's end.
bool plumb_edge(const Edge& e);

// The plumb edges of face `face`.
std::vector<Jamb> face_jambs(const Facade& facade, int face);

// A face's jambs ordered by x for jamb_at: a run's ends are looked up at every layout pass,
// and a face of a hundred windows has some four hundred jambs.
class JambIndex {
  public:
    explicit JambIndex(std::vector<Jamb> jambs);

    // The jamb bounding unit u's `left` (or right) side over the whole of row r, in the unit or
    // on its line (q: the unit's width); its x in `x`. Of two, the first given.
    bool jamb_at(const CourseGrid& g, double q, int r, int u, bool left, double& x) const;

  private:
    std::vector<Jamb> jambs_;
    std::vector<std::size_t> by_x_;  // indices into jambs_, by x
};

}  // namespace acanthus::cells::detail
