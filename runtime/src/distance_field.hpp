// Exact Euclidean distance field over the render buffer, with the nearest obstacle site and
// its kind for every pixel. Full computation is Meijster's separable EDT with a feature
// transform; add_sites() updates incrementally by propagating from the new sites only to the
// pixels whose nearest site changes.
#pragma once

#include <cstdint>
#include <vector>

namespace acanthus {

enum class ObstacleKind : std::uint8_t { none = 0, boundary = 1, element = 2 };

class DistanceField {
public:
    DistanceField(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Full recomputation from an occupancy grid (width*height, values of ObstacleKind).
    void compute(const std::vector<std::uint8_t>& occupancy);
    // Marks free pixels (indices j*width+i) as sites of `kind` and updates the field.
    // Pixels whose distance changed are appended to `changed` when it is not null.
    void add_sites(const std::vector<int>& pixels, ObstacleKind kind, std::vector<int>* changed);

    // Squared distance in pixels from pixel index to its nearest site (0 on a site).
    std::int64_t squared_distance(int index) const { return dist2_[index]; }
    double distance(int i, int j) const;
    // Index of the nearest site, or -1 when there is no site at all.
    int nearest_site(int index) const { return site_[index]; }
    ObstacleKind nearest_kind(int index) const;
    ObstacleKind occupancy(int index) const { return static_cast<ObstacleKind>(occ_[index]); }
    const std::vector<std::uint8_t>& occupancy() const { return occ_; }

private:
    int width_;
    int height_;
    std::vector<std::uint8_t> occ_;
    std::vector<std::int64_t> dist2_;
    std::vector<int> site_;
};

}  // namespace acanthus
