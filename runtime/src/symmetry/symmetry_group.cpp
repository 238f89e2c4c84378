#include "symmetry/symmetry_group.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "proxy/overlap.hpp"

namespace acanthus {

namespace {
// Domains and mirrors start from the upward direction (y points down): d1 is a left-right
// mirror, as most panels are.
constexpr double kStart = -M_PI / 2;
}  // namespace

Symmetry Symmetry::parse(std::string_view text) {
    std::string s(text);
    for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    const std::string usage =
        "--symmetry expects cN (N rotations) or dN (N rotations and N mirrors), e.g. c6 or d8, "
        "not '" +
        std::string(text) + "'";
    if (s.size() < 2 || (s[0] != 'c' && s[0] != 'd') ||
        s.find_first_not_of("0123456789", 1) != std::string::npos)
        throw UsageError(usage);
    long n = 0;
    auto [end, ec] = std::from_chars(s.data() + 1, s.data() + s.size(), n);
    if (ec != std::errc() || end != s.data() + s.size() || n > kMaxOrder)
        throw UsageError("--symmetry " + std::string(text) + ": the order N must be at most " +
                         std::to_string(kMaxOrder));
    if (n < 1)
        throw UsageError("--symmetry " + std::string(text) + ": the order N must be 1 or more");
    Symmetry out;
    out.kind = s[0] == 'c' ? Kind::cyclic : Kind::dihedral;
    out.order = static_cast<int>(n);
    return out;
}

std::string Symmetry::name() const {
    std::string text(1, kind == Kind::cyclic ? 'c' : 'd');  // not `"c" + string`: GCC 12 -Wrestrict
    return text += std::to_string(order);
}

namespace detail {

SymmetryGroup::SymmetryGroup(const Symmetry& spec, Point center)
    : spec_(spec), name_(spec.name()), center_(center) {
    const int n = std::max(1, spec.order);
    const bool dihedral = spec.kind == Symmetry::Kind::dihedral;
    wedge_ = (dihedral ? M_PI : 2 * M_PI) / n;
    transforms_.push_back(Isometry{});
    for (int k = 1; k < n; ++k) transforms_.push_back(Isometry::rotation(center, 2 * M_PI * k / n));
    if (dihedral)
        for (int k = 0; k < n; ++k)
            transforms_.push_back(Isometry::reflection(center, kStart + M_PI * k / n));
    gap_edges_[0] = Vector(std::cos(kStart), std::sin(kStart));
    gap_edges_[1] = Vector(std::cos(kStart + wedge_), std::sin(kStart + wedge_));
    gap_bisector_ = Vector(std::cos(kStart + wedge_ / 2), std::sin(kStart + wedge_ / 2));
    gap_cos_ = std::cos(wedge_ / 2) - 1e-9;
}

namespace {

// Within this of the identity's matrix, an isometry is a translation.
constexpr double kSame = 1e-9;

}  // namespace

SymmetryGroup::SymmetryGroup(TranslationGroup group, const Region& region)
    : name_(std::move(group.name)),
      center_(group.generic),
      transforms_(std::move(group.transforms)),
      lattice_(true),
      window_(group.window),
      frame_(group.frame),
      region_(&region),
      cosets_(std::move(group.cosets)),
      lattice_a_(group.a),
      lattice_b_(group.b) {
    for (std::size_t k = 1; k < transforms_.size(); ++k) {
        const Isometry& g = transforms_[k];
        const Point q = g.apply(center_);
        const Vector n = q - center_;
        if (n.length() > kSame) halfplanes_.emplace_back(center_ + n * 0.5, n * (1 / n.length()));
        if (g.reverses()) {
            // A reflection with no glide (g g = identity) fixes its mirror, through the midpoint
            // of any point and its image, along the eigenvector of eigenvalue 1.
            const Isometry twice = g.then(g);
            if (std::abs(twice.e) > kSame * (1 + std::abs(g.e)) ||
                std::abs(twice.f) > kSame * (1 + std::abs(g.f)))
                continue;
            const double t = std::atan2(g.b, g.a) / 2;
            const Point o = frame_.center();
            mirrors_.emplace_back(o + (g.apply(o) - o) * 0.5, Vector(std::cos(t), std::sin(t)));
        } else if (std::abs(g.a - 1) > kSame || std::abs(g.b) > kSame) {
            // A rotation fixes the solution of (I - R) c = t.
            const double m00 = 1 - g.a, m01 = -g.c, m10 = -g.b, m11 = 1 - g.d;
            const double det = m00 * m11 - m01 * m10;
            centres_.emplace_back((m11 * g.e - m01 * g.f) / det, (m00 * g.f - m10 * g.e) / det);
        }
    }
}

bool SymmetryGroup::keeps(const Element& image, double tolerance) const {
    if (!lattice_) return true;
    for (std::size_t k = 0; k < image.proxy_count(); ++k) {
        const Proxy& p = image.proxy(k);
        if (window_) {
            const Rect b = p.bounds();
            if (b.x0 <= window_->x1 && window_->x0 <= b.x1 && b.y0 <= window_->y1 &&
                window_->y0 <= b.y1)
                return true;
        } else {
            // Beyond the region's bounds first: cheap, and sure for a curve whose end only
            // just leaves them (the band's ends).
            const Rect b = p.bounds(), r = region_->bounds();
            if (b.x0 < r.x0 - tolerance || b.y0 < r.y0 - tolerance || b.x1 > r.x1 + tolerance ||
                b.y1 > r.y1 + tolerance || leaves_region(p, *region_, tolerance))
                return false;
        }
    }
    return !window_;
}

std::vector<Point> SymmetryGroup::centre_classes(double tolerance) const {
    if (!lattice_) return {center_};
    std::vector<Point> out;
    for (Point c : centres_)
        for (const Isometry& g : transforms_) {
            const Point q = g.apply(c);
            if (!in_domain(q, tolerance)) continue;
            // One of a class: no transformation carries a kept centre onto it.
            bool known = false;
            for (Point r : out)
                for (const Isometry& h : transforms_)
                    if (distance(h.apply(r), q) <= tolerance) known = true;
            if (!known) out.push_back(q);
            break;
        }
    return out;
}

std::vector<std::pair<Point, Point>> SymmetryGroup::mirror_edges(double tolerance) const {
    std::vector<std::pair<Point, Point>> out;
    if (!lattice_) return out;
    for (const auto& [a, b] : domain_edges(0))
        for (const auto& [o, dir] : mirrors_)
            if (std::abs(dir.cross(a - o)) <= tolerance &&
                std::abs(dir.cross(b - o)) <= tolerance) {
                out.emplace_back(a, b);
                break;
            }
    return out;
}

bool SymmetryGroup::in_domain(Point p, double tolerance) const {
    if (lattice_) {
        for (const auto& [m, n] : halfplanes_)
            if ((p - m).dot(n) > tolerance) return false;
        return true;
    }
    if (transforms_.size() == 1) return true;
    const Vector v = p - center_;
    const double r = v.length();
    if (r <= tolerance) return true;
    double t = std::atan2(v.y, v.x) - kStart;
    t -= 2 * M_PI * std::floor(t / (2 * M_PI));  // [0, 2 pi)
    const double slack = tolerance / r;
    return t <= wedge_ + slack || t >= 2 * M_PI - slack;
}

bool SymmetryGroup::moves_apart(Point p, double d) const {
    const double d2 = d * d;
    if (!lattice_) {  // a rosette's transformations are the whole group
        for (std::size_t k = 1; k < transforms_.size(); ++k) {
            const Vector v = transforms_[k].apply(p) - p;
            if (!(v.x * v.x + v.y * v.y > d2)) return false;
        }
        return true;
    }
    const Vector a = lattice_a_, b = lattice_b_;
    const double a2 = a.dot(a), det = a.cross(b);
    const bool flat = b.x == 0 && b.y == 0;  // a frieze
    if (cosets_.empty() || !(a2 > 0) || (!flat && !(std::abs(det) > 0))) return false;
    // A lattice point two steps or more from the nearest in a coordinate is at least 1.5
    // times the spacing of the lattice's lines across that coordinate away.
    const double spacing =
        flat ? std::sqrt(a2)
             : std::min(std::abs(det) / std::sqrt(b.dot(b)), std::abs(det) / std::sqrt(a2));
    if (!(1.5 * spacing > d)) return false;
    for (std::size_t h = 0; h < cosets_.size(); ++h) {
        // The coset's isometries move p by v + i a + j b: the nearest 3 x 3 of them.
        const Vector v = cosets_[h].apply(p) - p;
        const double u = flat ? v.dot(a) / a2 : v.cross(b) / det;
        const double w = flat ? 0 : a.cross(v) / det;
        const long i0 = std::lround(-u), j0 = flat ? 0 : std::lround(-w);
        for (long i = i0 - 1; i <= i0 + 1; ++i)
            for (long j = flat ? 0 : j0 - 1; j <= (flat ? 0 : j0 + 1); ++j) {
                if (h == 0 && i == 0 && j == 0) continue;  // the identity (first coset)
                const Vector m = v + a * static_cast<double>(i) + b * static_cast<double>(j);
                if (!(m.x * m.x + m.y * m.y > d2)) return false;
            }
    }
    return true;
}

double SymmetryGroup::domain_gap(Point p) const {
    if (lattice_ || transforms_.size() < 2 || !(wedge_ < 0.99 * M_PI)) return 0;
    const Vector a = p - center_;
    const double r = std::sqrt(a.x * a.x + a.y * a.y);  // hypot()'s care is not needed
    // Inside, or within rounding of an edge (the margin moves the test by 1e-9 of r): 0.
    if (a.dot(gap_bisector_) >= r * gap_cos_) return 0;
    // Outside a convex wedge the nearest point lies on an edge's ray.
    double gap = r;
    for (const Vector& u : gap_edges_)
        if (a.dot(u) > 0) gap = std::min(gap, std::abs(a.x * u.y - a.y * u.x));
    return gap * (1 - 1e-9);
}

std::vector<Point> SymmetryGroup::domain_part(const Circle& c, double tolerance,
                                              double flatness) const {
    // The circle as a polygon through points on it (the chord's sagitta at most `flatness`).
    const double step = c.radius > flatness ? 2 * std::acos(1 - flatness / c.radius) : M_PI / 2;
    const int n = std::clamp(static_cast<int>(std::ceil(2 * M_PI / step)), 16, 4096);
    std::vector<Point> poly;
    poly.reserve(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        poly.push_back(c.center + Vector(std::cos(a), std::sin(a)) * c.radius);
    }
    // The domain as half-planes (p - m) . normal <= slack.
    std::vector<std::pair<Point, Vector>> cuts;
    if (lattice_) {
        cuts = halfplanes_;
    } else if (transforms_.size() > 1) {
        // The wedge from angle kStart to kStart + wedge_ about the centre (at most a half-turn).
        const Vector first(std::cos(kStart), std::sin(kStart));
        const Vector last(std::cos(kStart + wedge_), std::sin(kStart + wedge_));
        cuts.emplace_back(center_, Vector(first.y, -first.x));
        cuts.emplace_back(center_, Vector(-last.y, last.x));
    }
    // Sutherland-Hodgman, one half-plane at a time.
    for (const auto& [m, normal] : cuts) {
        std::vector<Point> out;
        const std::size_t size = poly.size();
        for (std::size_t k = 0; k < size; ++k) {
            const Point a = poly[k], b = poly[(k + 1) % size];
            const double da = (a - m).dot(normal) - tolerance, db = (b - m).dot(normal) - tolerance;
            if (da <= 0) out.push_back(a);
            if ((da < 0 && db > 0) || (da > 0 && db < 0))
                out.push_back(a + (b - a) * (da / (da - db)));
        }
        poly = std::move(out);
        if (poly.size() < 3) return {};
    }
    return poly;
}

Point SymmetryGroup::snap(Point p, double tolerance) const {
    if (lattice_) {
        double best = tolerance;
        std::optional<Point> out;
        for (Point c : centres_)
            if (distance(c, p) <= best) {
                best = distance(c, p);
                out = c;
            }
        if (out) return *out;
        for (const auto& [o, dir] : mirrors_) {
            const Vector v = p - o;
            const double off = std::abs(dir.cross(v));
            if (off <= best) {
                best = off;
                out = o + dir * dir.dot(v);
            }
        }
        return out ? *out : p;
    }
    const Vector v = p - center_;
    if (v.length() <= tolerance) return center_;
    if (spec_.kind != Symmetry::Kind::dihedral) return p;
    double best = tolerance;
    Point out = p;
    for (int k = 0; k < spec_.order; ++k) {
        const Vector dir(std::cos(kStart + M_PI * k / spec_.order),
                         std::sin(kStart + M_PI * k / spec_.order));
        const double off = std::abs(dir.cross(v));
        if (off <= best) {
            best = off;
            out = center_ + dir * dir.dot(v);
        }
    }
    return out;
}

double SymmetryGroup::clearance(Point c, double tolerance, double at_most,
                                std::size_t* hint) const {
    // Squared distances decide what they surely can; hypot() (distance()) is taken only near
    // the tolerance and for the images that may be the nearest: distance()'s answer to the bit.
    constexpr double kLoose = 1 + 1e-12;
    const double tol2 = tolerance * tolerance;
    double best = std::numeric_limits<double>::infinity();
    double least = std::numeric_limits<double>::infinity();  // of the images surely beyond
    auto square = [&](std::size_t k) {
        const Vector v = c - transforms_[k].apply(c);
        return v.x * v.x + v.y * v.y;
    };
    // The loop below returns at_most at the first such transformation, whichever it is.
    if (hint && *hint > 0 && *hint < transforms_.size()) {
        const double s = square(*hint);
        if (s > tol2 * kLoose && s * kLoose < 4 * at_most * at_most) return at_most;
    }
    for (std::size_t k = 1; k < transforms_.size(); ++k) {
        const double s = square(k);
        if (s * kLoose < tol2) continue;  // surely within the tolerance
        if (s <= tol2 * kLoose) {
            const double d = distance(transforms_[k].apply(c), c);
            if (d > tolerance) best = std::min(best, d / 2);
        } else {
            least = std::min(least, s);
            // Surely beyond the tolerance and surely nearer than 2 at_most: done.
            if (s * kLoose < 4 * at_most * at_most) {
                if (hint) *hint = k;
                return at_most;
            }
        }
    }
    for (std::size_t k = 1; k < transforms_.size(); ++k) {
        const double s = square(k);
        if (s > tol2 * kLoose && s <= least * kLoose)
            best = std::min(best, distance(transforms_[k].apply(c), c) / 2);
    }
    return best;
}

std::vector<Circle> SymmetryGroup::clear_circles_in(const Circle& c, Point toward,
                                                    double tolerance) const {
    constexpr int kRings = 12, kSpokes = 48, kDirections = 16, kTouching = 64;
    // Only images of c's centre within 4 radii matter: farther, a point of c and its image are
    // more than 2 radii apart.
    std::vector<const Isometry*> near, fixing, mirrors;
    for (std::size_t k = 1; k < transforms_.size(); ++k) {
        const Isometry& g = transforms_[k];
        const double d = distance(g.apply(c.center), c.center);
        if (d > 4 * c.radius + tolerance) continue;
        near.push_back(&g);
        if (d <= tolerance) fixing.push_back(&g);
        // A reflection with no glide: the midpoint of p and its image lies on its mirror.
        if (g.reverses() && distance(g.then(g).apply(c.center), c.center) <= tolerance)
            mirrors.push_back(&g);
    }
    // The room about p (the largest circle there inside c and clear of its images), and
    // whether some transformation fixes p.
    // Squared distances decide what they surely can; hypot() (as distance() measures, and much
    // dearer) is taken only near the tolerance and for the images that may be the nearest, so
    // the answer is distance()'s to the last bit.
    constexpr double kLoose = 1 + 1e-12;
    const double tol2 = tolerance * tolerance;
    std::vector<double> squares(near.size());
    // Most points of the sample have less room than the best circle found: an upper bound of
    // the room from the squares (sqrt() within 1e-12, hypot() not taken) rules them out. Below
    // `bar_fixed` (a point some transformation fixes) or `bar_free` (else) the room is not
    // measured: -infinity, and `fixed` then tells nothing.
    constexpr double kBound = 1e-12;
    constexpr double kNone = -std::numeric_limits<double>::infinity();
    auto room = [&](Point p, bool& fixed, double bar_fixed, double bar_free) {
        fixed = false;
        const Vector to_centre = p - c.center;
        const double inside =
            c.radius -
            std::sqrt(to_centre.x * to_centre.x + to_centre.y * to_centre.y) * (1 - kBound) +
            kBound * c.radius;
        const double low = std::min(bar_fixed, bar_free);
        if (inside < low) return kNone;
        // An image nearer than twice the lower bar rules the point out whatever fixes it.
        const double least_bar = low > 0 ? 4 * low * low * (1 - 1e-9) : 0;
        double least = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < near.size(); ++k) {
            const Vector v = near[k]->apply(p) - p;
            double s = v.x * v.x + v.y * v.y;
            const bool close = s * kLoose < tol2 || (s <= tol2 * kLoose && v.length() <= tolerance);
            if (close) {
                fixed = true;
                s = -1;
            }
            squares[k] = s;
            if (s >= 0) least = std::min(least, s);
            if (least < least_bar) return kNone;
        }
        if (std::min(inside, std::sqrt(least) / 2 * (1 + kBound)) < (fixed ? bar_fixed : bar_free))
            return kNone;
        double r = c.radius - distance(p, c.center);
        // Every image is at least sqrt(least) / 2 away: when that is clearly beyond r, none
        // lowers it.
        if (r <= 0 || least / 4 >= r * r * kLoose) return r;
        for (std::size_t k = 0; k < near.size(); ++k)
            if (squares[k] >= 0 && squares[k] <= least * kLoose)
                r = std::min(r, distance(near[k]->apply(p), p) / 2);
        return r;
    };
    // [0]: the best circle about a point on a mirror, [1]: about a point on none; each with the
    // mirror it lies on.
    Circle best[2] = {{c.center, 0}, {c.center, 0}};
    const Isometry* best_mirror[2] = {nullptr, nullptr};
    // distance(p, c.center) <= tolerance, decided by the square where it surely can.
    auto on_centre = [&](Point p) {
        const Vector v = p - c.center;
        const double s = v.x * v.x + v.y * v.y;
        return s * kLoose < tol2 || (s <= tol2 * kLoose && v.length() <= tolerance);
    };
    auto consider = [&](Point p, const Isometry* mirror) {
        // room()'s first test, made here: most points of the sample fail it, and then neither
        // the centre's test nor the call is needed (the same test, so the same answer).
        const Vector to_centre = p - c.center;
        const double inside =
            c.radius -
            std::sqrt(to_centre.x * to_centre.x + to_centre.y * to_centre.y) * (1 - kBound) +
            kBound * c.radius;
        const double bar_fixed = best[0].radius + tolerance;
        double bar_free = best[1].radius + tolerance;
        if (inside < std::min(bar_fixed, bar_free)) return;
        // A point on a mirror is fixed by it (room() tells so by the same test): then only
        // bar_fixed decides, and room() rules the point out by it (the same answer).
        if (mirror) {
            const Vector v = mirror->apply(p) - p;
            const double s = v.x * v.x + v.y * v.y;
            if (s * kLoose < tol2 || (s <= tol2 * kLoose && v.length() <= tolerance)) {
                if (inside < bar_fixed) return;
                bar_free = bar_fixed;
            }
        }
        if (on_centre(p)) return;  // C itself
        bool fixed = false;
        const double r = room(p, fixed, bar_fixed, bar_free);
        Circle& b = best[fixed ? 0 : 1];
        if (r > b.radius + tolerance) {
            b = {p, r};
            best_mirror[fixed ? 0 : 1] = fixed ? mirror : nullptr;
        }
    };
    // The spokes' and the search's directions, each angle's cosine and sine taken once for
    // every call.
    struct Directions {
        Vector spokes[2][kSpokes], search[kDirections];
        Directions() {
            for (int odd = 0; odd < 2; ++odd)
                for (int j = 0; j < kSpokes; ++j) {
                    const double t = 2 * M_PI * (j + 0.5 * odd) / kSpokes;
                    spokes[odd][j] = Vector(std::cos(t), std::sin(t));
                }
            for (int d = 0; d < kDirections; ++d)
                search[d] = Vector(std::cos(2 * M_PI * d / kDirections),
                                   std::sin(2 * M_PI * d / kDirections));
        }
    };
    static const Directions kTables;
    const auto& spokes = kTables.spokes;
    const auto& directions = kTables.search;
    for (int i = 1; i < kRings; ++i)
        for (int j = 0; j < kSpokes; ++j) {
            const Point p = c.center + spokes[i % 2][j] * (c.radius * i / kRings);
            consider(p, nullptr);
            for (const Isometry* g : mirrors) consider(p + (g->apply(p) - p) * 0.5, g);
        }
    // Each refined by a pattern search in 16 directions (along its mirror for the first: the
    // optimum lies where several constraints meet, on a ridge), steps halving from the
    // sample's spacing.
    for (int k = 0; k < 2; ++k) {
        if (best[k].radius <= tolerance || (k == 0 && !best_mirror[0])) continue;
        for (double h = c.radius / kRings; h > c.radius * 1e-4; h /= 2)
            for (int moves = 0, moved = 1; moved && moves < 64; ++moves) {
                moved = 0;
                for (int d = 0; d < kDirections; ++d) {
                    Point q = best[k].center + directions[d] * h;
                    if (k == 0) q = q + (best_mirror[0]->apply(q) - q) * 0.5;
                    if (on_centre(q)) continue;
                    bool fixed = false;
                    const double bar = best[k].radius + tolerance;
                    const double r = room(q, fixed, bar, bar);
                    if (fixed == (k == 0) && r > best[k].radius + tolerance) {
                        best[k] = {q, r};
                        moved = 1;
                    }
                }
            }
    }
    std::vector<Circle> out;
    // First the largest one touching c where c is nearest `toward`: a rule growing from a
    // parent there (a curve leaving it, a spiral round C's centre) reaches it first.
    const Vector u = toward - c.center;
    if (u.length() > tolerance)
        for (int k = 1; k < kTouching; ++k) {
            const double r = c.radius * (1 - double(k) / kTouching);
            bool fixed = false;
            if (room(c.center + u * ((c.radius - r) / u.length()), fixed, r - tolerance,
                     r - tolerance) >= r - tolerance) {
                out.push_back({c.center + u * ((c.radius - r) / u.length()), r});
                break;
            }
        }
    for (const Circle& b : best) {
        if (b.radius <= tolerance) continue;
        Point pick = b.center;
        for (const Isometry* g : fixing) {
            const Point q = g->apply(b.center);
            if (distance(q, toward) < distance(pick, toward) - tolerance) pick = q;
        }
        out.push_back({pick, b.radius});
    }
    return out;
}

std::vector<std::pair<Point, Point>> SymmetryGroup::domain_edges(double radius) const {
    if (lattice_) {
        // The frame clipped by each half-plane in turn (Sutherland-Hodgman: convex).
        std::vector<Point> poly{{frame_.x0, frame_.y0},
                                {frame_.x1, frame_.y0},
                                {frame_.x1, frame_.y1},
                                {frame_.x0, frame_.y1}};
        for (const auto& [m, n] : halfplanes_) {
            std::vector<Point> next;
            for (std::size_t k = 0; k < poly.size(); ++k) {
                const Point a = poly[k], b = poly[(k + 1) % poly.size()];
                const double da = (a - m).dot(n), db = (b - m).dot(n);
                if (da <= 0) next.push_back(a);
                if ((da < 0 && db > 0) || (da > 0 && db < 0))
                    next.push_back(a + (b - a) * (da / (da - db)));
            }
            poly = std::move(next);
            if (poly.empty()) break;
        }
        std::vector<std::pair<Point, Point>> out;
        for (std::size_t k = 0; k < poly.size(); ++k)
            out.emplace_back(poly[k], poly[(k + 1) % poly.size()]);
        return out;
    }
    if (transforms_.size() == 1) return {};
    std::vector<std::pair<Point, Point>> out;
    for (double t : {kStart, kStart + wedge_})
        out.emplace_back(center_, center_ + Vector(std::cos(t), std::sin(t)) * radius);
    return out;
}

}  // namespace detail
}  // namespace acanthus
