// Pattern generator trees [4.1]: nodes that place cells, and nodes that pass a feature on by
// its kind, label, orientation, window analysis, curve or convexity [5.3].
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>

namespace acanthus::cells {

namespace {

const std::vector<std::string>& labels_of(const Facade& f, const FeatureRef& r) {
    auto i = static_cast<std::size_t>(r.index);
    switch (r.kind) {
        case FeatureKind::corner:
            return f.corners()[i].labels;
        case FeatureKind::edge:
            return f.edges()[i].labels;
        case FeatureKind::face:
            return f.faces()[i].labels;
    }
    return f.faces()[i].labels;
}

}  // namespace

Node leave() {
    return Node([](const FeatureRef&, Context&) {});
}

Node generator(std::string name, Generator g) {
    return generator(std::move(name), std::move(g), Node());
}

Node generator(std::string name, Generator g, Node then) {
    return Node([name = std::move(name), g = std::move(g), then](const FeatureRef& f, Context& c) {
        c.begin(name, f);
        g(f, c);
        then(f, c);
    });
}

Node by_kind(Node corner, Node edge, Node face) {
    return Node([=](const FeatureRef& f, Context& c) {
        switch (f.kind) {
            case FeatureKind::corner:
                corner(f, c);
                break;
            case FeatureKind::edge:
                edge(f, c);
                break;
            case FeatureKind::face:
                face(f, c);
                break;
        }
    });
}

Node by_label(std::string label, Node with, Node without) {
    return Node([=](const FeatureRef& f, Context& c) {
        const std::vector<std::string>& l = labels_of(c.facade(), f);
        if (std::find(l.begin(), l.end(), label) != l.end())
            with(f, c);
        else
            without(f, c);
    });
}

Node by_orientation(Node horizontal, Node vertical, bool corners_horizontal) {
    return Node([=](const FeatureRef& f, Context& c) {
        bool h = true;
        switch (f.kind) {
            case FeatureKind::corner:
                h = corners_horizontal;
                break;
            case FeatureKind::edge:
                h = !c.facade().edges()[static_cast<std::size_t>(f.index)].vertical();
                break;
            case FeatureKind::face:
                h = false;
                break;  // a facade's faces stand upright
        }
        if (h)
            horizontal(f, c);
        else
            vertical(f, c);
    });
}

Node by_part(Node top, Node bottom, Node sides) {
    return Node([=](const FeatureRef& f, Context& c) {
        Part p = Part::side;
        auto i = static_cast<std::size_t>(f.index);
        if (f.kind == FeatureKind::corner) p = c.facade().corners()[i].part;
        if (f.kind == FeatureKind::edge) p = c.facade().edges()[i].part;
        switch (p) {
            case Part::top:
                top(f, c);
                break;
            case Part::bottom:
                bottom(f, c);
                break;
            case Part::side:
                sides(f, c);
                break;
        }
    });
}

Node by_curve(Node arc, Node straight) {
    return Node([=](const FeatureRef& f, Context& c) {
        const auto& edges = c.facade().edges();
        bool on_arc = false;
        if (f.kind == FeatureKind::edge) on_arc = edges[static_cast<std::size_t>(f.index)].arc;
        if (f.kind == FeatureKind::corner) {
            // A springing or an apex: the arch is set out from there, before any brick.
            const Corner& k = c.facade().corners()[static_cast<std::size_t>(f.index)];
            for (int e : {k.edge_in, k.edge_out})
                on_arc |= e >= 0 && edges[static_cast<std::size_t>(e)].arc;
        }
        if (on_arc)
            arc(f, c);
        else
            straight(f, c);
    });
}

Node by_convexity(Node convex, Node concave) {
    return Node([=](const FeatureRef& f, Context& c) {
        if (f.kind == FeatureKind::corner &&
            !c.facade().corners()[static_cast<std::size_t>(f.index)].convex)
            concave(f, c);
        else
            convex(f, c);
    });
}

}  // namespace acanthus::cells
