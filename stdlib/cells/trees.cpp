// The ready pattern generator trees (Figure 4's idea): what goes where on a facade.
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>

#include "context_data.hpp"
#include "head_edge.hpp"

namespace acanthus::cells {

namespace {

// Arc edges and the corners on them (springings, apexes) get `arch`, labelled `arch` or not (a
// ring of voussoirs is what a mason lays round an oculus too); the rest gets `rest`.
Node arches(Node arch, Node rest) { return by_curve(arch, rest); }

bool on_opening(const FeatureRef& f, Context& c) {
    auto i = static_cast<std::size_t>(f.index);
    return f.kind == FeatureKind::corner ? c.facade().corners()[i].opening
                                         : c.facade().edges()[i].opening;
}

}  // namespace

Node brick_tree() {
    Node b = generator("bricks", bricks());
    Node arch = generator("arch_stones", arch_stones());
    Node wb = generator("window_bottom", window_bottom());
    Node soldiers = generator("soldier_course", soldier_course());
    Node lin = generator("lintel", lintel());
    // A head by its span: a soldier course over a small opening, a lintel over a wide one.
    Node head = Node([=](const FeatureRef& f, Context& c) {
        const int h = detail::head_edge(c.facade(), f);
        if (h < 0) return b(f, c);
        const Options& o = c.options();
        const double most = o.soldier_span > 0 ? o.soldier_span : 6 * o.brick_length;
        if (c.facade().edges()[static_cast<std::size_t>(h)].bounds.width() <= most)
            soldiers(f, c);
        else
            lin(f, c);
    });
    // Labelled `relieving`: a lintel at any span, a relieving arch over it.
    Node relief = by_label("relieving", generator("relieving_arch", relieving_arch(), lin), head);
    Node openings = by_part(relief, by_kind(wb, wb, b), b);
    Node features = Node([=](const FeatureRef& f, Context& c) {
        if (on_opening(f, c))
            openings(f, c);
        else
            b(f, c);
    });
    return by_kind(arches(arch, features), arches(arch, features), b);
}

Node framed_tree() {
    Node b = generator("bricks", bricks());
    Node lin = generator("lintel", lintel());
    Node q = generator("quoins", quoins());
    Node relief = by_label("relieving", generator("relieving_arch", relieving_arch(), lin), lin);
    Node openings = by_part(by_curve(b, relief), generator("window_bottom", window_bottom()), q);
    Node features = Node([=](const FeatureRef& f, Context& c) {
        if (on_opening(f, c))
            openings(f, c);
        else if (f.kind == FeatureKind::edge &&
                 c.facade().edges()[static_cast<std::size_t>(f.index)].vertical())
            q(f, c);
        else
            b(f, c);
    });
    // Top corners of openings lay the lintel before any corner brick can notch it.
    Node arch = generator("arch_stones", arch_stones());
    Node tree = by_kind(arches(arch, features), arches(arch, features), b);
    return Node([tree](const FeatureRef& f, Context& c) {
        c.data().quoined = true;  // the brick layouts bond the quoins in (quoin_rows.hpp)
        c.data().lintels = true;  // and close the bond against every lintel (lintel.hpp)
        tree(f, c);
    });
}

Node ashlar_tree() {
    Node a = generator("ashlar", ashlar());
    Node arch = generator("arch_stones", arch_stones());
    Node wb = generator("window_bottom", sill_stones());
    Node lin = generator("lintel", lintel());
    // Openings: a lintel over a straight head (its corners lay it first), sill stones under.
    Node relief = by_label("relieving", generator("relieving_arch", relieving_arch(), lin), lin);
    Node openings = by_part(relief, by_kind(wb, wb, a), a);
    Node features = Node([=](const FeatureRef& f, Context& c) {
        if (on_opening(f, c))
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
