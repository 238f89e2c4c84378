// Window-bottom bricks [5.2]: a row of headers in the course under an opening's sill, one more
// header past each bottom corner, set off the joints of the courses below and above. Faces are not
// its business: passing one is an error.
#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <vector>

#include "brick_layout.hpp"
#include "context_data.hpp"
#include "feature_walk.hpp"

namespace acanthus::cells {

namespace {

// The sill edge a bottom corner belongs to, or -1.
int sill_of(const Facade& facade, const Corner& c) {
    for (int e : {c.edge_in, c.edge_out}) {
        const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
        if (edge.opening && edge.part == Part::bottom) return e;
    }
    return -1;
}

// Head joints of the bond's pieces in `row` (their left ends), to keep the header row off them.
bool joint_at(const detail::BrickLayout& layout, int row, int u) {
    if (row < 0 || row >= layout.grid.rows()) return false;
    for (const detail::Piece& p : layout.rows[static_cast<std::size_t>(row)])
        if (p.start == u && p.start > 0) return true;
    return false;
}

// Joints of the header row over units [a, b): every other unit, on the parity that meets fewest
// joints of the courses below and above (a straight joint otherwise); end pieces of 2 or 3.
std::vector<int> header_joints(const detail::BrickLayout& layout, int row, int a, int b) {
    int best = 0, fewest = -1;
    for (int parity = 0; parity < 2; ++parity) {
        int straight = 0;
        for (int u = a + 2; u <= b - 2; ++u)
            if (((u % 2) + 2) % 2 == parity)
                straight += joint_at(layout, row + 1, u) + joint_at(layout, row - 1, u);
        if (fewest < 0 || straight < fewest) fewest = straight, best = parity;
    }
    std::vector<int> joints{a};
    for (int u = a + 2; u <= b - 2; ++u)
        if (((u % 2) + 2) % 2 == best) joints.push_back(u);
    joints.push_back(b);
    return joints;
}

// Lays the header row's pieces that overlap [lo, hi); pieces already laid claim nothing more.
void headers(Context& c, const detail::BrickLayout& layout, int row, const std::vector<int>& j,
             int lo, int hi) {
    for (std::size_t k = 0; k + 1 < j.size(); ++k) {
        const int u = std::max(0, j[k]), end = std::min(j[k + 1], layout.grid.units());
        if (end <= lo || u >= hi || u >= end) continue;
        const Rect drawn = layout.drawn(row, u, end);
        c.place(detail::polygon_of(layout.grid.cell(row, u, end)), layout.grid.course(row), true,
                &drawn);
    }
}

}  // namespace

Generator window_bottom() {
    return [](const FeatureRef& f, Context& c) {
        const Facade& facade = c.facade();
        if (f.kind == FeatureKind::face)
            throw InputError(facade.name() +
                             ": cells: the tree passes a face to window_bottom, which textures "
                             "only corners and edges");
        int edge_index = f.index;
        if (f.kind == FeatureKind::corner)
            edge_index = sill_of(facade, facade.corners()[static_cast<std::size_t>(f.index)]);
        if (edge_index < 0) return;
        const Edge& sill = facade.edges()[static_cast<std::size_t>(edge_index)];
        detail::BrickLayout& layout = detail::brick_layout(c, sill.face);
        const double inset = 0.25 * c.options().brick_height;
        Point below = sill.at(sill.length / 2) + sill.inward(sill.length / 2) * inset;
        int row = layout.grid.row_at(below.y);
        double x0 = std::min(sill.bounds.x0, sill.bounds.x1), x1 = sill.bounds.x1;
        double tiny = 1e-6 * (x1 - x0);
        int u0 = layout.grid.unit_at(x0 + tiny), u1 = layout.grid.unit_at(x1 - tiny);
        if (row < 0 || u0 < 0 || u1 < 0) return;
        const std::vector<int> joints = header_joints(layout, row, u0 - 2, u1 + 3);
        if (f.kind == FeatureKind::edge) {
            headers(c, layout, row, joints, u0, u1 + 1);
            return;
        }
        const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
        if (corner.position.x <= (x0 + x1) / 2)
            headers(c, layout, row, joints, u0 - 2, u0);
        else
            headers(c, layout, row, joints, u1 + 1, u1 + 3);
    };
}

}  // namespace acanthus::cells
