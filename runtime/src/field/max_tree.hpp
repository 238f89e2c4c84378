// A fixed number of slots holding unsigned keys, with the maximum over all of them kept in a
// complete binary tree: set() is O(log n), max() and argmax() are O(1) / O(log n).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace acanthus::detail {

class MaxTree {
  public:
    explicit MaxTree(std::size_t slots = 0) { reset(slots); }

    void reset(std::size_t slots) {
        leaves_ = 1;
        while (leaves_ < slots) leaves_ *= 2;
        node_.assign(2 * leaves_, 0);
    }
    std::uint64_t get(std::size_t slot) const { return node_[leaves_ + slot]; }
    void set(std::size_t slot, std::uint64_t key) {
        std::size_t n = leaves_ + slot;
        if (node_[n] == key) return;
        node_[n] = key;
        for (n /= 2; n >= 1; n /= 2) {
            const std::uint64_t m =
                node_[2 * n] > node_[2 * n + 1] ? node_[2 * n] : node_[2 * n + 1];
            if (node_[n] == m) break;
            node_[n] = m;
        }
    }
    std::uint64_t max() const { return node_[1]; }

  private:
    std::size_t leaves_ = 1;
    std::vector<std::uint64_t> node_;
};

}  // namespace acanthus::detail
