// Layer order from the sibling order of placement (see layer_order.hpp).
#include "output/layer_order.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>

namespace acanthus::detail {

std::vector<const ElementType*> layer_order(const std::vector<const Element*>& elements) {
    std::vector<const ElementType*> types;  // in order of first element
    auto index_of = [&](const ElementType* t) {
        return static_cast<std::size_t>(std::find(types.begin(), types.end(), t) - types.begin());
    };
    for (const Element* e : elements)
        if (index_of(&e->type()) == types.size()) types.push_back(&e->type());
    std::size_t n = types.size();

    // before[a][b]: sibling pairs with an `a` placed earlier than a `b`. Children sorted by
    // parent, then placement, are counted by type one parent at a time: linear after the sort,
    // and 16 bytes an element (a map of counts per parent took 30 MB at 444,626 dots).
    struct Child {
        const Element* parent;
        std::uint32_t order, type;
    };
    std::vector<Child> children;
    for (std::size_t k = 0; k < elements.size(); ++k)
        if (elements[k]->parent)
            children.push_back({elements[k]->parent, static_cast<std::uint32_t>(k),
                                static_cast<std::uint32_t>(index_of(&elements[k]->type()))});
    std::sort(children.begin(), children.end(), [](const Child& x, const Child& y) {
        return x.parent != y.parent ? std::less<const Element*>()(x.parent, y.parent)
                                    : x.order < y.order;
    });
    std::vector<std::vector<long>> before(n, std::vector<long>(n, 0));
    std::vector<long> counts(n, 0);  // the current parent's children so far, per type
    for (std::size_t k = 0; k < children.size(); ++k) {
        if (k == 0 || children[k].parent != children[k - 1].parent)
            std::fill(counts.begin(), counts.end(), 0);
        std::size_t t = children[k].type;
        for (std::size_t a = 0; a < n; ++a) before[a][t] += counts[a];
        ++counts[t];
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
