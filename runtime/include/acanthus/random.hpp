// Seeded random numbers that give the same sequence on every platform (no std distributions).
#pragma once

#include <cstdint>

namespace acanthus {

class Random {
  public:
    explicit Random(std::uint64_t seed = 1) { reseed(seed); }
    void reseed(std::uint64_t seed);
    std::uint64_t next_u64();
    // Uniform in [0, 1).
    double uniform();
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [lo, hi].
    long long uniform_int(long long lo, long long hi);
    double normal(double mean = 0.0, double stddev = 1.0);
    bool chance(double probability) { return uniform() < probability; }

  private:
    std::uint64_t s_[4]{};
    bool has_spare_ = false;
    double spare_ = 0.0;
};

}  // namespace acanthus
