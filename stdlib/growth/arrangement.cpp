#include "arrangement.hpp"

#include <algorithm>
#include <cmath>

namespace acanthus::growth::detail {

Arrangement::Arrangement(double cell) : cell_(cell) {}

std::int64_t Arrangement::key(Point p) const {
    return key(static_cast<std::int64_t>(std::floor(p.x / cell_)),
               static_cast<std::int64_t>(std::floor(p.y / cell_)));
}

int Arrangement::add(Node node) {
    int id = static_cast<int>(nodes_.size());
    grid_[key(node.position)].push_back(id);
    nodes_.push_back(std::move(node));
    return id;
}

void Arrangement::kill(int id) {
    Node& n = nodes_[static_cast<std::size_t>(id)];
    if (!n.alive) return;
    for (const Link& l : n.links) {
        auto& other = nodes_[static_cast<std::size_t>(l.node)].links;
        other.erase(
            std::remove_if(other.begin(), other.end(), [&](const Link& k) { return k.node == id; }),
            other.end());
    }
    n.links.clear();
    auto& cell = grid_[key(n.position)];
    cell.erase(std::remove(cell.begin(), cell.end(), id), cell.end());
    n.alive = false;
}

void Arrangement::move(int id, Point to) {
    Node& n = nodes_[static_cast<std::size_t>(id)];
    std::int64_t from_key = key(n.position), to_key = key(to);
    if (from_key != to_key) {
        auto& cell = grid_[from_key];
        cell.erase(std::remove(cell.begin(), cell.end(), id), cell.end());
        grid_[to_key].push_back(id);
    }
    n.position = to;
    for (const Link& l : n.links)
        longest_link_ = std::max(longest_link_, distance(to, nodes_[l.node].position));
}

void Arrangement::link(int a, int b, Vector desired) {
    nodes_[static_cast<std::size_t>(a)].links.push_back({b, desired});
    nodes_[static_cast<std::size_t>(b)].links.push_back({a, -desired});
    longest_link_ = std::max(longest_link_, distance(nodes_[a].position, nodes_[b].position));
}

bool Arrangement::linked(int a, int b) const {
    for (const Link& l : nodes_[static_cast<std::size_t>(a)].links)
        if (l.node == b) return true;
    return false;
}

void Arrangement::set_desired(int from, int to, Vector desired) {
    for (Link& l : nodes_[static_cast<std::size_t>(from)].links)
        if (l.node == to) l.desired = desired;
}

std::vector<int> Arrangement::near(Point p, double radius) const {
    std::vector<int> out;
    any_near(p, radius, [&](int id) {
        out.push_back(id);
        return false;
    });
    std::sort(out.begin(), out.end());
    return out;
}

int Arrangement::nearest(Point p, double radius, int except) const {
    int best = -1;
    double best_d = INFINITY;
    for (int id : near(p, radius)) {
        double d = distance(nodes_[id].position, p);
        if (id != except && d < best_d) {
            best = id;
            best_d = d;
        }
    }
    return best;
}

namespace {
bool segments_cross(Point a, Point b, Point c, Point d) {
    auto side = [](Point o, Point p, Point q) { return (p - o).cross(q - o); };
    double d1 = side(a, b, c), d2 = side(a, b, d), d3 = side(c, d, a), d4 = side(c, d, b);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}
}  // namespace

bool Arrangement::crosses(Point a, Point b, int end_a, int end_b) const {
    Point mid = midpoint(a, b);
    double reach = distance(a, b) / 2 + longest_link_;
    for (int u : near(mid, reach)) {
        if (u == end_a || u == end_b) continue;
        for (const Link& l : nodes_[static_cast<std::size_t>(u)].links) {
            if (l.node == end_a || l.node == end_b || l.node < u) continue;
            if (segments_cross(a, b, nodes_[u].position, nodes_[l.node].position)) return true;
        }
    }
    return false;
}

}  // namespace acanthus::growth::detail
