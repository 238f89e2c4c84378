// Where a library keeps the maker of elements its rule file registers for partial pictures
// (report_partial, <acanthus/partial_picture.hpp>): dartfill's, growth's and cells' alike.
#pragma once

#include <atomic>

namespace acanthus {

class Element;

template <class Placed>
class PartialMakerSlot {
  public:
    using Make = const Element* (*)(const Placed&);
    // Returns true, for a `static const bool` in the rule file that sets it.
    bool set(Make make) noexcept {
        make_.store(make, std::memory_order_relaxed);
        return true;
    }
    Make get() const noexcept { return make_.load(std::memory_order_relaxed); }

  private:
    std::atomic<Make> make_{nullptr};
};

}  // namespace acanthus
