// The candidate points of Sakurai & Miyata section 4.3, drawn from a GapField without a pass over
// the whole field: free pixels are filed in groups of nearly equal distance, kept up to date from
// the pixels each placement changes, so a round costs O(groups + |Q|) instead of O(pixels).
#pragma once

#include <acanthus/random.hpp>
#include <cstdint>
#include <vector>

#include "gap_field.hpp"

namespace acanthus::dartfill {

// d^n from q = d^2 (q in [0, 1]): q^(n/2), by squaring when n/2 is a small integer.
double power_of_distance(double q, double exponent);

class CandidateSampler {
  public:
    // Files every free pixel of `gaps`; the sampler reads distances from it afterwards.
    explicit CandidateSampler(const GapField& gaps);

    // Re-files pixels whose distance or occupancy changed (GapField::add reports them).
    void update(const std::vector<int>& pixels);
    // Largest squared distance over the free pixels (0 when none is free).
    std::int64_t max_squared_distance() const;
    long free_pixels() const { return filed_; }
    // The group a pixel is filed in, or -1 (a site, or outside the space).
    int filed_group(int pixel) const { return group_[pixel]; }

    // Q: every free pixel joins independently with probability alpha = d^n, d its distance over
    // the largest distance. Exact: a group is thinned from the bound of its alpha, each proposal
    // kept with alpha / bound (geometric skips between proposals). Appends to `q`.
    void draw_q(double exponent, Random& random, std::vector<int>& q) const;
    // P: `count` members of a fresh Q chosen uniformly without replacement (all of Q when it is
    // smaller). Empty only when no pixel is free.
    std::vector<int> draw(double exponent, int count, Random& random) const;

    // Group of a squared distance >= 1: exact below 16, else the leading four bits (so the
    // squared distances of one group differ by less than a factor 9/8).
    static int group_of(std::int64_t d2);
    // One past the largest squared distance of group `g`.
    static std::int64_t group_end(int g);

  private:
    void file(int pixel);
    void unfile(int pixel);

    const GapField& gaps_;
    std::vector<std::vector<int>> groups_;
    std::vector<int> group_;  // per pixel: its group, or -1 when not filed
    std::vector<int> slot_;   // per pixel: its place in the group
    long filed_ = 0;
};

}  // namespace acanthus::dartfill
