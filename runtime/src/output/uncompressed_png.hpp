// A PNG of a Cairo image whose pixels are stored, not deflated: for a picture read at once over
// loopback (the preview's), where Cairo's compression costs more than the bytes it saves.
#pragma once

#include <cairo.h>

#include <string>

namespace acanthus::detail {

// The image (Cairo's ARGB32, premultiplied) as an RGBA PNG, written by libpng at compression
// level 0 with no row filter. Throws InputError if libpng fails.
std::string uncompressed_png(cairo_surface_t* image);

}  // namespace acanthus::detail
