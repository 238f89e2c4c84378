// The dots pattern of Wong et al. Appendix A, written by hand the way the compiler generates
// rule files (element classes, rule functions taking RuleCall&, a Pattern), for the growth
// engine's tests and benchmark.
#pragma once

#include <acanthus/body.hpp>
#include <acanthus/element.hpp>
#include <acanthus/pattern.hpp>
#include <acanthus/rule_call.hpp>

namespace dots {

using namespace acanthus::body;
using acanthus::ElementType;
using acanthus::FieldWriter;
using acanthus::Pattern;
using acanthus::ProxyKind;
using acanthus::RuleCall;
using acanthus::RuleInfo;

inline int dot_count = 0;

struct seed;
struct dot;
Element* create_seed();
Element* create_dot();
inline const ElementType seed_type{"seed", {ProxyKind::point}, &create_seed, nullptr, 1};
inline const ElementType dot_type{"dot", {ProxyKind::circle}, &create_dot, nullptr, 5};

struct seed : Element {
    PointProxy p0;
    const ElementType& type() const override { return seed_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
};

struct dot : Element {
    CircleProxy p0;
    int order = 0;
    const ElementType& type() const override { return dot_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p0; }
    void write_fields(FieldWriter& out) const override { out.field("order", order); }
};

inline Element* create_seed() { return new seed; }
inline Element* create_dot() { return new dot; }

// seed --> dot
inline Result rule_seed_dot(RuleCall& call_) {
    auto* self_ = &call_.parent<seed>();
    auto* c0_ = call_.make_static<dot>();
    c0_->p0.set(self_->p0, 3.0);
    c0_->order = dot_count++;
    self_->sterile = 1;
    return SUCCESS;
}

// dot --> dot
inline Result rule_dot_dot(RuleCall& call_) {
    auto* self_ = &call_.parent<dot>();
    auto* c0_ = call_.make_static<dot>();
    if (goal().radius < 0.5) return FAILURE;
    double r = min(3.0, goal().radius);
    c0_->p0.set(self_->p0.center.offset(goal().center - self_->p0.center, self_->p0.radius + r), r);
    c0_->order = dot_count++;
    return SUCCESS;
}

inline Pattern pattern() {
    Pattern p;
    p.name = "dots";
    p.file = "dots.acr";
    p.types = {&seed_type, &dot_type};
    p.seed = &seed_type;
    p.rules.push_back(
        RuleInfo{"seed --> dot", 18, "dots.acr", &seed_type, {&dot_type}, &rule_seed_dot});
    p.rules.push_back(
        RuleInfo{"dot --> dot", 29, "dots.acr", &dot_type, {&dot_type}, &rule_dot_dot});
    return p;
}

}  // namespace dots
