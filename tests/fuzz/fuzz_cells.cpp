// libFuzzer target for the cells library's facade reader: any input is either a facade, which
// is then textured by a small brick tree (about 20 bricks across, so each input stays quick),
// or an InputError.
#include <acanthus/error.hpp>
#include <acanthus/stdlib/cells.hpp>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace cells = acanthus::cells;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        cells::Facade facade = cells::Facade::from_svg_string(text, "fuzz.svg");
        acanthus::Rect b = facade.bounds();
        cells::Options o;
        o.brick_length = std::max(b.width(), b.height()) / 20;
        o.brick_height = o.brick_length / 3;
        o.mortar = o.brick_length / 20;
        cells::check(o, "fuzz.svg");
        (void)cells::texture(facade, cells::brick_tree(), o, 1);
    } catch (const acanthus::InputError&) {
    }
    return 0;
}
