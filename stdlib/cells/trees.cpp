// The ready pattern generator trees (Figure 4's idea): what goes where on a facade.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>

#include "context_data.hpp"

namespace acanthus::cells {

namespace {

// Arc edges and the corners on them (springings, apexes) get `arch`, labelled `arch` or not (a
// ring of voussoirs is what a mason lays round an oculus too); the rest gets `rest`.
Node arches(Node arch, Node rest) { return by_curve(arch, rest); }

// Opening bottoms (sill and its corners) get `wb`; the rest goes to `rest`.
Node sills(Node rest, Node wb = generator("window_bottom", window_bottom())) {
    Node openings = by_part(rest, by_kind(wb, wb, rest), rest);
    return Node([openings, rest](const FeatureRef& f, Context& c) {
        bool opening = false;
        auto i = static_cast<std::size_t>(f.index);
        if (f.kind == FeatureKind::corner) opening = c.facade().corners()[i].opening;
        if (f.kind == FeatureKind::edge) opening = c.facade().edges()[i].opening;
        // A door's bottom lies on the ground, not over wall: only openings with wall below.
        if (opening)
            openings(f, c);
        else
            rest(f, c);
    });
}

}  // namespace

Node brick_tree() {
    Node b = generator("bricks", bricks());
    Node arch = generator("arch_stones", arch_stones());
    return by_kind(arches(arch, sills(b)), arches(arch, sills(b)), b);
}

Node framed_tree() {
    Node b = generator("bricks", bricks());
    Node lin = generator("lintel", lintel());
    Node q = generator("quoins", quoins());
    Node openings = by_part(by_curve(b, lin), generator("window_bottom", window_bottom()), q);
    Node features = Node([=](const FeatureRef& f, Context& c) {
        auto i = static_cast<std::size_t>(f.index);
        bool opening = f.kind == FeatureKind::corner ? c.facade().corners()[i].opening
                                                     : c.facade().edges()[i].opening;
        if (opening)
            openings(f, c);
        else if (f.kind == FeatureKind::edge && c.facade().edges()[i].vertical())
            q(f, c);
        else
            b(f, c);
    });
    // Top corners of openings lay the lintel before any corner brick can notch it.
    Node arch = generator("arch_stones", arch_stones());
    Node tree = by_kind(arches(arch, features), arches(arch, features), b);
    return Node([tree](const FeatureRef& f, Context& c) {
        c.data().quoined = true;  // the brick layouts bond the quoins in (quoin_rows.hpp)
        tree(f, c);
    });
}

Node ashlar_tree() {
    Node a = generator("ashlar", ashlar());
    Node arch = generator("arch_stones", arch_stones());
    Node wb = generator("window_bottom", sill_stones());
    Node lin = generator("lintel", lintel());
    // Openings: a lintel over a straight head (its corners lay it first), sill stones under.
    Node openings = by_part(lin, by_kind(wb, wb, a), a);
    Node features = Node([=](const FeatureRef& f, Context& c) {
        auto i = static_cast<std::size_t>(f.index);
        bool opening = f.kind == FeatureKind::corner ? c.facade().corners()[i].opening
                                                     : c.facade().edges()[i].opening;
        if (opening)
            openings(f, c);
        else
            a(f, c);
    });
    Node tree = by_kind(arches(arch, features), arches(arch, features), a);
    return Node([tree](const FeatureRef& f, Context& c) {
        c.data().stone = true;  // lintels on the ashlar grid
        tree(f, c);
    });
}

Node rgb_tree() { return generator("rgb_blocks", rgb_blocks()); }

Node tree_for(const Options& options) {
    return options.bond == Bond::ashlar ? ashlar_tree() : brick_tree();
}

}  // namespace acanthus::cells
