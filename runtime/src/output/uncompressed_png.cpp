#include "output/uncompressed_png.hpp"

#include <png.h>

#include <acanthus/error.hpp>
#include <csetjmp>
#include <cstdint>
#include <vector>

namespace acanthus::detail {

namespace {

void append(png_structp png, png_bytep data, png_size_t size) {
    static_cast<std::string*>(png_get_io_ptr(png))
        ->append(reinterpret_cast<const char*>(data), size);
}

void no_flush(png_structp) {}

// Cairo stores premultiplied native-endian ARGB; PNG wants straight RGBA.
void unpremultiply_row(const std::uint32_t* in, int width, png_bytep out) {
    for (int x = 0; x < width; ++x, out += 4) {
        const std::uint32_t p = in[x];
        const unsigned a = p >> 24;
        unsigned r = (p >> 16) & 0xff, g = (p >> 8) & 0xff, b = p & 0xff;
        if (a != 0 && a != 255) {
            r = (r * 255 + a / 2) / a;
            g = (g * 255 + a / 2) / a;
            b = (b * 255 + a / 2) / a;
        }
        out[0] = static_cast<png_byte>(r);
        out[1] = static_cast<png_byte>(g);
        out[2] = static_cast<png_byte>(b);
        out[3] = static_cast<png_byte>(a);
    }
}

}  // namespace

std::string uncompressed_png(cairo_surface_t* image) {
    const int width = cairo_image_surface_get_width(image);
    const int height = cairo_image_surface_get_height(image);
    const int stride = cairo_image_surface_get_stride(image);
    const unsigned char* pixels = cairo_image_surface_get_data(image);
    std::string out;
    // Stored pixels: the file is their size and a little (a filter byte a row, the stored
    // blocks' and the chunks' headers): grown piece by piece, it was copied again and again.
    const std::size_t raw =
        static_cast<std::size_t>(height) * (1 + 4 * static_cast<std::size_t>(width));
    out.reserve(raw + raw / 64 + 4096);
    std::vector<png_byte> row(static_cast<std::size_t>(width) * 4);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw InputError("writing the PNG failed: out of memory");
    }
    // libpng reports errors by longjmp: nothing with a destructor is made past this point.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw InputError("writing the PNG failed");
    }
    png_set_write_fn(png, &out, append, no_flush);
    png_set_compression_level(png, 0);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) {
        unpremultiply_row(reinterpret_cast<const std::uint32_t*>(pixels + y * stride), width,
                          row.data());
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

}  // namespace acanthus::detail
