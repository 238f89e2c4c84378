// The straight head of an opening a feature stands for: the edge itself, or the top edge a
// corner ends (its corners lay the head first, so no corner brick notches it); -1 otherwise.
#pragma once

#include <acanthus/stdlib/cells.hpp>

namespace acanthus::cells::detail {

inline int head_edge(const Facade& facade, const FeatureRef& f) {
    if (f.kind == FeatureKind::face) return -1;
    int head = -1;
    if (f.kind == FeatureKind::edge) {
        head = f.index;
    } else {
        const Corner& corner = facade.corners()[static_cast<std::size_t>(f.index)];
        for (int e : {corner.edge_in, corner.edge_out})
            if (facade.edges()[static_cast<std::size_t>(e)].part == Part::top &&
                !facade.edges()[static_cast<std::size_t>(e)].arc)
                head = e;
    }
    if (head < 0) return -1;
    const Edge& e = facade.edges()[static_cast<std::size_t>(head)];
    return e.arc || e.part != Part::top || !e.opening ? -1 : head;
}

}  // namespace acanthus::cells::detail
