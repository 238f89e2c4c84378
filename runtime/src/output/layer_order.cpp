// Layer order from the sibling order of placement (see layer_order.hpp).
#include "output/layer_order.hpp"

#include <algorithm>
#include <map>

namespace acanthus::detail {

std::vector<const ElementType*> layer_order(const std::vector<const Element*>& elements) {
    std::vector<const ElementType*> types;  // in order of first element
    auto index_of = [&](const ElementType* t) {
        return static_cast<std::size_t>(std::find(types.begin(), types.end(), t) - types.begin());
    };
    for (const Element* e : elements)
        if (index_of(&e->type()) == types.size()) types.push_back(&e->type());
    std::size_t n = types.size();

    // before[a][b]: sibling pairs with an `a` placed earlier than a `b`; each parent's children
    // in placement order, counted by type so that the pass stays linear in the elements.
    std::vector<std::vector<long>> before(n, std::vector<long>(n, 0));
    std::map<const Element*, std::vector<long>> seen;  // parent -> children so far per type
    for (const Element* e : elements) {
        if (!e->parent) continue;
        std::vector<long>& counts = seen[e->parent];
        counts.resize(n, 0);
        std::size_t b = index_of(&e->type());
        for (std::size_t a = 0; a < n; ++a) before[a][b] += counts[a];
        ++counts[b];
    }

    std::vector<const ElementType*> order;
    std::vector<bool> placed(n, false);
    while (order.size() < n) {
        // The first type in appearance order that nothing unplaced must go under; else the first.
        std::size_t pick = n;
        for (std::size_t b = 0; b < n && pick == n; ++b) {
            if (placed[b]) continue;
            bool free = true;
            for (std::size_t a = 0; a < n && free; ++a)
                if (!placed[a] && a != b && before[a][b] > before[b][a]) free = false;
            if (free) pick = b;
        }
        if (pick == n)
            pick = static_cast<std::size_t>(std::find(placed.begin(), placed.end(), false) -
                                            placed.begin());
        placed[pick] = true;
        order.push_back(types[pick]);
    }
    return order;
}

}  // namespace acanthus::detail
