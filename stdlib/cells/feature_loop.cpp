#include "feature_loop.hpp"

#include <algorithm>
#include <cmath>

#include "clip.hpp"

namespace acanthus::cells::detail {

namespace {

// Window analysis [5.3] from the normal into the wall: for an opening, wall below the edge
// means its bottom (+y is down); for the wall's outline the same normal means its top.
Part part_of(Vector inward, bool opening) {
    const double lean = std::sqrt(0.5);
    if (inward.y > lean) return opening ? Part::bottom : Part::top;
    if (inward.y < -lean) return opening ? Part::top : Part::bottom;
    return Part::side;
}

bool same_circle(const Segment& a, const Segment& b) {
    double tol = 1e-9 * std::max(1.0, a.radius);
    return distance(a.center, b.center) <= tol && std::abs(a.radius - b.radius) <= tol;
}

void append_unique(std::vector<std::string>& to, const std::vector<std::string>& from) {
    for (const std::string& s : from)
        if (std::find(to.begin(), to.end(), s) == to.end()) to.push_back(s);
}

}  // namespace

void flatten(const Segment& s, double tolerance, std::vector<Point>& out) {
    if (!s.arc) {
        out.push_back(s.a);
        return;
    }
    // Chord error r (1 - cos(step / 2)) <= tolerance.
    double step = 2 * std::acos(std::max(-1.0, 1 - tolerance / std::max(s.radius, 1e-300)));
    step = std::min(step, M_PI / 18);
    int n = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / std::max(step, 1e-6))));
    n = std::min(n, 4096);
    for (int i = 0; i < n; ++i) out.push_back(s.at(s.length() * i / n));
}

void add_loop(FacadeData& data, int face, const std::vector<LoopSegment>& loop, bool interior_left,
              const std::vector<ShapeLabels>& shapes) {
    const std::size_t n = loop.size();
    if (n == 0) return;
    // Vertex i sits between segment i-1 and segment i: a corner, a break (kind or circle
    // changes) or a smooth joint.
    std::vector<char> corner(n, 0), brk(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const LoopSegment& prev = loop[(i + n - 1) % n];
        const LoopSegment& next = loop[i];
        Vector tin = prev.segment.tangent(prev.segment.length());
        Vector tout = next.segment.tangent(0);
        double turn = std::atan2(tin.cross(tout), tin.dot(tout));
        bool is_corner = std::abs(turn) > kCornerTurn || prev.shape != next.shape;
        bool kind_change = prev.segment.arc != next.segment.arc ||
                           (prev.segment.arc && !same_circle(prev.segment, next.segment));
        corner[i] = is_corner;
        brk[i] = is_corner || kind_change;
    }
    std::size_t first = n;
    for (std::size_t i = 0; i < n; ++i)
        if (brk[i]) {
            first = i;
            break;
        }

    const int first_edge = static_cast<int>(data.edges.size());
    auto finish_edge = [&](Edge& e, int shape) {
        e.offsets.clear();
        double s = 0;
        for (const Segment& seg : e.segments) {
            e.offsets.push_back(s);
            s += seg.length();
        }
        e.length = s;
        e.arc = e.segments.front().arc;
        e.face = face;
        e.interior_left = interior_left;
        if (shape >= 0) {
            e.labels = shapes[static_cast<std::size_t>(shape)].labels;
            e.opening = shapes[static_cast<std::size_t>(shape)].opening;
        }
        std::vector<Point> pts;
        for (const Segment& seg : e.segments) flatten(seg, 1e-3 * std::max(1.0, seg.radius), pts);
        pts.push_back(e.segments.back().b);
        e.bounds = bounds_of(pts);
        e.part = part_of(e.inward(e.length / 2), e.opening);
        data.faces[static_cast<std::size_t>(face)].edges.push_back(
            static_cast<int>(data.edges.size()));
        data.edges.push_back(std::move(e));
    };

    if (first == n) {  // one closed edge: a circle, or a smooth closed curve
        Edge e;
        for (const LoopSegment& s : loop) e.segments.push_back(s.segment);
        e.closed = true;
        finish_edge(e, loop.front().shape);
        return;
    }
    // Edges from break to break, starting at the first break.
    std::vector<std::size_t> starts;  // vertex index where each edge starts
    Edge current;
    int shape = -1;
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t i = (first + k) % n;
        if (brk[i] && !current.segments.empty()) {
            finish_edge(current, shape);
            current = Edge{};
        }
        if (current.segments.empty()) {
            starts.push_back(i);
            shape = loop[i].shape;
        }
        current.segments.push_back(loop[i].segment);
    }
    finish_edge(current, shape);

    const int edge_count = static_cast<int>(data.edges.size()) - first_edge;
    for (int k = 0; k < edge_count; ++k) {
        std::size_t v = starts[static_cast<std::size_t>(k)];
        if (!corner[v]) continue;
        int out_edge = first_edge + k;
        int in_edge = first_edge + (k + edge_count - 1) % edge_count;
        Edge& ein = data.edges[static_cast<std::size_t>(in_edge)];
        Edge& eout = data.edges[static_cast<std::size_t>(out_edge)];
        Corner c;
        c.position = eout.segments.front().a;
        c.in = ein.tangent(ein.length);
        c.out = eout.tangent(0);
        c.convex = (c.in.cross(c.out) > 0) == interior_left;
        c.edge_in = in_edge;
        c.edge_out = out_edge;
        c.face = face;
        c.opening = ein.opening || eout.opening;
        c.labels = ein.labels;
        append_unique(c.labels, eout.labels);
        // A corner is on the bottom (top) of its shape when an edge it joins is.
        const Edge& own = ein.opening == c.opening ? ein : eout;
        const Edge& other = &own == &ein ? eout : ein;
        if (own.part == Part::bottom || (other.opening == c.opening && other.part == Part::bottom))
            c.part = Part::bottom;
        else if (own.part == Part::top || (other.opening == c.opening && other.part == Part::top))
            c.part = Part::top;
        else
            c.part = Part::side;
        int index = static_cast<int>(data.corners.size());
        ein.corner_end = index;
        eout.corner_start = index;
        data.faces[static_cast<std::size_t>(face)].corners.push_back(index);
        data.corners.push_back(std::move(c));
    }
}

}  // namespace acanthus::cells::detail
