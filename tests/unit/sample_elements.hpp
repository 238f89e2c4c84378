// Small hand-written element types, one per proxy kind, standing in for compiled rule files in the
// rendering and JSON tests.
#pragma once

#include <acanthus/canvas.hpp>
#include <acanthus/element.hpp>
#include <acanthus/pattern.hpp>
#include <deque>
#include <string>
#include <vector>

namespace sample {

using namespace acanthus;

inline const ElementType seed_type{"seed", {ProxyKind::point}, nullptr, nullptr, 1};
inline const ElementType dot_type{"dot", {ProxyKind::circle}, nullptr, nullptr, 4};
inline const ElementType stem_type{"stem", {ProxyKind::linesegment}, nullptr, nullptr, 8};
inline const ElementType leaf_type{
    "leaf", {ProxyKind::bezier, ProxyKind::arc}, nullptr, nullptr, 12};
inline const ElementType petal_type{"petal", {ProxyKind::polygon}, nullptr, nullptr, 16};

struct Seed : Element {
    PointProxy p;
    const ElementType& type() const override { return seed_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return p; }
};

struct Dot : Element {
    CircleProxy c;
    int order = 0;
    double weight = 0.5;
    bool marked = false;
    std::string label = "dot";
    const ElementType* kind = &dot_type;  // tests swap in types with a %draw
    const ElementType& type() const override { return *kind; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return c; }
    void write_fields(FieldWriter& out) const override {
        out.field("order", order);
        out.field("weight", weight);
        out.field("marked", marked);
        out.field("label", label);
    }
};

struct Stem : Element {
    LineSegmentProxy s;
    const ElementType& type() const override { return stem_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return s; }
};

struct Leaf : Element {
    BezierProxy b;
    ArcProxy a;
    const ElementType& type() const override { return leaf_type; }
    std::size_t proxy_count() const override { return 2; }
    Proxy& proxy(std::size_t k) override {
        if (k == 0) return b;
        return a;
    }
};

struct Petal : Element {
    PolygonProxy poly;
    const ElementType& type() const override { return petal_type; }
    std::size_t proxy_count() const override { return 1; }
    Proxy& proxy(std::size_t) override { return poly; }
};

// An ornament of every proxy kind inside rect:100,80, in placement order; elements live in
// deques (stable addresses, no Element::operator new needed).
struct Ornament {
    std::deque<Seed> seeds;
    std::deque<Dot> dots;
    std::deque<Stem> stems;
    std::deque<Leaf> leaves;
    std::deque<Petal> petals;
    std::vector<const Element*> placed;
    Pattern pattern;

    template <class T>
    T& add(std::deque<T>& store, Element* parent) {
        T& e = store.emplace_back();
        e.id = static_cast<int>(placed.size());
        e.parent = parent;
        e.depth = parent ? parent->depth + 1 : 0;
        if (parent) ++parent->children;
        placed.push_back(&e);
        return e;
    }

    Ornament() {
        pattern.name = "sample";
        pattern.file = "sample.acr";
        pattern.types = {&seed_type, &dot_type, &stem_type, &leaf_type, &petal_type};
        pattern.seed = &seed_type;
        Seed& seed = add(seeds, nullptr);
        seed.p.set({20, 60});
        seed.sterile = true;
        Element* parent = &seed;
        for (int i = 0; i < 5; ++i) {
            Dot& d = add(dots, parent);
            d.c.set({20.0 + 14 * i, 60.0 - 8 * i}, 6.0);
            d.order = i;
            d.weight = 0.25 * i;
            d.marked = i % 2 == 1;
            d.label = "dot" + std::to_string(i);
            parent = &d;
        }
        Stem& s = add(stems, &dots[0]);
        s.s.set({10, 10}, {40, 25});
        Leaf& l = add(leaves, &dots[1]);
        l.b.set({50, 10}, {60, 0}, {75, 25}, {90, 12});
        l.a.set({80, 65}, 8, 0, M_PI);
        Petal& p = add(petals, &dots[2]);
        p.poly.set({{5, 70}, {15, 70}, {10, 76}});
    }
};

}  // namespace sample
