// Helper of the region area oracle (region_oracle.py, label `regions`):
//   region_oracle region FILE.svg   prints the region's area and bounds as Acanthus reads them
//   region_oracle coverage FILE.png prints the summed alpha coverage of a raster (anti-aliased
//                                   edge pixels count fractionally) and the pixel box of
//                                   every pixel with any coverage
// Output is "key value..." lines; an InputError is printed and exits 1, anything else 2.
#include <cairo.h>

#include <acanthus/error.hpp>
#include <acanthus/region.hpp>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

namespace {

int region(const char* file) {
    acanthus::Region r = acanthus::Region::from_svg_file(file);
    acanthus::Rect b = r.bounds();
    std::printf("area %.17g\nbounds %.17g %.17g %.17g %.17g\nparts %zu\n", r.area(), b.x0, b.y0,
                b.x1, b.y1, r.parts().size());
    return 0;
}

int coverage(const char* file) {
    cairo_surface_t* s = cairo_image_surface_create_from_png(file);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        std::fprintf(stderr, "%s: cannot read PNG: %s\n", file,
                     cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        return 2;
    }
    cairo_surface_flush(s);
    const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const cairo_format_t format = cairo_image_surface_get_format(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    std::uint64_t sum = 0;  // in 1/255 of a pixel
    int x0 = w, y0 = h, x1 = -1, y1 = -1;
    for (int y = 0; y < h; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + std::ptrdiff_t(y) * stride);
        for (int x = 0; x < w; ++x) {
            // ARGB32 keeps alpha in the top byte; an opaque RGB24 PNG covers every pixel.
            unsigned a = format == CAIRO_FORMAT_ARGB32 ? row[x] >> 24 : 255;
            if (a == 0) continue;
            sum += a;
            if (x < x0) x0 = x;
            if (x > x1) x1 = x;
            if (y < y0) y0 = y;
            if (y > y1) y1 = y;
        }
    }
    cairo_surface_destroy(s);
    std::printf("size %d %d\ncoverage %.17g\n", w, h, double(sum) / 255.0);
    if (x1 >= 0) std::printf("pixels %d %d %d %d\n", x0, y0, x1 + 1, y1 + 1);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: region_oracle region FILE.svg | coverage FILE.png\n");
        return 2;
    }
    const std::string mode = argv[1];
    try {
        if (mode == "region") return region(argv[2]);
        if (mode == "coverage") return coverage(argv[2]);
        std::fprintf(stderr, "region_oracle: unknown mode '%s'\n", argv[1]);
        return 2;
    } catch (const acanthus::InputError& e) {
        std::printf("refused %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::printf("exception %s\n", e.what());
        return 2;
    }
}
