// Where the region's bounds land on the output page: size, margin, scale and line width.
#pragma once

#include <acanthus/point.hpp>

typedef struct _cairo cairo_t;

namespace acanthus::detail {

struct PageLayout {
    int width = 0, height = 0;          // page size: pixels (PNG) or points (vector formats)
    double scale = 1;                   // page units per user unit
    double offset_x = 0, offset_y = 0;  // page position of user (0, 0)
    // Outline width in user units: one page unit per 800 of page width, at least one.
    double line_width = 1;

    // Maps user units to the page on `cr`.
    void apply(cairo_t* cr) const;
};

// The page `width` units wide whose height follows the bounds' aspect ratio, with a margin of
// 2% of the larger side all round. Throws UsageError on a width outside 1..32767.
PageLayout page_layout(const Rect& bounds, double width);

}  // namespace acanthus::detail
