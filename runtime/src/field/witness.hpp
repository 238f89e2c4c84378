// The lazy field's witness test: a site already deferred to a block outranks new sites there
// when every pixel of the block is at least as near to it as to any point of the new sites'
// bounding box. Then the new sites lower nothing in the block, now or after it is measured.
#pragma once

#include <acanthus/distance_metric.hpp>

namespace acanthus::detail {

struct PixelBox {
    int x0, y0, x1, y1;  // inclusive
};

// Whether every pixel of `pixels` is at least as near to site (si, sj) as to every point of
// `sites`, in `metric`. False when it cannot tell (the test is conservative).
bool outranks(int si, int sj, const PixelBox& sites, const PixelBox& pixels, DistanceMetric metric);

}  // namespace acanthus::detail
