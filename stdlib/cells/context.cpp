// Context::place: cells claim space-filling footprints in the occupancy maps [3.3]; the drawn
// cell is the claim shrunk by half the mortar joint [5.4].
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cmath>
#include <utility>

#include "clip.hpp"
#include "context_data.hpp"
#include "facade_data.hpp"
#include "face_occupancy.hpp"
#include "feature_walk.hpp"
#include "run_ends.hpp"

namespace acanthus::cells {

namespace detail {
int face_of(const Facade& facade, const FeatureRef& f) {
    switch (f.kind) {
        case FeatureKind::corner:
            return facade.corners()[static_cast<std::size_t>(f.index)].face;
        case FeatureKind::edge:
            return facade.edges()[static_cast<std::size_t>(f.index)].face;
        case FeatureKind::face:
            return f.index;
    }
    return 0;
}

namespace {

// A brick cut off by a jamb a few millimetres off a whole number of quarter bricks: laid whole.
// Shorter than its space, it reaches into the reveal's half joint (the brick's face may be the
// reveal); longer, its head joint opens by the difference. That head joint never closes (past
// the tolerance, or within a quarter brick of the joint above or below).
double nominal_width(Rect r, const Options& o) {
    const double q = (o.brick_length + o.mortar) / 4;
    const double m = std::round(r.width() / q);
    return m >= 1 ? m * q - o.mortar : 0;
}

}  // namespace

// The drawn brick, or an empty rect when the piece is no shaved brick at a jamb.
Rect nominal_at_jamb(Rect r, Rect claim, Rect drawn, const Options& o) {
    const double h = o.mortar / 2, w = nominal_width(r, o), short_by = w - (r.width() - o.mortar);
    const double eps = 1e-9 * std::max(1.0, std::abs(r.x1) + std::abs(r.y1));
    const bool left = r.x0 > claim.x0 + eps, right = r.x1 < claim.x1 - eps;
    // Full-height courses only, cut at one end only; short by no more than the reveal's half
    // joint (and twice the tolerance), or long by no more than the head joint may open.
    // Never by more than a quarter joint: a quarter brick is a quarter joint shorter than a unit,
    // so two such joints moved towards each other in consecutive courses stay a quarter brick
    // apart (no straight joint).
    // On a grid whose units the joints squeezed to fit the wall, a unit is less than a quarter
    // joint over a quarter brick: the joint moves by half what the brick reaches into it, and
    // stays a tenth of a joint clear of that margin.
    const double most = std::min(o.mortar / 4, o.joint_tolerance);
    const double units =
        std::max(1.0, std::round(claim.width() / ((o.brick_length + o.mortar) / 4)));
    const double margin = claim.width() / units - o.brick_length / 4;
    const double reach = std::min({h, 2 * most, 2 * margin - 0.1 * o.mortar});
    // On units the joints opened to bring jambs onto joints, the next brick's joint is open
    // already, by up to half a stretcher's four units' stretch.
    const double opened =
        std::max(0.0, 4 * (claim.width() / units - (o.brick_length + o.mortar) / 4));
    const bool fits = short_by > 0 ? short_by <= reach + eps : -short_by <= most - opened + eps;
    if (w <= 0 || std::abs(short_by) <= eps || !fits || left == right || r.y0 > drawn.y0 + eps ||
        r.y1 < drawn.y1 - eps ||
        std::abs(r.height() - (drawn.height() + o.mortar)) > o.joint_tolerance + eps)
        return {0, 0, 0, 0};
    // Short of its space, the brick keeps its uncut end where a whole brick's is (its head
    // joint as laid) and reaches into the reveal's half joint, never past the reveal; longer,
    // it stands a half joint off the reveal and the head joint opens, by a quarter joint at most.
    if (short_by > 0)
        return left ? Rect{std::max(r.x0, drawn.x1 - w), drawn.y0, std::max(r.x0, drawn.x1 - w) + w,
                           drawn.y1}
                    : Rect{std::min(r.x1, drawn.x0 + w) - w, drawn.y0, std::min(r.x1, drawn.x0 + w),
                           drawn.y1};
    return left ? Rect{r.x0 + h, drawn.y0, r.x0 + h + w, drawn.y1}
                : Rect{r.x1 - h - w, drawn.y0, r.x1 - h, drawn.y1};
}

}  // namespace detail

Context::Context(const Facade& facade, const Options& options, std::uint64_t seed)
    : data_(std::make_unique<detail::ContextData>()) {
    data_->facade = &facade;
    data_->options = options;
    data_->random.reseed(seed);
    for (const Edge& e : facade.edges()) data_->edges.emplace_back(e.length);
    data_->faces.resize(facade.faces().size());
    Rect b = facade.bounds();
    data_->edge_tolerance = 2e-5 * std::max(b.width(), b.height());
    data_->smallest_cell = 0.1 * options.brick_length * options.brick_height;
}

Context::~Context() = default;
const Facade& Context::facade() const { return *data_->facade; }
const Options& Context::options() const { return data_->options; }
Random& Context::random() { return data_->random; }
EdgeOccupancy& Context::edge_occupancy(int edge) {
    return data_->edges.at(static_cast<std::size_t>(edge));
}
FaceOccupancy& Context::face_occupancy(int face) {
    std::unique_ptr<FaceOccupancy>& f = data_->faces.at(static_cast<std::size_t>(face));
    if (!f) f = std::make_unique<FaceOccupancy>(*data_->facade, face);
    return *f;
}
const FeatureRef& Context::feature() const { return data_->feature; }
std::vector<Cell>& Context::cells() { return data_->cells; }

void Context::begin(const std::string& generator, const FeatureRef& feature) {
    data_->generator = generator;
    data_->feature = feature;
    const std::vector<std::string>* labels = nullptr;
    const Facade& f = *data_->facade;
    auto i = static_cast<std::size_t>(feature.index);
    switch (feature.kind) {
        case FeatureKind::corner:
            labels = &f.corners()[i].labels;
            break;
        case FeatureKind::edge:
            labels = &f.edges()[i].labels;
            break;
        case FeatureKind::face:
            labels = &f.faces()[i].labels;
            break;
    }
    data_->label.clear();
    for (const std::string& l : *labels) {
        if (!data_->label.empty()) data_->label += ' ';
        data_->label += l;
    }
}

using detail::axis_rect;

namespace {

// The vertices of `d` (a cut piece drawn inset by `h` from its claim `claimed`) on the claim's
// beds moved to the drawn brick's beds, unless another vertex lies between, where the move
// could fold the outline.
void keep_beds(std::vector<Point>& d, Rect claimed, Rect drawn, double h) {
    const double eps = 1e-7 * std::max(1.0, std::abs(claimed.x1) + std::abs(claimed.y1));
    for (auto [from, to] : {std::pair{claimed.y0 + h, drawn.y0}, {claimed.y1 - h, drawn.y1}}) {
        const double lo = std::min(from, to), hi = std::max(from, to);
        bool on = false, between = false;
        for (Point p : d) {
            on |= std::abs(p.y - from) <= eps;
            between |= std::abs(p.y - from) > eps && p.y > lo - eps && p.y < hi + eps;
        }
        if (!on || between) continue;
        for (Point& p : d)
            if (std::abs(p.y - from) <= eps) p.y = to;
    }
}

// A rectangle (its outline may hold points along its sides) of whole units whose joints
// opened or closed, up to the tolerance, is drawn at the brick's nominal length: an end that is
// its claim's where the layout lays it (`drawn`: flush at a jamb, its joints shared), else
// centred. (Closed: units set out between jambs a little short, the brick's corner cut by a
// gable's rake; drawn short, it read as a brick shaved 1-3 mm.)
void nominal_length(std::vector<Point>& d, const Options& o, Rect claimed, Rect drawn) {
    if (d.empty()) return;
    Rect b{d[0].x, d[0].y, d[0].x, d[0].y};
    for (Point p : d)
        b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
    const double eps = 1e-3 * o.mortar;
    for (Point p : d)
        if (std::abs(p.x - b.x0) > eps && std::abs(p.x - b.x1) > eps &&
            std::abs(p.y - b.y0) > eps && std::abs(p.y - b.y1) > eps)
            return;
    if (std::abs(std::abs(detail::area_of(d)) - b.width() * b.height()) > eps * b.height()) return;
    const double q = (o.brick_length + o.mortar) / 4, m = std::round((b.width() + o.mortar) / q);
    const double over = b.width() + o.mortar - m * q;
    if (m < 1 || std::abs(over) <= eps || std::abs(over) > m * o.joint_tolerance / 4 + eps)
        return;
    const double w = m * q - o.mortar, h = o.mortar / 2;
    double x0 = (b.x0 + b.x1 - w) / 2;
    const double at = std::abs(b.x0 - (claimed.x0 + h)) <= eps   ? drawn.x0
                      : std::abs(b.x1 - (claimed.x1 - h)) <= eps ? drawn.x1 - w
                                                                 : x0;
    if (at >= b.x0 - h && at + w <= b.x1 + h) x0 = at;
    // Its beds the course's, as keep_beds() sets them (a side's extra point can stop it).
    if (std::abs(b.y0 - (claimed.y0 + h)) <= eps) b.y0 = drawn.y0;
    if (std::abs(b.y1 - (claimed.y1 - h)) <= eps) b.y1 = drawn.y1;
    d = {{x0, b.y0}, {x0 + w, b.y0}, {x0 + w, b.y1}, {x0, b.y1}};
}

}  // namespace

int Context::place_free_rect(Rect r, int course, const Rect* drawn) {
    const Facade& facade = *data_->facade;
    int face = detail::face_of(facade, data_->feature);
    face_occupancy(face).claim(r);
    double h = data_->options.mortar / 2;
    if (drawn) r = {drawn->x0 - h, drawn->y0 - h, drawn->x1 + h, drawn->y1 + h};
    if (r.width() <= 2 * h || r.height() <= 2 * h) return 0;
    if ((r.width() - 2 * h) * (r.height() - 2 * h) < data_->smallest_cell) return 0;
    data_->add_cell(course).polygon = {
        {r.x0 + h, r.y0 + h}, {r.x1 - h, r.y0 + h}, {r.x1 - h, r.y1 - h}, {r.x0 + h, r.y1 - h}};
    return 1;
}

int Context::place(const std::vector<Point>& claim, int course, bool clip, const Rect* drawn) {
    const Facade& facade = *data_->facade;
    int face = detail::face_of(facade, data_->feature);
    FaceOccupancy& occupancy = face_occupancy(face);
    const detail::IntScale& scale = occupancy.data().scale();
    std::vector<std::vector<Point>> pieces;
    Rect r;
    bool whole = !clip;
    if (clip && axis_rect(claim, r)) {
        // What the booleans would give when the rectangle is wholly free: itself on the grid.
        auto snap = [&](Point p) { return scale.to_point(scale.to_int(p)); };
        Point a = snap({r.x0, r.y0}), b = snap({r.x1, r.y1});
        if (a.x < b.x && a.y < b.y && occupancy.data().snapped_rect_is_free({a.x, a.y, b.x, b.y})) {
            pieces.push_back({a, {b.x, a.y}, b, {a.x, b.y}});
            whole = true;
        } else
            pieces = occupancy.free_part(claim);
    } else if (clip) {
        pieces = occupancy.free_part(claim);
    } else {
        pieces.push_back(claim);
    }
    int added = 0;
    std::vector<int>& near = data_->near_edges;
    for (const std::vector<Point>& piece : pieces) {
        occupancy.claim(piece);
        if (data_->feature.kind != FeatureKind::face) {
            // Project the claim onto the face's edges it lies along (its vertices on them).
            Rect box = detail::bounds_of(piece);
            double tol = data_->edge_tolerance;
            Rect grown{box.x0 - tol, box.y0 - tol, box.x1 + tol, box.y1 + tol};
            occupancy.data().edges_near(grown, near);
            for (int e : near) {
                const Edge& edge = facade.edges()[static_cast<std::size_t>(e)];
                if (!detail::overlaps(edge.bounds, grown)) continue;
                double s0 = 1e300, s1 = -1e300;
                int on = 0;
                for (Point v : piece) {
                    if (!grown.contains(v)) continue;
                    double s = edge.project(v);
                    if (distance(edge.at(s), v) > tol) continue;
                    s0 = std::min(s0, s);
                    s1 = std::max(s1, s);
                    ++on;
                }
                if (on >= 2) data_->edges[static_cast<std::size_t>(e)].claim(s0, s1);
            }
        }
        std::vector<std::vector<Point>> drawn_cells;
        double h = data_->options.mortar / 2;
        if (whole && drawn) {
            drawn_cells.push_back(detail::polygon_of(*drawn));
        } else if (Rect claimed, n;
                   drawn && axis_rect(piece, r) && axis_rect(claim, claimed) &&
                   (n = detail::nominal_at_jamb(r, claimed, *drawn, data_->options)).width() > 0) {
            drawn_cells.push_back(detail::polygon_of(n));
        } else if (axis_rect(piece, r)) {
            // A cut piece keeps its course's beds: where the joints took up a course's
            // difference, whole bricks are drawn at nominal height and so are the cut ones.
            // One bounded by joints at both ends (cut only in height, or not at all) is drawn
            // at the brick's nominal length too.
            Rect claimed, d{r.x0 + h, r.y0 + h, r.x1 - h, r.y1 - h};
            if (drawn && axis_rect(claim, claimed)) {
                const double eps = 1e-9 * std::max(1.0, std::abs(r.x1) + std::abs(r.y1));
                if (std::abs(r.y0 - claimed.y0) <= eps) d.y0 = drawn->y0;
                if (std::abs(r.y1 - claimed.y1) <= eps) d.y1 = drawn->y1;
                // Ends within a thousandth of a joint of the claim's: the booleans' grid, not a
                // cut (unit lines set out between jambs fall between its points).
                const double ends = std::max(eps, 1e-3 * data_->options.mortar);
                const double q = (data_->options.brick_length + data_->options.mortar) / 4;
                const double m = std::round(r.width() / q);
                if (std::abs(r.x0 - claimed.x0) <= ends && std::abs(r.x1 - claimed.x1) <= ends) {
                    d.x0 = drawn->x0, d.x1 = drawn->x1;
                } else if (m >= 1 && r.width() - m * q > ends &&
                           r.width() - m * q <= m * data_->options.joint_tolerance / 4 + ends) {
                    // Whole units the joints opened (the rest of the claim taken before): the
                    // brick at its nominal length, its end that is the claim's where the layout
                    // lays it (flush at a jamb), else centred.
                    const double w = m * q - data_->options.mortar, c = (r.x0 + r.x1) / 2;
                    d.x0 = c - w / 2, d.x1 = c + w / 2;
                    const double at = std::abs(r.x0 - claimed.x0) <= ends   ? drawn->x0
                                      : std::abs(r.x1 - claimed.x1) <= ends ? drawn->x1 - w
                                                                            : d.x0;
                    if (at >= r.x0 && at + w <= r.x1) d.x0 = at, d.x1 = at + w;
                }
            }
            if (d.width() > 0 && d.height() > 0) drawn_cells.push_back(detail::polygon_of(d));
        } else {
            drawn_cells = detail::shrink(piece, h, scale);
            // Cut at a corner only (an extrados through its end), a piece keeps its course's
            // beds as well: its level sides that lie on the claim's beds move to the drawn ones.
            if (Rect claimed; drawn && axis_rect(claim, claimed))
                for (std::vector<Point>& d : drawn_cells) {
                    keep_beds(d, claimed, *drawn, h);
                    nominal_length(d, data_->options, claimed, *drawn);
                }
        }
        for (std::vector<Point>& d : drawn_cells) {
            // A piece under a tenth of a brick's face is no cell a mason lays: mortar fills it.
            if (detail::area_of(d) < data_->smallest_cell) continue;
            data_->add_cell(course).polygon = std::move(d);
            ++added;
        }
    }
    return added;
}

}  // namespace acanthus::cells
