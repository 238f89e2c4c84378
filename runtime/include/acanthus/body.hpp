// The support library visible in rule, %draw, %exhausted and %source code
// (generated files say `using namespace acanthus::body;`).
#pragma once

#include <acanthus/canvas.hpp>
#include <acanthus/environment.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/progress.hpp>
#include <acanthus/rule_call.hpp>
#include <acanthus/skeletal_stroke.hpp>
#include <cmath>
#include <type_traits>
#include <vector>

namespace acanthus::body {

using acanthus::ArcProxy;
using acanthus::BezierProxy;
using acanthus::Canvas;
using acanthus::Circle;
using acanthus::CircleProxy;
using acanthus::Color;
using acanthus::CONTINUE;
using acanthus::Corner;
using acanthus::Direction;
using acanthus::distance;
using acanthus::Element;
using acanthus::FAILURE;
using acanthus::Flow;
using acanthus::hue;
using acanthus::lerp;
using acanthus::LineSegmentProxy;
using acanthus::midpoint;
using acanthus::parse_color;
using acanthus::Point;
using acanthus::PointProxy;
using acanthus::PolygonProxy;
using acanthus::Proxy;
using acanthus::Rect;
using acanthus::report_progress;
using acanthus::Result;
using acanthus::SkeletalStroke;
using acanthus::STOP;
using acanthus::SUCCESS;
using acanthus::Vector;

// The empty circle C ($goal).
Circle goal();
// True if any proxy of `e` overlaps a placed element's proxy or leaves the region.
bool intersection(const Element& e);
bool intersection(const Element* e);
bool intersection(const Proxy& p);
bool inside(Point p);
double distance_to_boundary(Point p);
Element* nearest_element(Point p);
void clear_exclude_list();
// The panel's corners, its signal points (Region::corners): empty when there is no region.
const std::vector<Corner>& corners();
// Adds a dynamic child created with `new` during this rule call.
void new_child(Element& e);
void new_child(Element* e);

// `rng.uniform(lo, hi)`, `rng.normal(mean, sd)`, `rng.chance(p)`: seeded by --rng-seed.
struct RandomSource {
    double uniform() const;
    double uniform(double lo, double hi) const;
    long long uniform_int(long long lo, long long hi) const;
    double normal(double mean = 0.0, double stddev = 1.0) const;
    bool chance(double probability) const;
};
inline constexpr RandomSource rng{};

// min/max over mixed arithmetic types, so min(3, r) works with a double r.
template <class A, class B>
constexpr std::common_type_t<A, B> min(A a, B b) {
    return b < a ? b : a;
}
template <class A, class B>
constexpr std::common_type_t<A, B> max(A a, B b) {
    return a < b ? b : a;
}

}  // namespace acanthus::body
