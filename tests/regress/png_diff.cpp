// Compares two PNG files pixel by pixel; writes a diff picture when they differ.
// Usage: png_diff EXPECTED.png ACTUAL.png DIFF.png [TOLERANCE [MAX_BAD_FRACTION]]
// Exit 0 when every channel differs by at most TOLERANCE (0-255) except for at most
// MAX_BAD_FRACTION of the pixels; 1 when they differ (DIFF.png written); 2 on bad input.
#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {
cairo_surface_t* load(const char* path) {
    cairo_surface_t* s = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        std::fprintf(stderr, "png_diff: cannot read %s: %s\n", path,
                     cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        return nullptr;
    }
    cairo_surface_flush(s);
    return s;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: png_diff EXPECTED.png ACTUAL.png DIFF.png [TOL [FRACTION]]\n");
        return 2;
    }
    const int tolerance = argc > 4 ? std::atoi(argv[4]) : 8;
    const double max_bad = argc > 5 ? std::atof(argv[5]) : 0.001;
    cairo_surface_t* a = load(argv[1]);
    cairo_surface_t* b = load(argv[2]);
    if (!a || !b) return 2;
    const int w = cairo_image_surface_get_width(a), h = cairo_image_surface_get_height(a);
    if (w != cairo_image_surface_get_width(b) || h != cairo_image_surface_get_height(b)) {
        std::fprintf(stderr, "png_diff: sizes differ: %dx%d vs %dx%d\n", w, h,
                     cairo_image_surface_get_width(b), cairo_image_surface_get_height(b));
        return 1;
    }
    cairo_surface_t* d = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    const int sa = cairo_image_surface_get_stride(a), sb = cairo_image_surface_get_stride(b),
              sd = cairo_image_surface_get_stride(d);
    const unsigned char* pa = cairo_image_surface_get_data(a);
    const unsigned char* pb = cairo_image_surface_get_data(b);
    unsigned char* pd = cairo_image_surface_get_data(d);
    long bad = 0;
    int worst = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Both surfaces share the same format as both come from PNG decoding.
            const auto* qa = reinterpret_cast<const std::uint32_t*>(pa + y * sa) + x;
            const auto* qb = reinterpret_cast<const std::uint32_t*>(pb + y * sb) + x;
            int diff = 0;
            for (int c = 0; c < 32; c += 8)
                diff = std::max(diff, std::abs(int((*qa >> c) & 255) - int((*qb >> c) & 255)));
            worst = std::max(worst, diff);
            auto* qd = reinterpret_cast<std::uint32_t*>(pd + y * sd) + x;
            if (diff > tolerance) {
                ++bad;
                *qd = 0xffff0000u;  // opaque red where they differ
            } else {
                // Faint grey copy of the expected picture for orientation.
                const int g = 255 - ((((*qa >> 8) & 255) + ((*qa >> 16) & 255)) / 2) / 4;
                *qd = 0xff000000u | (g << 16) | (g << 8) | g;
            }
        }
    }
    cairo_surface_mark_dirty(d);
    const double fraction = double(bad) / (double(w) * h);
    int rc = 0;
    if (fraction > max_bad) {
        cairo_surface_write_to_png(d, argv[3]);
        std::fprintf(stderr,
                     "png_diff: %ld pixels (%.4f%%) differ by more than %d (worst %d); diff: %s\n",
                     bad, fraction * 100, tolerance, worst, argv[3]);
        rc = 1;
    }
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
    cairo_surface_destroy(d);
    return rc;
}
