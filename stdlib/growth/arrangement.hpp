// The pattern under synthesis: placed elements and seeds as nodes of one graph, with a uniform
// grid over their positions for the local queries of growth (merge, collision, overlap).
#pragma once

#include <acanthus/point.hpp>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace acanthus::growth::detail {

struct Link {
    int node = -1;
    Vector desired;  // wanted offset node - this (the reference ring's, or as it was made)
};

struct Node {
    Point position;
    int symbol = -1;  // -1: an id-less seed
    int source = -1;  // reference element once placed; -1 for a seed
    double rotation = 0;
    double angle = 0;
    double scale = 1;
    double tint = 0;
    double radius = 0;
    double start_distance = 0;  // to the nearest start seed: the growth order
    bool alive = true;
    bool fixed = false;    // held by relaxation
    bool waiting = false;  // a seed set aside for a higher-priority seed near it
    std::vector<Link> links;
    bool placed() const { return source >= 0; }
};

class Arrangement {
  public:
    explicit Arrangement(double cell);

    int add(Node node);
    void kill(int id);
    void move(int id, Point to);
    // Adds the link both ways; `desired` is the wanted b - a (b's side gets its negation).
    void link(int a, int b, Vector desired);
    bool linked(int a, int b) const;
    void set_desired(int from, int to, Vector desired);

    // Alive nodes within `radius` of p, by index.
    std::vector<int> near(Point p, double radius) const;
    // Calls visit(id) for each alive node within `radius` of p, in no set order, until it
    // returns true (then true); nothing is allocated, for the hottest queries.
    template <class Visit>
    bool any_near(Point p, double radius, Visit visit) const;
    // The nearest alive node within `radius` other than `except`, or -1.
    int nearest(Point p, double radius, int except) const;
    // True when segment a-b crosses a link that shares no end with it.
    bool crosses(Point a, Point b, int end_a, int end_b) const;

    std::vector<Node>& nodes() { return nodes_; }
    const std::vector<Node>& nodes() const { return nodes_; }
    const Node& operator[](int id) const { return nodes_[static_cast<std::size_t>(id)]; }
    Node& operator[](int id) { return nodes_[static_cast<std::size_t>(id)]; }
    double longest_link() const { return longest_link_; }
    double largest_radius() const { return largest_radius_; }
    void note_radius(double r) { largest_radius_ = r > largest_radius_ ? r : largest_radius_; }

  private:
    std::int64_t key(Point p) const;
    std::int64_t key(std::int64_t i, std::int64_t j) const { return (i << 32) ^ (j & 0xffffffff); }

    double cell_;
    std::vector<Node> nodes_;
    std::unordered_map<std::int64_t, std::vector<int>> grid_;  // looked up only, never iterated
    double longest_link_ = 0;
    double largest_radius_ = 0;
};

template <class Visit>
bool Arrangement::any_near(Point p, double radius, Visit visit) const {
    // Fewer nodes than cells to look in: every node is looked at instead.
    const double span = 2 * radius / cell_ + 2;
    if (span * span > static_cast<double>(nodes_.size())) {
        for (int id = 0; id < static_cast<int>(nodes_.size()); ++id)
            if (nodes_[static_cast<std::size_t>(id)].alive &&
                distance(nodes_[static_cast<std::size_t>(id)].position, p) <= radius && visit(id))
                return true;
        return false;
    }
    const auto i0 = static_cast<std::int64_t>(std::floor((p.x - radius) / cell_));
    const auto i1 = static_cast<std::int64_t>(std::floor((p.x + radius) / cell_));
    const auto j0 = static_cast<std::int64_t>(std::floor((p.y - radius) / cell_));
    const auto j1 = static_cast<std::int64_t>(std::floor((p.y + radius) / cell_));
    for (auto i = i0; i <= i1; ++i)
        for (auto j = j0; j <= j1; ++j) {
            auto it = grid_.find(key(i, j));
            if (it == grid_.end()) continue;
            for (int id : it->second)
                if (distance(nodes_[static_cast<std::size_t>(id)].position, p) <= radius &&
                    visit(id))
                    return true;
        }
    return false;
}

}  // namespace acanthus::growth::detail
