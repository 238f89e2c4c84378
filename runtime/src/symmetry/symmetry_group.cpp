#include "symmetry/symmetry_group.hpp"

#include <acanthus/error.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

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
    return (kind == Kind::cyclic ? "c" : "d") + std::to_string(order);
}

namespace detail {

SymmetryGroup::SymmetryGroup(const Symmetry& spec, Point center) : spec_(spec), center_(center) {
    const int n = std::max(1, spec.order);
    const bool dihedral = spec.kind == Symmetry::Kind::dihedral;
    wedge_ = (dihedral ? M_PI : 2 * M_PI) / n;
    transforms_.push_back(Isometry{});
    for (int k = 1; k < n; ++k) transforms_.push_back(Isometry::rotation(center, 2 * M_PI * k / n));
    if (dihedral)
        for (int k = 0; k < n; ++k)
            transforms_.push_back(Isometry::reflection(center, kStart + M_PI * k / n));
}

bool SymmetryGroup::in_domain(Point p, double tolerance) const {
    if (transforms_.size() == 1) return true;
    const Vector v = p - center_;
    const double r = v.length();
    if (r <= tolerance) return true;
    double t = std::atan2(v.y, v.x) - kStart;
    t -= 2 * M_PI * std::floor(t / (2 * M_PI));  // [0, 2 pi)
    const double slack = tolerance / r;
    return t <= wedge_ + slack || t >= 2 * M_PI - slack;
}

Point SymmetryGroup::snap(Point p, double tolerance) const {
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

double SymmetryGroup::clearance(Point c, double tolerance) const {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < transforms_.size(); ++k) {
        const double d = distance(transforms_[k].apply(c), c);
        if (d > tolerance) best = std::min(best, d / 2);
    }
    return best;
}

std::vector<std::pair<Point, Point>> SymmetryGroup::domain_edges(double radius) const {
    if (transforms_.size() == 1) return {};
    std::vector<std::pair<Point, Point>> out;
    for (double t : {kStart, kStart + wedge_})
        out.emplace_back(center_, center_ + Vector(std::cos(t), std::sin(t)) * radius);
    return out;
}

}  // namespace detail
}  // namespace acanthus
